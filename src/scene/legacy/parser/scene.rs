//! The Scene block: image size, background, the older files' ambient light, ray depth and
//! the (unused) output file name.

use super::super::error::LegacyError;
use super::super::syntax::SceneSetting;
use super::entries::{Entry, Word};
use super::values::{colour, name, numbers, whole};
use crate::scene::validate::{MAX_DEPTH, MAX_IMAGE_SIDE};

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
            whole(&entry.args[0], v[0], 0..=MAX_DEPTH, "the ray depth", errors)
                .map(SceneSetting::RayDepth)
        }
        _ => name(entry, errors).map(SceneSetting::Filename),
    }
}
