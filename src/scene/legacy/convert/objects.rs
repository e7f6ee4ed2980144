//! Object blocks and object trees: each leaf copies its material (and may change its
//! copy), `Torus R` and `Tube R` become the scene's parametric shapes, `Mesh PATH` is
//! found beside the scene, CSG nodes and groups keep their operands and children.
//!
//! `Torus R` is the legacy unit torus (centre circle 1, tube radius 0.5) scaled by R, so
//! it imports as `Torus(minor: 0.5)` with a scale R applied first; `Tube R` is the solid
//! between radius sqrt(R/2) and 1, so `Tube(inner: sqrt(R/2))`. A tree node's transforms
//! apply after its operands' own (world = parent * child); its material keywords do
//! nothing in the legacy readers and are ignored with a warning.

use super::super::syntax::{At, Item, ObjectKind, ObjectNode, ObjectSetting, TransformStep};
use super::converter::Converter;
use super::materials::apply;
use super::pending::{Base, PendingObject, PendingShape};
use super::transform::{compose, scene_transform};
use crate::scene::{CsgOp, Shape};

/// The tube radius of the legacy unit torus (its centre circle has radius 1).
pub const LEGACY_TORUS_MINOR: f64 = 0.5;

impl Converter<'_> {
    /// A top-level Object, CSG or ObjectGroup block.
    pub(super) fn object_block(&mut self, node: &ObjectNode) {
        if let Some(object) = self.object_node(node) {
            self.objects.push(object);
        }
    }

    /// One object and everything below it; `None` when it is skipped (warned) or broken
    /// (errors pushed).
    fn object_node(&mut self, node: &ObjectNode) -> Option<PendingObject> {
        let (shape, first_steps) = match &node.kind {
            ObjectKind::Skipped => return None,
            ObjectKind::Shape(shape) => (shape.clone(), Vec::new()),
            ObjectKind::Torus(r) => (
                Shape::Torus {
                    minor: LEGACY_TORUS_MINOR,
                },
                vec![TransformStep::Scale(*r)],
            ),
            ObjectKind::Tube(r) => (
                Shape::Tube {
                    inner: (r / 2.0).sqrt(),
                },
                Vec::new(),
            ),
            ObjectKind::Mesh(path) => (
                Shape::Mesh {
                    path: self.mesh_path(path, &node.at)?,
                },
                Vec::new(),
            ),
            ObjectKind::Csg { op, operands, .. } => {
                return self.tree_node(node, Some(*op), operands);
            }
            ObjectKind::Group(children) => return self.tree_node(node, None, children),
        };
        self.leaf(node, shape, first_steps)
    }

    /// A leaf: its material, overrides and transforms (after `first_steps`).
    fn leaf(
        &mut self,
        node: &ObjectNode,
        shape: Shape,
        mut steps: Vec<TransformStep>,
    ) -> Option<PendingObject> {
        let mut material = self.default_material();
        let mut base = Base::Default;
        let mut overridden_at: Option<usize> = None;
        let mut ok = true;
        for setting in &node.settings {
            match &setting.value {
                ObjectSetting::Material(name) => match self.lookup_material(name, &setting.at) {
                    Some(index) => {
                        if let Some(line) = overridden_at.take() {
                            self.warn(
                                line,
                                format!(
                                    "this material change is undone by `Material {name}` at line {}, \
                                     which copies the whole material",
                                    setting.at.line
                                ),
                            );
                        }
                        material = self.definitions[index].material.clone();
                        base = Base::Definition(index);
                    }
                    None => ok = false,
                },
                ObjectSetting::Surface(edit) => {
                    apply(&mut material, edit);
                    overridden_at.get_or_insert(setting.at.line);
                }
                ObjectSetting::Transform(step) => steps.push(*step),
            }
        }
        if !ok {
            return None;
        }
        let base_material = match base {
            Base::Default => self.default_material(),
            Base::Definition(index) => self.definitions[index].material.clone(),
        };
        let own = (overridden_at.is_some() && material != base_material).then_some(material);
        if own.is_none() {
            match base {
                Base::Default => self.default_used = true,
                Base::Definition(index) => self.definitions[index].used = true,
            }
        }
        Some(PendingObject {
            name: node.name.clone(),
            shape: PendingShape::Leaf { shape, base, own },
            transform: scene_transform(&compose(&steps)),
            at: node.at.clone(),
        })
    }

    /// A CSG node (`op` given) or a group, with the members that import.
    fn tree_node(
        &mut self,
        node: &ObjectNode,
        op: Option<CsgOp>,
        members: &[ObjectNode],
    ) -> Option<PendingObject> {
        let what = match op {
            Some(op) => format!("CSG {}", op.name()),
            None => "ObjectGroup".to_owned(),
        };
        let article = if op.is_some() { "a" } else { "an" };
        let steps = self.node_steps(&node.settings, &format!("{article} {what}"));
        let imported: Vec<PendingObject> =
            members.iter().filter_map(|m| self.object_node(m)).collect();
        let shape = match op {
            Some(op) => {
                if imported.is_empty() {
                    self.warn(
                        node.at.line,
                        format!("this {what} has no operand that imports: skipped"),
                    );
                    return None;
                }
                if members.len() != 2 {
                    self.warn(
                        node.at.line,
                        format!(
                            "this {what} has {} operands; the legacy readers take exactly two, \
                             raylab combines them all",
                            members.len()
                        ),
                    );
                }
                PendingShape::Csg {
                    op,
                    operands: imported,
                }
            }
            None => PendingShape::Group(imported),
        };
        Some(PendingObject {
            name: node.name.clone(),
            shape,
            transform: scene_transform(&compose(&steps)),
            at: node.at.clone(),
        })
    }

    /// A tree node's transforms, in file order; its material keywords are ignored with a
    /// warning each.
    fn node_steps(&mut self, settings: &[Item<ObjectSetting>], what: &str) -> Vec<TransformStep> {
        let mut steps = Vec::new();
        for setting in settings {
            match &setting.value {
                ObjectSetting::Transform(step) => steps.push(*step),
                ObjectSetting::Material(_) | ObjectSetting::Surface(_) => self.warn(
                    setting.at.line,
                    format!(
                        "`{}` on {what} node does nothing in the legacy readers (its \
                         members keep their own materials): ignored",
                        setting.at.token
                    ),
                ),
            }
        }
        steps
    }

    /// The path a `Mesh PATH` imports with. With the scene's folder known, the file must
    /// be there, as written or lowercased (the 2016 framework lowercases it); a missing
    /// file draws nothing in the legacy renderer, so the object is skipped with a warning.
    fn mesh_path(&mut self, path: &str, at: &At) -> Option<String> {
        let Some(folder) = self.folder.clone() else {
            return Some(path.to_owned());
        };
        let lowercased = path.to_lowercase();
        if let Some(found) = [path, lowercased.as_str()]
            .into_iter()
            .find(|candidate| folder.join(candidate).is_file())
        {
            return Some(found.to_owned());
        }
        self.warn(
            at.line,
            format!(
                "Mesh `{path}`: no such file in {} (as written or lowercased); the legacy \
                 renderer draws nothing for it: skipped",
                folder.display()
            ),
        );
        None
    }
}
