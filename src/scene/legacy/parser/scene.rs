//! The Scene block: image size, background, the older files' ambient light, ray depth and
//! the (unused) output file name.

use super::super::error::LegacyError;
use super::super::syntax::SceneSetting;
use super::entries::{Entry, Word};
use super::error;
use super::values::{colour, name, numbers, whole};
use crate::scene::MAX_IMAGE_SIDE;

/// The keywords of a Scene block.
pub(super) const SCENE_WORDS: &[Word] = &[
    Word::RenderSize,
    Word::BackgroundColour,
    Word::AmbientLight,
    Word::RayDepth,
    Word::Filename,
];

/// One entry of a Scene block.
pub(super) fn setting(
    entry: &Entry<'_, '_>,
    errors: &mut Vec<LegacyError>,
) -> Option<SceneSetting> {
    match entry.word {
        Word::RenderSize => {
            let v = numbers(entry, errors)?;
            let side = |i: usize, errors: &mut Vec<LegacyError>| {
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
