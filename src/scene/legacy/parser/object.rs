//! The Object block: `Object SHAPE` (one of the shapes raylab draws, the octahedron too), its
//! material, material overrides and transforms.

use super::super::error::LegacyError;
use super::super::lexer::Token;
use super::super::syntax::{Block, ObjectKind, ObjectSetting, ParsedBlock};
use super::entries::{Entry, Word, decode};
use super::material::surface_edit;
use super::transform::transform_step;
use super::values::name;
use super::{at, error, header, no_numbers};
use crate::scene::Shape;

/// The keywords of an Object block.
const OBJECT_WORDS: &[Word] = &[
    Word::Material,
    Word::Colour,
    Word::Ambient,
    Word::Diffuse,
    Word::Specular,
    Word::Mirror,
    Word::Translate,
    Word::Rotate,
    Word::Scale,
    Word::Scale3,
];

/// An Object block: the word `Object` and the tokens after it.
pub(super) fn parse_object(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Vec<LegacyError>,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a shape, such as `Sphere`", errors)?;
    // The torus and the tube take their radius on the header line (`Torus 0.3`), which
    // this reader does not parse yet.
    let kind = Shape::ALL
        .into_iter()
        .filter(|shape| !matches!(shape, Shape::Torus { .. } | Shape::Tube { .. }))
        .find(|shape| header.kind.is(shape.name()))
        .map(ObjectKind::Shape);
    if kind.is_none() {
        errors.push(error(
            &header.kind,
            "unknown object type (expected Sphere, Plane, Cube, Cylinder, Cone or Octahedron)",
        ));
    }
    let numbers_ok = no_numbers(&header, errors);
    let (settings, _) = decode(header.body, OBJECT_WORDS, word, errors, object_setting);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Object {
            kind: kind?,
            settings,
        },
        at: at(&header.kind),
    })
}

fn object_setting(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<ObjectSetting> {
    match entry.word {
        Word::Material => name(entry, errors).map(ObjectSetting::Material),
        Word::Translate | Word::Rotate | Word::Scale | Word::Scale3 => {
            transform_step(entry, errors).map(ObjectSetting::Transform)
        }
        _ => surface_edit(entry, errors).map(ObjectSetting::Surface),
    }
}
