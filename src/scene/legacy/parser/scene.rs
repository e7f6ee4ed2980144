//! The Scene block: image size, background, the older files' ambient light, ray depth and
//! the (unused) output file name; the students' `Supersampling`, `FSAA N` (samples per
//! pixel) and `scaleResolution s`, and the debug `renderNormals` (ignored).

use super::super::error::Diagnostics;
use super::super::syntax::SceneSetting;
use super::at_token::error;
use super::entries::{Entry, Word};
use super::values::{capped_count, colour, name, numbers, whole};
use crate::scene::{MAX_IMAGE_SIDE, MAX_SAMPLES_PER_PIXEL};

/// The keywords of a Scene block.
pub(super) const SCENE_WORDS: &[Word] = &[
    Word::RenderSize,
    Word::BackgroundColour,
    Word::AmbientLight,
    Word::RayDepth,
    Word::Filename,
    Word::Supersampling,
    Word::Fsaa,
    Word::ScaleResolution,
    Word::RenderNormals,
];

/// The most samples per axis `FSAA N` may ask for: N * N is at most
/// [`MAX_SAMPLES_PER_PIXEL`].
pub const MAX_FSAA: u32 = 256;

/// `Supersampling`: a 2 x 2 grid.
pub const SUPERSAMPLING_SAMPLES: u32 = 4;

/// One entry of a Scene block.
pub(super) fn setting(
    entry: &Entry<'_, '_>,
    errors: &mut Diagnostics,
) -> Option<Option<SceneSetting>> {
    match entry.word {
        Word::Supersampling => {
            if let Some(number) = entry.args.first() {
                errors.warn(
                    number.line,
                    format!(
                        "`{}` after `Supersampling` is skipped, as the legacy reader does: \
                         it always takes {SUPERSAMPLING_SAMPLES} samples (a 2 x 2 grid)",
                        number.text
                    ),
                );
            }
            Some(Some(SceneSetting::SamplesPerPixel(SUPERSAMPLING_SAMPLES)))
        }
        Word::Fsaa => {
            let v = numbers(entry, errors)?;
            let per_axis =
                capped_count(&entry.args[0], v[0], MAX_FSAA, &samples_per_axis(), errors)?;
            Some(Some(SceneSetting::SamplesPerPixel(per_axis * per_axis)))
        }
        Word::ScaleResolution => {
            let v = numbers(entry, errors)?;
            if v[0] <= 0.0 {
                errors.push(error(
                    &entry.args[0],
                    "a resolution scale must be more than 0",
                ));
                return None;
            }
            Some(Some(SceneSetting::ScaleResolution(v[0])))
        }
        Word::RenderNormals => {
            errors.warn(
                entry.keyword.line,
                "`renderNormals` is a debug view of one reader: ignored (raylab shades the scene)",
            );
            Some(None)
        }
        _ => plain_setting(entry, errors).map(Some),
    }
}

/// The base format's Scene keywords.
fn plain_setting(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<SceneSetting> {
    match entry.word {
        Word::RenderSize => {
            let v = numbers(entry, errors)?;
            let side = |i: usize, errors: &mut Diagnostics| {
                whole(
                    &entry.args[i],
                    v[i],
                    1..=MAX_IMAGE_SIDE,
                    "an image side",
                    errors,
                )
            };
            let width = side(0, errors);
            let height = side(1, errors);
            Some(SceneSetting::RenderSize {
                width: width?,
                height: height?,
            })
        }
        Word::BackgroundColour => colour(entry, errors).map(SceneSetting::Background),
        Word::AmbientLight => colour(entry, errors).map(SceneSetting::AmbientLight),
        Word::RayDepth => {
            let v = numbers(entry, errors)?;
            // Any whole number the format allows; the converter caps what raylab renders.
            if !(v[0].fract() == 0.0 && v[0] >= 0.0) {
                errors.push(error(
                    &entry.args[0],
                    "the ray depth must be a whole number, 0 or more",
                ));
                return None;
            }
            Some(SceneSetting::RayDepth(v[0]))
        }
        _ => name(entry, errors).map(SceneSetting::Filename),
    }
}

/// What `FSAA N` counts, for the capping warning.
fn samples_per_axis() -> String {
    format!("samples per axis (N * N at most {MAX_SAMPLES_PER_PIXEL} per pixel)")
}
