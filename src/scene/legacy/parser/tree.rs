//! Object trees: `Object CSG OP` (the 2016 framework's form), `CSG OP ... End` (a block
//! of its own) and `ObjectGroup ... End`.
//!
//! Inside a tree each `End` closes the innermost open object, as the 2016 reader pairs
//! `Object` and `End` tokens. Operands and children are `Object ... End` blocks (which
//! may be trees again, or `CSG` / `ObjectGroup` blocks); every other token belongs to the
//! node itself (its transforms, wherever they sit among the operands, in file order).
//! Nesting deeper than [`MAX_NESTING`] is an error at the block that goes too deep.

use super::super::error::Diagnostics;
use super::super::lexer::{Comments, Token};
use super::super::syntax::{CsgForm, ObjectKind, ObjectNode};
use super::at_token::{at, error};
use super::entries::{decode, present};
use super::object::{OBJECT_WORDS, object_setting, parse_object};
use crate::scene::CsgOp;

/// The deepest nesting of trees a legacy file may have: far beyond the few levels
/// students' files use (a snowman is three), and well inside the scene format's
/// `MAX_TREE_DEPTH`. The importer reads, converts and names trees recursively, so this
/// bounds its stack (a thread's default 2 MiB holds it in a debug build).
pub const MAX_NESTING: usize = 100;

/// Whether `tokens` start a tree: `Object CSG`, `CSG` or `ObjectGroup`.
pub(super) fn opens_tree(tokens: &[Token<'_>]) -> bool {
    match tokens {
        [first, second, ..] if first.is("Object") && second.is("CSG") => true,
        [first, ..] => first.is("CSG") || first.is("ObjectGroup"),
        [] => false,
    }
}

/// Reads the tree that `tokens` start (see [`opens_tree`]) at nesting `depth` (0 at the
/// top level). Returns the node (`None` when it is broken, with errors pushed) and how
/// many tokens it used, up to and including its `End`.
pub(super) fn parse_tree(
    tokens: &[Token<'_>],
    comments: &Comments<'_>,
    depth: usize,
    errors: &mut Diagnostics,
) -> (Option<ObjectNode>, usize) {
    let first = tokens[0];
    if depth >= MAX_NESTING {
        errors.push(error(
            &first,
            format!(
                "objects nest more than {MAX_NESTING} levels deep here (the importer's limit; \
                 students' scenes nest a few)"
            ),
        ));
        return (
            None,
            matching_end(tokens).map_or(tokens.len(), |end| end + 1),
        );
    }
    let name = comments.name_before(first.line);
    let is_2016 = first.is("Object");
    // The token naming the kind: `CSG` or `ObjectGroup`.
    let kind_token = if is_2016 { tokens[1] } else { first };
    let mut i = if is_2016 { 2 } else { 1 };
    let op = if kind_token.is("CSG") {
        let op = tokens
            .get(i)
            .and_then(|t| CsgOp::ALL.into_iter().find(|op| t.is(op.name())));
        if op.is_none() {
            let near = tokens.get(i).unwrap_or(&kind_token);
            errors.push(error(
                near,
                "`CSG` takes an operation: Union, Intersection or Difference",
            ));
        } else {
            i += 1;
        }
        Some(op)
    } else {
        None
    };
    let mut own: Vec<Token<'_>> = Vec::new();
    let mut children: Vec<ObjectNode> = Vec::new();
    let mut closed = false;
    while let Some(token) = tokens.get(i) {
        let rest = &tokens[i..];
        if token.is("End") {
            i += 1;
            closed = true;
            break;
        } else if opens_tree(rest) {
            let (child, used) = parse_tree(rest, comments, depth + 1, errors);
            children.extend(child);
            i += used;
        } else if token.is("Object") {
            let end = rest.iter().position(|t| t.is("End"));
            let body = &rest[1..end.unwrap_or(rest.len())];
            if end.is_none() {
                errors.push(error(
                    token,
                    "the Object block has no `End` (unexpected end of file)",
                ));
            }
            let name = comments.name_before(token.line);
            children.extend(parse_object(token, body, name, errors));
            i += end.map_or(rest.len(), |end| end + 1);
        } else {
            own.push(*token);
            i += 1;
        }
    }
    if !closed {
        errors.push(error(
            &first,
            format!(
                "the {} block has no `End` (unexpected end of file)",
                kind_token.text
            ),
        ));
    }
    let (settings, _) = decode(&own, OBJECT_WORDS, &kind_token, errors, object_setting);
    let kind = match op {
        Some(Some(op)) => ObjectKind::Csg {
            op,
            form: if is_2016 {
                CsgForm::Object2016
            } else {
                CsgForm::TopLevel
            },
            operands: children,
        },
        Some(None) => return (None, i),
        None => ObjectKind::Group(children),
    };
    let node = ObjectNode {
        kind,
        settings: present(settings),
        name,
        at: at(&kind_token),
    };
    (Some(node), i)
}

/// The index of the `End` that closes the tree `tokens` start, pairing every `Object`,
/// `CSG` (not right after `Object`) and `ObjectGroup` with an `End`; without recursion,
/// so any depth is safe.
fn matching_end(tokens: &[Token<'_>]) -> Option<usize> {
    let mut open = 0usize;
    for (index, token) in tokens.iter().enumerate() {
        let after_object = index > 0 && tokens[index - 1].is("Object");
        let opens =
            token.is("Object") || token.is("ObjectGroup") || (token.is("CSG") && !after_object);
        if opens {
            open += 1;
        } else if token.is("End") {
            open = open.saturating_sub(1);
            if open == 0 {
                return Some(index);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::super::super::syntax::{Block, ObjectSetting};
    use super::super::parse_text;
    use super::*;

    fn object(text: &str) -> ObjectNode {
        let (blocks, errors) = parse_text(text);
        assert!(errors.is_empty(), "{errors:?}");
        let [block] = blocks.as_slice() else {
            panic!("{blocks:?}")
        };
        let Block::Object(node) = &block.block else {
            panic!("{blocks:?}")
        };
        node.clone()
    }

    #[test]
    fn each_end_closes_the_innermost_object() {
        let node = object(
            "Object CSG Difference\n Object CSG Union Object Sphere End Object Cube End End\n \
             Object Cone End\n Translate 0 1 0\nEnd",
        );
        let ObjectKind::Csg { op, form, operands } = &node.kind else {
            panic!("{node:?}")
        };
        assert_eq!((*op, *form), (CsgOp::Difference, CsgForm::Object2016));
        assert_eq!(operands.len(), 2);
        assert!(
            matches!(&operands[0].kind, ObjectKind::Csg { operands, .. } if operands.len() == 2)
        );
        assert!(matches!(
            node.settings[0].value,
            ObjectSetting::Transform(_)
        ));
    }

    #[test]
    fn top_level_csg_takes_node_transforms_between_operands() {
        let node =
            object("CSG Union Scale 2 Object Sphere End Translate 1 0 0 Object Cube End End");
        assert!(matches!(
            node.kind,
            ObjectKind::Csg {
                form: CsgForm::TopLevel,
                ..
            }
        ));
        assert_eq!(node.settings.len(), 2);
    }

    #[test]
    fn a_group_holds_any_number_of_children() {
        let node = object(
            "ObjectGroup Object Sphere End Translate 0 0 5 Object Cube End Object Cone End End",
        );
        assert!(matches!(&node.kind, ObjectKind::Group(children) if children.len() == 3));
    }

    #[test]
    fn an_unbalanced_tree_is_an_error_at_its_start() {
        let (_, errors) = parse_text("Object CSG Union\nObject Sphere End\nObject Cube End\n");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!((errors[0].line, errors[0].token.as_str()), (1, "Object"));
        let (_, errors) = parse_text("CSG Xor Object Sphere End End");
        assert_eq!(errors[0].token, "Xor");
    }

    #[test]
    fn matching_end_pairs_objects_at_any_depth() {
        let text = "ObjectGroup ".repeat(5000) + &"End ".repeat(5000);
        let tokens = super::super::super::lexer::tokenize(&text);
        assert_eq!(matching_end(&tokens), Some(9999));
    }
}
