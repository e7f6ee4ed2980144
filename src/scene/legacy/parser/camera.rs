//! The Camera block: `Camera PinholeCamera F` and the camera's transforms.

use super::super::error::Diagnostics;
use super::super::lexer::Token;
use super::super::syntax::{Block, ParsedBlock};
use super::at_token::{at, error};
use super::entries::decode;
use super::header::{Header, header};
use super::transform::{TRANSFORM_WORDS, transform_step};
use super::values::number;

/// A Camera block: the word `Camera` and the tokens after it.
pub(super) fn parse_camera(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Diagnostics,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a camera type: `PinholeCamera F`", errors)?;
    let known = header.kind.is("PinholeCamera");
    if !known {
        errors.push(error(
            &header.kind,
            "unknown camera type (expected PinholeCamera F)",
        ));
    }
    let focal_length = if known {
        focal_length(&header, errors)
    } else {
        None
    };
    let (transforms, _) = decode(
        header.body,
        &[TRANSFORM_WORDS],
        word,
        errors,
        transform_step,
    );
    Some(ParsedBlock {
        block: Block::Camera {
            focal_length: focal_length?,
            transforms,
        },
        at: at(&header.kind),
    })
}

fn focal_length(header: &Header<'_, '_>, errors: &mut Diagnostics) -> Option<f64> {
    let [token] = header.numbers else {
        errors.push(error(
            &header.kind,
            format!(
                "`PinholeCamera` takes F, the focal length (1 number), found {}",
                header.numbers.len()
            ),
        ));
        return None;
    };
    let value = number(token, errors)?;
    if value <= 0.0 {
        errors.push(error(token, "the focal length must be positive"));
        return None;
    }
    Some(value)
}
