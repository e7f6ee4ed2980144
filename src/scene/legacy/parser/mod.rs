//! Tokens to typed blocks, collecting every error on the way.
//!
//! A block is the tokens up to the next `End`. Inside a block, a keyword starts an entry
//! and takes the tokens after it that look like numbers (they start with a digit, a sign
//! or a point); keywords that take a name (`Material`, `filename`, and the axis of
//! `Rotate`) take the next token whatever it is. Anything else where a keyword should be
//! is an unknown keyword, skipped with a warning together with the numbers after it (an
//! unknown block type or object kind is skipped whole, with a warning). A block word where
//! a keyword should be is an error: a missing `End`. Numbers are whole tokens: `1,0` is a
//! bad number, not `1`.
//!
//! Object trees (`Object CSG`, `CSG`, `ObjectGroup`) nest: there each `End` closes the
//! innermost open object (see `tree`).
//!
//! Values the scene format cannot hold (negative colours, zero scales, a spot angle over
//! 180 degrees...) are errors here too, at the token that holds them.
//!
//! This file splits the stream into blocks, `header` reads block headers, `at_token` says
//! where a token stands (and reports errors there); `entries` splits a
//! block body into keyword entries, `values` checks their arguments, and one file per
//! block kind (`scene`, `camera`, `light`, `material`, `object`, with `transform` shared by
//! cameras and objects) turns entries into typed settings; `tree` reads nested blocks.

mod at_token;
mod camera;
mod entries;
mod header;
mod light;
mod material;
mod object;
mod scene;
mod transform;
mod tree;
mod values;

use super::error::Diagnostics;
#[cfg(test)]
use super::error::LegacyError;
use super::lexer::{Comments, Token, block_word, is_grammar_word};
use super::syntax::{Block, ParsedBlock};
use at_token::{at, error};
use entries::decode;
pub use tree::MAX_NESTING;

pub(crate) use super::lexer::BLOCK_WORDS;

/// Parses the whole token stream into blocks. Blocks with errors in their header are
/// left out; entries with errors are left out of their block. Every error is pushed.
pub fn parse(
    tokens: &[Token<'_>],
    comments: &Comments<'_>,
    errors: &mut Diagnostics,
) -> Vec<ParsedBlock> {
    let mut blocks = Vec::new();
    let mut rest = tokens;
    while let Some(first) = rest.first() {
        if tree::opens_tree(rest) {
            let (node, used) = tree::parse_tree(rest, comments, 0, errors);
            blocks.extend(node.map(|node| ParsedBlock {
                at: node.at.clone(),
                block: Block::Object(node),
            }));
            rest = &rest[used..];
            continue;
        }
        match rest.iter().position(|t| t.is("End")) {
            Some(0) => {
                errors.push(error(first, "`End` with no block before it"));
                rest = &rest[1..];
            }
            Some(end) => {
                blocks.extend(parse_block(&rest[..end], comments, errors));
                rest = &rest[end + 1..];
            }
            None => {
                if let Some(word) = block_word(first) {
                    errors.push(error(
                        first,
                        format!("the {word} block has no `End` (unexpected end of file)"),
                    ));
                    blocks.extend(parse_block(rest, comments, errors));
                } else {
                    errors.push(error(
                        first,
                        "unexpected end of file: tokens after the last `End`",
                    ));
                }
                break;
            }
        }
    }
    blocks
}

/// One block: its tokens without the `End`; never empty.
fn parse_block(
    tokens: &[Token<'_>],
    comments: &Comments<'_>,
    errors: &mut Diagnostics,
) -> Option<ParsedBlock> {
    let (first, rest) = tokens.split_first()?;
    match block_word(first) {
        Some("Scene") => {
            let (settings, _) = decode(rest, &[scene::SCENE_WORDS], first, errors, scene::setting);
            Some(ParsedBlock {
                block: Block::Scene(entries::present(settings)),
                at: at(first),
            })
        }
        Some("Camera") => camera::parse_camera(first, rest, errors),
        Some("Light") => light::parse_light(first, rest, errors),
        Some("Material") => material::parse_material(first, rest, errors),
        Some("Object") => {
            let name = comments.name_before(first.line);
            let node = object::parse_object(first, rest, name, errors)?;
            Some(ParsedBlock {
                at: node.at.clone(),
                block: Block::Object(node),
            })
        }
        // A keyword where a block should start: an `End` too many closed its block.
        _ if is_grammar_word(first.text) => {
            errors.push(error(
                first,
                "a keyword outside any block: is there an `End` too many before it?",
            ));
            None
        }
        _ => {
            errors.warn(
                first.line,
                format!(
                    "unknown block type `{}` (expected Scene, Camera, Light, Material, \
                     Object, CSG or ObjectGroup): skipped up to its `End`",
                    first.text
                ),
            );
            None
        }
    }
}

#[cfg(test)]
fn parse_text(text: &str) -> (Vec<ParsedBlock>, Vec<LegacyError>) {
    let (blocks, diagnostics) = parse_diagnosed(text);
    (blocks, diagnostics.errors)
}

#[cfg(test)]
fn parse_diagnosed(text: &str) -> (Vec<ParsedBlock>, Diagnostics) {
    let mut diagnostics = Diagnostics::default();
    let comments = Comments::of(text);
    let blocks = parse(&super::lexer::tokenize(text), &comments, &mut diagnostics);
    (blocks, diagnostics)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrong_count_is_an_error_and_unknown_keyword_a_warning() {
        let (blocks, diagnostics) = parse_diagnosed("Material m\n Colour 1 0\n Shiny 3\nEnd");
        let summary: Vec<(usize, &str)> = diagnostics
            .errors
            .iter()
            .map(|e| (e.line, e.token.as_str()))
            .collect();
        assert_eq!(summary, [(2, "Colour")]);
        let [warning] = diagnostics.warnings.as_slice() else {
            panic!("{diagnostics:?}")
        };
        assert_eq!(warning.line, Some(3));
        assert!(warning.message.contains("`Shiny`"), "{warning}");
        assert_eq!(blocks.len(), 1);
    }

    #[test]
    fn a_missing_end_lists_the_blocks_keywords_in_order() {
        let (_, errors) = parse_text("Object Sphere\n  Colour 1 0 0\nObject Cube\nEnd");
        let [error] = errors.as_slice() else {
            panic!("{errors:?}")
        };
        assert_eq!(
            error.message,
            "unknown keyword in this Object block (expected Material, Colour, Ambient, \
             Diffuse, Specular, Mirror, Opacity, RefractiveIndex, Translate, Rotate, Scale, \
             Scale3, DisableBoundingBox); is the `End` of the Object block at line 1 missing?"
        );
    }

    #[test]
    fn a_keyword_where_a_block_should_start_is_an_error() {
        let (_, errors) =
            parse_text("Object CSG Union Object Sphere End End\nTranslate 0 1 0\nEnd");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!((errors[0].line, errors[0].token.as_str()), (2, "Translate"));
        assert!(
            errors[0].message.contains("`End` too many"),
            "{}",
            errors[0]
        );
    }

    #[test]
    fn unknown_block_types_are_skipped_with_a_warning() {
        let (blocks, diagnostics) =
            parse_diagnosed("Lamp Bright 3 End\nObject Sphere End\nObjekt Cube Scale 2 End");
        assert!(diagnostics.errors.is_empty(), "{diagnostics:?}");
        let lines: Vec<Option<usize>> = diagnostics.warnings.iter().map(|w| w.line).collect();
        assert_eq!(lines, [Some(1), Some(3)]);
        assert_eq!(blocks.len(), 1);
    }

    #[test]
    fn block_word_inside_a_block_hints_at_a_missing_end() {
        let (_, errors) = parse_text("Object Sphere\n Translate 0 0 1\nObject Cube\nEnd");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!((errors[0].line, errors[0].token.as_str()), (3, "Object"));
        assert!(
            errors[0].message.contains("line 1 missing"),
            "{}",
            errors[0]
        );
    }
}
