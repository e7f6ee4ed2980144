//! The Light block: `Light AmbientLight | PointLight | DirectionalLight | SpotLight` and
//! its colour, location, direction and angle, and a sphere light's `Radius` and
//! `Samples`.

use super::super::error::Diagnostics;
use super::super::lexer::Token;
use super::super::syntax::{Block, LightSetting, ParsedBlock};
use super::at_token::{at, error};
use super::entries::{Entry, Word, decode};
use super::header::{header, no_numbers};
use super::values::{capped_count, colour, numbers, vector};
use crate::scene::{LightKind, MAX_LIGHT_SAMPLES, MAX_SPOT_ANGLE_DEG};

/// The keywords of a Light block.
const LIGHT_WORDS: &[Word] = &[
    Word::Colour,
    Word::Location,
    Word::Direction,
    Word::Angle,
    Word::Radius,
    Word::Samples,
];

/// The type word of a light kind in legacy files: `PointLight` for `Point`.
fn type_word(kind: LightKind) -> String {
    format!("{}Light", kind.name())
}

/// A Light block: the word `Light` and the tokens after it.
pub(super) fn parse_light(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Diagnostics,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a light type, such as `PointLight`", errors)?;
    let kind = LightKind::ALL
        .into_iter()
        .find(|&kind| header.kind.is(&type_word(kind)));
    if kind.is_none() {
        errors.push(error(
            &header.kind,
            "unknown light type (expected AmbientLight, PointLight, DirectionalLight or SpotLight)",
        ));
    }
    let numbers_ok = no_numbers(&header, errors);
    let (settings, broken) = decode(header.body, &[LIGHT_WORDS], word, errors, light_setting);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Light {
            kind: kind?,
            settings,
            broken,
        },
        at: at(&header.kind),
    })
}

fn light_setting(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<LightSetting> {
    match entry.word {
        Word::Colour => colour(entry, errors).map(LightSetting::Colour),
        Word::Location => vector(entry, errors).map(LightSetting::Location),
        Word::Direction => {
            let direction = vector(entry, errors)?;
            if !direction.length_squared().is_normal() {
                errors.push(error(
                    &entry.keyword,
                    "the direction is zero (or too short to give a direction)",
                ));
                return None;
            }
            Some(LightSetting::Direction(direction))
        }
        Word::Radius => {
            let v = numbers(entry, errors)?;
            if v[0] < 0.0 {
                errors.push(error(&entry.args[0], "a light's radius cannot be negative"));
                return None;
            }
            Some(LightSetting::Radius(v[0]))
        }
        Word::Samples => {
            let v = numbers(entry, errors)?;
            capped_count(
                &entry.args[0],
                v[0],
                MAX_LIGHT_SAMPLES,
                "shadow rays",
                errors,
            )
            .map(LightSetting::Samples)
        }
        _ => {
            let v = numbers(entry, errors)?;
            if !(v[0] > 0.0 && v[0] <= MAX_SPOT_ANGLE_DEG) {
                errors.push(error(
                    &entry.args[0],
                    format!(
                        "a spot light's half-angle must be more than 0 and at most \
                         {MAX_SPOT_ANGLE_DEG} degrees"
                    ),
                ));
                return None;
            }
            Some(LightSetting::Angle(v[0]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::parse_text;
    use super::*;

    #[test]
    fn light_types_are_the_kind_names_with_light_appended() {
        for kind in LightKind::ALL {
            let (blocks, errors) =
                parse_text(&format!("Light {} Colour 1 1 1 End", type_word(kind)));
            assert!(errors.is_empty(), "{errors:?}");
            assert!(
                matches!(blocks[0].block, Block::Light { kind: k, .. } if k == kind),
                "{blocks:?}"
            );
        }
    }
}
