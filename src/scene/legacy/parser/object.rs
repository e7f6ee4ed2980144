//! The Object block: `Object KIND` (a unit shape, `Torus R`, `Tube R`, `Mesh PATH`), its
//! material, material overrides and transforms. An unknown kind, or `Parabaloid` (a stub
//! that draws nothing in the one reader that has it), is skipped with a warning.

use super::super::error::Diagnostics;
use super::super::lexer::Token;
use super::super::syntax::{ObjectKind, ObjectNode, ObjectSetting};
use super::at_token::{at, error};
use super::entries::{Entry, Word, decode, present};
use super::header::{header, no_numbers};
use super::material::{MATERIAL_WORDS, surface_edit};
use super::transform::{TRANSFORM_WORDS, transform_step};
use super::values::{name, number};
use crate::scene::Shape;

/// The keywords of an Object block (and of a tree node's own keywords): its material,
/// the Material block's keywords (overrides), the transforms, and its own flag.
pub(super) const OBJECT_WORDS: &[&[Word]] = &[
    &[Word::Material],
    MATERIAL_WORDS,
    TRANSFORM_WORDS,
    &[Word::DisableBoundingBox],
];

/// The largest `Tube R`: the hole's radius sqrt(R / 2) must stay below 1.
const MAX_TUBE_R: f64 = 2.0;

/// An Object block: the word `Object` and the tokens after it (without its `End`).
pub(super) fn parse_object(
    word: &Token<'_>,
    rest: &[Token<'_>],
    name: Option<String>,
    errors: &mut Diagnostics,
) -> Option<ObjectNode> {
    let header = header(word, rest, "a shape, such as `Sphere`", errors)?;
    let kind_token = header.kind;
    let mut body = header.body;
    let mut numbers_ok = true;
    // The torus and the tube take R on the header line, read below.
    let plain_shape = Shape::ALL
        .into_iter()
        .filter(|shape| !matches!(shape, Shape::Torus { .. } | Shape::Tube { .. }))
        .find(|shape| kind_token.is(shape.name()));
    let kind = if let Some(shape) = plain_shape {
        numbers_ok = no_numbers(&header, errors);
        Some(ObjectKind::Shape(shape))
    } else if kind_token.is("Torus") || kind_token.is("Tube") {
        size_parameter(&kind_token, header.numbers, errors)
    } else if kind_token.is("Mesh") {
        // The path is the next token whatever it looks like (`../scenes/x.obj` starts
        // like a number).
        match rest[1..].split_first() {
            Some((path, after)) => {
                body = after;
                Some(ObjectKind::Mesh(path.text.to_owned()))
            }
            None => {
                errors.push(error(&kind_token, "`Mesh` takes PATH, an OBJ file"));
                None
            }
        }
    } else if kind_token.is("Parabaloid") || kind_token.is("Paraboloid") {
        errors.warn(
            kind_token.line,
            format!(
                "`Object {}` is a stub that draws nothing in the one reader that has it: \
                 nothing imported",
                kind_token.text
            ),
        );
        Some(ObjectKind::Skipped)
    } else {
        errors.warn(
            kind_token.line,
            format!(
                "unknown object type `{}` (raylab reads Sphere, Plane, Cube, Cylinder, Cone, \
                 Octahedron, Torus R, Tube R, Mesh PATH, CSG and ObjectGroup): skipped",
                kind_token.text
            ),
        );
        Some(ObjectKind::Skipped)
    };
    let (settings, _) = decode(body, OBJECT_WORDS, word, errors, object_setting);
    numbers_ok.then_some(())?;
    Some(ObjectNode {
        kind: kind?,
        settings: present(settings),
        name,
        at: at(&kind_token),
    })
}

/// `Torus R` (R > 0) or `Tube R` (0 < R < 2).
fn size_parameter(
    kind: &Token<'_>,
    numbers: &[Token<'_>],
    errors: &mut Diagnostics,
) -> Option<ObjectKind> {
    let is_torus = kind.is("Torus");
    let [token] = numbers else {
        errors.push(error(
            kind,
            format!(
                "`{}` takes R ({}), found {} numbers",
                kind.text,
                if is_torus {
                    "the size: centre circle R, tube radius R/2"
                } else {
                    "the hole: radius sqrt(R/2)"
                },
                numbers.len()
            ),
        ));
        return None;
    };
    let r = number(token, errors)?;
    if is_torus {
        if r <= 0.0 {
            errors.push(error(token, "a torus's R must be more than 0"));
            return None;
        }
        return Some(ObjectKind::Torus(r));
    }
    if !(r > 0.0 && r < MAX_TUBE_R) {
        errors.push(error(
            token,
            "a tube's R must be between 0 and 2 (the hole's radius sqrt(R/2) is below 1)",
        ));
        return None;
    }
    Some(ObjectKind::Tube(r))
}

/// One object keyword; `DisableBoundingBox` (a debug switch) is dropped with a warning.
pub(super) fn object_setting(
    entry: &Entry<'_, '_>,
    errors: &mut Diagnostics,
) -> Option<Option<ObjectSetting>> {
    match entry.word {
        Word::Material => name(entry, errors).map(|n| Some(ObjectSetting::Material(n))),
        Word::Translate | Word::Rotate | Word::Scale | Word::Scale3 => {
            transform_step(entry, errors).map(|t| Some(ObjectSetting::Transform(t)))
        }
        Word::DisableBoundingBox => {
            errors.warn(
                entry.keyword.line,
                "`DisableBoundingBox` is a debug switch of one reader: ignored",
            );
            Some(None)
        }
        _ => surface_edit(entry, errors).map(|e| Some(ObjectSetting::Surface(e))),
    }
}
