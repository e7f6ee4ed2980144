//! Objects and object trees as Object, CSG and ObjectGroup blocks, each named by a
//! comment on the line before it (as the importer reads names back), each leaf with its
//! material (its own or the nearest ancestor's) written as `Material NAME`.
//!
//! What each dialect's readers take:
//! - 2020: the base shapes, `Torus R` (a torus of minor radius 0.5 only, the course's
//!   proportions), `Tube R`, `Octahedron`; CSG as a block of its own (`CSG OP`) at the
//!   top level with two primitive operands; `ObjectGroup` at the top level holding
//!   primitives. A group inside a group is written into the outer one with its
//!   placement composed (warned: the inner group does not come back). No meshes.
//! - 2016: the base shapes and `Mesh PATH` (the framework lowercases the path: warned
//!   when that changes it); CSG as `Object CSG OP`, nesting to any depth, the node's
//!   transforms after its two operands. No ObjectGroup: a group's members are written
//!   as objects of their own with the group's placement composed after theirs (warned).
//!
//! A CSG node of one operand is written as that operand; one of three or more, in 2016,
//! as nested two-operand nodes (warned); in 2020 it is refused. Everything else is
//! refused by name: a group inside a CSG, a tree where the dialect takes primitives only, a shape the dialect
//! lacks, and a transform that is not a translate / rotate / scale.

use std::collections::HashSet;

use super::super::convert::{Dialect, LEGACY_TORUS_MINOR};
use super::super::lexer::Comments;
use super::materials::MaterialNames;
use super::numbers::number;
use super::problem::{Problems, Subject};
use super::steps::{SHEAR_REFUSAL, Step, steps};
use crate::scene::{CsgOp, Object, Shape, Transform};

/// Where an object is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Place {
    /// A block of its own.
    TopLevel,
    /// An operand of a CSG node.
    Operand,
    /// A member of an ObjectGroup (2020).
    Member,
}

/// Writes objects into one text.
pub struct ObjectWriter<'a> {
    dialect: Dialect,
    names: &'a MaterialNames,
    problems: &'a mut Problems,
    text: String,
}

impl<'a> ObjectWriter<'a> {
    /// A writer for `dialect`, naming materials by `names`.
    pub fn new(dialect: Dialect, names: &'a MaterialNames, problems: &'a mut Problems) -> Self {
        Self {
            dialect,
            names,
            problems,
            text: String::new(),
        }
    }

    /// Writes the scene's top-level objects, in order.
    pub fn write_all(mut self, objects: &[Object]) -> String {
        for (index, object) in objects.iter().enumerate() {
            let path = if object.name.is_empty() {
                format!("{} {index}", object.shape.name())
            } else {
                object.name.clone()
            };
            self.object(object, &path, None, &[], Place::TopLevel, 0);
        }
        self.text
    }

    fn refuse(&mut self, path: &str, message: impl Into<String>) {
        self.problems
            .refuse(Subject::Object(path.to_owned()), message);
    }

    /// One object: `path` names it in messages, `inherited` is the nearest ancestor's
    /// material, `trailing` the steps of flattened groups around it (applied after its
    /// own), `depth` its indentation.
    fn object(
        &mut self,
        object: &Object,
        path: &str,
        inherited: Option<&str>,
        trailing: &[Step],
        place: Place,
        depth: usize,
    ) {
        let own_material = Some(object.material.as_str()).filter(|m| !m.is_empty());
        let material = own_material.or(inherited);
        let Some(mut own_steps) = steps(&object.transform) else {
            self.refuse(path, SHEAR_REFUSAL);
            return;
        };
        own_steps.extend_from_slice(trailing);
        match &object.shape {
            Shape::Csg { op, operands } => {
                self.csg(
                    object, path, *op, operands, material, &own_steps, place, depth,
                );
            }
            Shape::Group { children } => {
                self.group(object, path, children, material, &own_steps, place, depth);
            }
            leaf => self.leaf(object, path, leaf, material, &own_steps, depth),
        }
    }

    fn leaf(
        &mut self,
        object: &Object,
        path: &str,
        shape: &Shape,
        material: Option<&str>,
        steps: &[Step],
        depth: usize,
    ) {
        let Some(kind) = self.leaf_kind(path, shape) else {
            return;
        };
        let Some(material) = material else {
            self.refuse(path, "it has no material (nor has any object it sits in)");
            return;
        };
        let names = self.names;
        let Some(written_material) = names.get(material) else {
            self.refuse(
                path,
                format!("its material \"{material}\" is not in the scene"),
            );
            return;
        };
        let indent = "  ".repeat(depth);
        self.name_comment(object, path, &indent);
        self.text.push_str(&format!("{indent}Object {kind}\n"));
        self.text
            .push_str(&format!("{indent}  Material {written_material}\n"));
        self.steps(steps, &indent);
        self.text.push_str(&format!("{indent}End\n"));
    }

    /// The words after `Object` for a leaf, or `None` (refused) when the dialect lacks it.
    fn leaf_kind(&mut self, path: &str, shape: &Shape) -> Option<String> {
        let is_2020 = self.dialect == Dialect::Framework2020;
        let lacks = |what: &str, other: &str| {
            format!(
                "the {} dialect has no {what} (use --dialect {other})",
                year(self.dialect)
            )
        };
        match shape {
            Shape::Sphere | Shape::Plane | Shape::Cube | Shape::Cylinder | Shape::Cone => {
                Some(shape.name().to_owned())
            }
            Shape::Torus { minor } if is_2020 => {
                if *minor == LEGACY_TORUS_MINOR {
                    Some("Torus 1".to_owned())
                } else {
                    self.refuse(
                        path,
                        format!(
                            "its torus has minor radius {}; the course's `Torus R` is always \
                             a tube of radius R/2 around a circle of radius R (minor 0.5)",
                            number(*minor)
                        ),
                    );
                    None
                }
            }
            Shape::Tube { inner } if is_2020 => {
                // The importer reads `Tube R` as inner = sqrt(R / 2): R = 2 inner^2, and
                // sqrt(inner^2) is inner again exactly.
                Some(format!("Tube {}", number(2.0 * inner * inner)))
            }
            Shape::Octahedron if is_2020 => Some("Octahedron".to_owned()),
            Shape::Mesh { path: file } if !is_2020 => {
                if file.contains(char::is_whitespace) || file.starts_with('#') {
                    self.refuse(
                        path,
                        format!(
                            "its mesh path \"{file}\" is not one word, as a course path must be"
                        ),
                    );
                    return None;
                }
                if file.to_lowercase() != *file {
                    self.problems.warn(
                        Subject::Object(path.to_owned()),
                        format!(
                            "the 2016 framework lowercases mesh paths: it opens \"{}\", not \
                             \"{file}\"",
                            file.to_lowercase()
                        ),
                    );
                }
                Some(format!("Mesh {file}"))
            }
            Shape::Torus { .. } => {
                self.refuse(path, lacks("Torus", "2020"));
                None
            }
            Shape::Tube { .. } => {
                self.refuse(path, lacks("Tube", "2020"));
                None
            }
            Shape::Octahedron => {
                self.refuse(path, lacks("Octahedron", "2020"));
                None
            }
            Shape::Mesh { .. } => {
                self.refuse(path, lacks("Mesh", "2016"));
                None
            }
            Shape::Csg { .. } | Shape::Group { .. } => None,
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn csg(
        &mut self,
        object: &Object,
        path: &str,
        op: CsgOp,
        operands: &[Object],
        material: Option<&str>,
        steps: &[Step],
        place: Place,
        depth: usize,
    ) {
        let subject = || Subject::Object(path.to_owned());
        let binary: Vec<Object>;
        let operands = match operands {
            [only] => {
                // A CSG node of one operand is that operand.
                self.problems.warn(
                    subject(),
                    format!(
                        "its CSG {} has one operand; the course readers take two: the operand \
                         is written alone, with the node's placement",
                        op.name()
                    ),
                );
                let only_path = child_path(path, only, 0);
                self.object(only, &only_path, material, steps, place, depth);
                return;
            }
            [_, _] => operands,
            _ if self.dialect == Dialect::Framework2016 => {
                self.problems.warn(
                    subject(),
                    format!(
                        "its CSG {} has {} operands; the course readers take two: written as \
                         nested two-operand CSG nodes ({}), which come back unnamed",
                        op.name(),
                        operands.len(),
                        match op {
                            CsgOp::Difference => "the first minus the union of the others",
                            CsgOp::Union | CsgOp::Intersection => "each holding the next",
                        }
                    ),
                );
                binary = two_operands(op, operands);
                &binary
            }
            _ => {
                self.refuse(
                    path,
                    format!(
                        "its CSG {} has {} operands; the 2020 dialect's CSG block takes exactly \
                         two primitives (use --dialect 2016, which nests)",
                        op.name(),
                        operands.len()
                    ),
                );
                return;
            }
        };
        let header = match self.dialect {
            Dialect::Framework2016 => format!("Object CSG {}", op.name()),
            Dialect::Framework2020 => {
                if place != Place::TopLevel {
                    self.refuse(
                        path,
                        "a CSG inside another tree: the 2020 dialect's `CSG` is a block of its \
                         own at the top level (use --dialect 2016, whose `Object CSG` nests)",
                    );
                    return;
                }
                if let Some(tree) = operands.iter().find(|o| o.shape.is_tree_node()) {
                    self.refuse(
                        path,
                        format!(
                            "its operand \"{}\" is a tree; the 2020 dialect's CSG operands are \
                             primitives (use --dialect 2016, whose `Object CSG` nests)",
                            tree.name
                        ),
                    );
                    return;
                }
                format!("CSG {}", op.name())
            }
        };
        let indent = "  ".repeat(depth);
        self.name_comment(object, path, &indent);
        self.text.push_str(&format!("{indent}{header}\n"));
        for (index, operand) in operands.iter().enumerate() {
            let operand_path = child_path(path, operand, index);
            if matches!(operand.shape, Shape::Group { .. }) {
                self.refuse(
                    &operand_path,
                    "a group as a CSG operand: the course readers' CSG operands are solids, \
                     not groups",
                );
                continue;
            }
            self.object(
                operand,
                &operand_path,
                material,
                &[],
                Place::Operand,
                depth + 1,
            );
        }
        self.steps(steps, &indent);
        self.text.push_str(&format!("{indent}End\n"));
    }

    #[allow(clippy::too_many_arguments)]
    fn group(
        &mut self,
        object: &Object,
        path: &str,
        children: &[Object],
        material: Option<&str>,
        steps: &[Step],
        place: Place,
        depth: usize,
    ) {
        if place == Place::Operand {
            self.refuse(
                path,
                "a group as a CSG operand: the course readers' CSG operands are solids, not \
                 groups",
            );
            return;
        }
        let flattened = match self.dialect {
            Dialect::Framework2016 => Some((
                place,
                depth,
                "the 2016 framework has no ObjectGroup: its members are written as objects \
                 of their own, with its placement; the group does not come back",
            )),
            Dialect::Framework2020 if place == Place::Member => Some((
                place,
                depth,
                "a group inside a group: its members are written into the outer ObjectGroup, \
                 with its placement; the inner group does not come back",
            )),
            Dialect::Framework2020 => None,
        };
        if let Some((place, depth, why)) = flattened {
            self.problems.warn(Subject::Object(path.to_owned()), why);
            for (index, child) in children.iter().enumerate() {
                let child_path = child_path(path, child, index);
                self.object(child, &child_path, material, steps, place, depth);
            }
            return;
        }
        let indent = "  ".repeat(depth);
        self.name_comment(object, path, &indent);
        self.text.push_str(&format!("{indent}ObjectGroup\n"));
        for (index, child) in children.iter().enumerate() {
            let child_path = child_path(path, child, index);
            if matches!(child.shape, Shape::Csg { .. }) {
                self.refuse(
                    &child_path,
                    "a CSG inside an ObjectGroup: the 2020 readers' groups hold primitives \
                     (use --dialect 2016)",
                );
                continue;
            }
            self.object(child, &child_path, material, &[], Place::Member, depth + 1);
        }
        self.steps(steps, &indent);
        self.text.push_str(&format!("{indent}End\n"));
    }

    fn steps(&mut self, steps: &[Step], indent: &str) {
        for step in steps {
            self.text.push_str(&format!("{indent}  {step}\n"));
        }
    }

    /// The comment that names the block about to be written, when the importer reads
    /// the name back from it; a name it cannot read back is warned about.
    fn name_comment(&mut self, object: &Object, path: &str, indent: &str) {
        if object.name.is_empty() {
            return;
        }
        match name_comment(&object.name) {
            Some(comment) => self.text.push_str(&format!("{indent}{comment}\n")),
            None => self.problems.warn(
                Subject::Object(path.to_owned()),
                "its name cannot be written as a comment the importer reads back (it is \
                 empty after trimming, longer than 60 characters, holds a line break or a \
                 `/`, or starts with a keyword of the format): it comes back with \
                 the default name \"<Shape> <index>\"",
            ),
        }
    }
}

/// Two operands that make the same solid as `operands` (three or more): the first,
/// and the others combined by the same operation for a union or an intersection, by a
/// union for a difference (A minus B minus C is A minus (B union C)). The others are
/// combined two at a time, halves first, so the tree stays shallow; the nodes made here
/// have no name, transform or material (their leaves keep theirs).
fn two_operands(op: CsgOp, operands: &[Object]) -> Vec<Object> {
    let rest_op = match op {
        CsgOp::Difference => CsgOp::Union,
        CsgOp::Union | CsgOp::Intersection => op,
    };
    let (first, rest) = operands.split_at(1);
    vec![first[0].clone(), balanced(rest_op, rest)]
}

/// `operands` (at least one) combined by `op`, two at a time: each half, then both.
fn balanced(op: CsgOp, operands: &[Object]) -> Object {
    if let [only] = operands {
        return only.clone();
    }
    let (left, right) = operands.split_at(operands.len() / 2);
    Object {
        name: String::new(),
        shape: Shape::Csg {
            op,
            operands: vec![balanced(op, left), balanced(op, right)],
        },
        transform: Transform::default(),
        material: String::new(),
    }
}

/// `# name`, when the importer reads exactly `name` back from it.
#[must_use]
pub fn name_comment(name: &str) -> Option<String> {
    if name.contains(['\n', '\r']) {
        return None;
    }
    let comment = format!("# {name}");
    let text = format!("{comment}\nObject");
    (Comments::of(&text).name_before(2).as_deref() == Some(name)).then_some(comment)
}

/// The names of the materials some leaf of `objects` is drawn with (its own, else the
/// nearest ancestor's).
#[must_use]
pub fn used_materials(objects: &[Object]) -> HashSet<String> {
    let mut used = HashSet::new();
    // A work list, not recursion: trees may be deep.
    let mut pending: Vec<(&Object, &str)> = objects.iter().map(|o| (o, "")).collect();
    while let Some((object, inherited)) = pending.pop() {
        let material = if object.material.is_empty() {
            inherited
        } else {
            object.material.as_str()
        };
        match object.shape.children() {
            [] if !object.shape.is_tree_node() => {
                used.insert(material.to_owned());
            }
            children => pending.extend(children.iter().map(|c| (c, material))),
        }
    }
    used
}

/// The tree path of a child: its name, or its default one where it has none.
fn child_path(parent: &str, child: &Object, index: usize) -> String {
    if child.name.is_empty() {
        format!("{parent}/{} {index}", child.shape.name())
    } else {
        format!("{parent}/{}", child.name)
    }
}

/// "2016" or "2020".
pub fn year(dialect: Dialect) -> &'static str {
    match dialect {
        Dialect::Framework2016 => "2016",
        Dialect::Framework2020 => "2020",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_go_out_as_comments_only_where_they_come_back() {
        assert_eq!(
            name_comment("Snowman's body").as_deref(),
            Some("# Snowman's body")
        );
        assert_eq!(name_comment("#tag").as_deref(), Some("# #tag"));
        for lost in [
            "a/b",
            "Mirror ball",
            " padded",
            "two\nlines",
            &"x".repeat(61),
        ] {
            assert_eq!(name_comment(lost), None, "{lost:?}");
        }
    }
}
