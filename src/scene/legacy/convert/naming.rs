//! Names for what an import makes: materials (used ones, and the last definition of each
//! name) and objects, which become scene objects with the names of their materials.
//!
//! Objects take the name their comment gives them, else "<Shape> <index>" (the scene
//! format's default names, counting only the imported objects among their siblings). An
//! object that changes its material's copy gets a material of its own,
//! "<material> (<object path>)".

use std::collections::{BTreeMap, HashSet};

use super::converter::Converter;
use super::materials::{DEFAULT_MATERIAL_NAME, default_material, unique};
use super::pending::{Base, PendingObject, PendingShape};
use crate::scene::{Material, Object, Scene, Shape};

/// What the naming needs besides the objects.
struct Names {
    materials: BTreeMap<String, Material>,
    taken: HashSet<String>,
    definition_names: Vec<String>,
    default_name: Option<String>,
}

impl Converter<'_> {
    /// Names every material that is used (or is the last definition of its name), and
    /// the objects with the names of their materials; each top-level object is checked
    /// against the scene rules.
    pub(super) fn materials_and_objects(&mut self) -> (BTreeMap<String, Material>, Vec<Object>) {
        let mut materials = BTreeMap::new();
        let mut taken: HashSet<String> = self.definitions.iter().map(|d| d.name.clone()).collect();
        let definition_names: Vec<String> = (0..self.definitions.len())
            .map(|index| {
                let definition = &self.definitions[index];
                if self.latest.get(&definition.name) == Some(&index) {
                    definition.name.clone()
                } else {
                    unique(
                        &mut taken,
                        format!("{} (line {})", definition.name, definition.line),
                    )
                }
            })
            .collect();
        for (index, definition) in self.definitions.iter().enumerate() {
            if definition.used || self.latest.get(&definition.name) == Some(&index) {
                materials.insert(definition_names[index].clone(), definition.material.clone());
            }
        }
        let needs_default = self.default_used || copies_default(&self.objects);
        let default_name = needs_default.then(|| unique(&mut taken, DEFAULT_MATERIAL_NAME.into()));
        if self.default_used
            && let Some(name) = &default_name
        {
            materials.insert(name.clone(), default_material(self.dialect.dialect));
        }
        let mut names = Names {
            materials,
            taken,
            definition_names,
            default_name,
        };
        let mut objects = Vec::new();
        for (index, pending) in std::mem::take(&mut self.objects).into_iter().enumerate() {
            let at = pending.at.clone();
            let object = finish(pending, index, "", &mut names);
            let fragment = Scene {
                materials: names.materials.clone(),
                objects: vec![object.clone()],
                ..Scene::empty()
            };
            self.check(&fragment, &at, "this object cannot be imported");
            objects.push(object);
        }
        (names.materials, objects)
    }
}

/// Whether some leaf copies the default material (and so needs its name).
fn copies_default(objects: &[PendingObject]) -> bool {
    objects.iter().any(|object| match &object.shape {
        PendingShape::Leaf { base, .. } => matches!(base, Base::Default),
        PendingShape::Csg {
            operands: members, ..
        }
        | PendingShape::Group(members) => copies_default(members),
    })
}

/// Siblings in file order, named "<Shape> <index>" unless a comment names them.
fn finish_siblings(
    pending: Vec<PendingObject>,
    parent_path: &str,
    names: &mut Names,
) -> Vec<Object> {
    pending
        .into_iter()
        .enumerate()
        .map(|(index, object)| finish(object, index, parent_path, names))
        .collect()
}

fn finish(pending: PendingObject, index: usize, parent_path: &str, names: &mut Names) -> Object {
    let name = pending
        .name
        .clone()
        .unwrap_or_else(|| format!("{} {index}", pending.kind_name()));
    let path = if parent_path.is_empty() {
        name.clone()
    } else {
        format!("{parent_path}/{name}")
    };
    let (shape, material) = match pending.shape {
        PendingShape::Leaf { shape, base, own } => {
            let base_name = match base {
                Base::Default => names.default_name.clone().unwrap_or_default(),
                Base::Definition(i) => names.definition_names[i].clone(),
            };
            let material = match own {
                None => base_name,
                Some(own) => {
                    let own_name = unique(&mut names.taken, format!("{base_name} ({path})"));
                    names.materials.insert(own_name.clone(), own);
                    own_name
                }
            };
            (shape, material)
        }
        PendingShape::Csg { op, operands } => (
            Shape::Csg {
                op,
                operands: finish_siblings(operands, &path, names),
            },
            String::new(),
        ),
        PendingShape::Group(children) => (
            Shape::Group {
                children: finish_siblings(children, &path, names),
            },
            String::new(),
        ),
    };
    Object {
        name,
        shape,
        transform: pending.transform,
        material,
    }
}
