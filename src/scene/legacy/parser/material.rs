//! The Material block, `Material NAME`, and the material keywords it shares with objects
//! (`Colour`, `Ambient`, `Diffuse`, `Specular`, `Mirror`, `Opacity`, `RefractiveIndex`).

use glam::DVec3;

use super::super::error::Diagnostics;
use super::super::lexer::Token;
use super::super::syntax::{Block, ParsedBlock, SurfaceEdit};
use super::at_token::{at, error};
use super::entries::{Entry, Word, decode};
use super::header::{header, no_numbers};
use super::values::{colour, non_negative, numbers};
use crate::scene::MAX_IOR;

/// The keywords of a Material block, which an Object block takes too.
pub(super) const MATERIAL_WORDS: &[Word] = &[
    Word::Colour,
    Word::Ambient,
    Word::Diffuse,
    Word::Specular,
    Word::Mirror,
    Word::Opacity,
    Word::RefractiveIndex,
];

/// A Material block: the word `Material` and the tokens after it.
pub(super) fn parse_material(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Diagnostics,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a name: `Material NAME`", errors)?;
    let numbers_ok = no_numbers(&header, errors);
    let (edits, _) = decode(header.body, &[MATERIAL_WORDS], word, errors, surface_edit);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Material {
            name: header.kind.text.to_owned(),
            edits,
        },
        at: at(&header.kind),
    })
}

/// One material keyword, in a Material block or overriding an object's copy.
pub(super) fn surface_edit(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<SurfaceEdit> {
    match entry.word {
        Word::Colour => colour(entry, errors).map(SurfaceEdit::Colour),
        Word::Ambient => colour(entry, errors).map(SurfaceEdit::Ambient),
        Word::Diffuse => colour(entry, errors).map(SurfaceEdit::Diffuse),
        Word::Mirror => colour(entry, errors).map(SurfaceEdit::Mirror),
        Word::Opacity => {
            let v = numbers(entry, errors)?;
            if !(0.0..=1.0).contains(&v[0]) {
                errors.push(error(
                    &entry.args[0],
                    "an opacity must be from 0 (clear) to 1 (opaque)",
                ));
                return None;
            }
            Some(SurfaceEdit::Opacity(v[0]))
        }
        Word::RefractiveIndex => {
            let v = numbers(entry, errors)?;
            if !(v[0] > 0.0 && v[0] <= MAX_IOR) {
                errors.push(error(
                    &entry.args[0],
                    format!("a refractive index must be more than 0 and at most {MAX_IOR}"),
                ));
                return None;
            }
            Some(SurfaceEdit::RefractiveIndex(v[0]))
        }
        _ => {
            let v = numbers(entry, errors)?;
            let mut ok = non_negative(entry, &v[..3], errors);
            // 0 is allowed: the lobe is then 1 wherever r.v > 0.
            if v[3] < 0.0 {
                errors.push(error(
                    &entry.args[3],
                    "the Phong exponent cannot be negative",
                ));
                ok = false;
            }
            ok.then_some(SurfaceEdit::Specular {
                colour: DVec3::new(v[0], v[1], v[2]),
                exponent: v[3],
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::parse_text;
    use super::*;

    #[test]
    fn keywords_are_case_insensitive_and_names_are_not() {
        let (blocks, errors) = parse_text("mATERIAL Red cOLOUR 1 0 0 eND");
        assert!(errors.is_empty(), "{errors:?}");
        let Block::Material { name, edits } = &blocks[0].block else {
            panic!("{blocks:?}");
        };
        assert_eq!(name, "Red");
        assert_eq!(edits[0].value, SurfaceEdit::Colour(DVec3::X));
    }
}
