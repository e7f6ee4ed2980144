//! Materials and the objects that use them: Material blocks in file order, objects that
//! copy a material (and may change their copy), and the names the materials get.
//!
//! Naming: objects are "<Shape> <index>" (the scene format's default names, counting only
//! imported objects). An object that overrides its material gets a material of its own,
//! "<material> (<object>)". The default material is "default" (only added when used). A
//! material defined twice keeps its name for the last definition; objects before that
//! keep the earlier one as "<name> (line N)". Generated names never clash with names in
//! the file: a clash gets " 2", " 3"... appended.

use std::collections::{BTreeMap, HashSet};

use glam::DVec3;

use super::super::error::LegacyError;
use super::super::syntax::{At, Item, ObjectKind, ObjectSetting, SurfaceEdit, TransformStep};
use super::Converter;
use super::transform::{compose, scene_transform};
use crate::scene::{Material, Object, Scene, Shape, Transform};

/// Preferred name of the legacy default (magenta) material.
pub const DEFAULT_MATERIAL_NAME: &str = "default";

/// The legacy default material: magenta ambient and diffuse, nothing else. Material
/// blocks start from it too.
#[must_use]
pub fn default_material() -> Material {
    let magenta = DVec3::new(1.0, 0.0, 1.0);
    Material {
        ambient: magenta,
        diffuse: magenta,
        specular: DVec3::ZERO,
        shininess: 1.0,
        mirror: DVec3::ZERO,
        transmission: DVec3::ZERO,
        ior: 1.0,
    }
}

/// One Material block's result.
pub(super) struct Definition {
    name: String,
    material: Material,
    line: usize,
    used: bool,
}

/// Which material an object copied.
#[derive(Clone, Copy)]
enum Base {
    Default,
    Definition(usize),
}

/// An object before materials are named.
pub(super) struct PendingObject {
    shape: Shape,
    transform: Transform,
    base: Base,
    own: Option<Material>,
    at: At,
}

impl PendingObject {
    /// The centre of the object's bounds in world space: the unit shape's centre
    /// (the origin, but (0, 0, 0.5) for the cone, whose apex is at the origin) placed by
    /// its transform.
    pub(super) fn centre(&self) -> DVec3 {
        let unit_centre = match self.shape {
            Shape::Cone => DVec3::new(0.0, 0.0, 0.5),
            _ => DVec3::ZERO,
        };
        self.transform
            .world_from_object()
            .transform_point3(unit_centre)
    }
}

impl Converter<'_> {
    pub(super) fn material_block(&mut self, name: &str, edits: &[Item<SurfaceEdit>], at: &At) {
        let mut material = default_material();
        for edit in edits {
            apply(&mut material, &edit.value);
        }
        if let Some(&previous) = self.latest.get(name) {
            let line = self.definitions[previous].line;
            self.warn(
                at.line,
                format!(
                    "material `{name}` is defined again (before: line {line}); \
                     objects above this line keep the earlier definition"
                ),
            );
        }
        self.latest.insert(name.to_owned(), self.definitions.len());
        self.definitions.push(Definition {
            name: name.to_owned(),
            material,
            line: at.line,
            used: false,
        });
    }

    pub(super) fn object_block(
        &mut self,
        kind: ObjectKind,
        settings: &[Item<ObjectSetting>],
        at: &At,
    ) {
        let mut material = default_material();
        let mut base = Base::Default;
        let mut overridden_at: Option<usize> = None;
        let mut steps: Vec<TransformStep> = Vec::new();
        let mut ok = true;
        for setting in settings {
            match &setting.value {
                ObjectSetting::Material(name) => match self.latest.get(name).copied() {
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
                    None => {
                        ok = false;
                        let message = match self.first_definition.get(name) {
                            Some(line) => format!(
                                "material used before it is defined (its definition is at line {line})"
                            ),
                            None => "material used but never defined".to_owned(),
                        };
                        self.errors
                            .push(LegacyError::new(setting.at.line, name, message));
                    }
                },
                ObjectSetting::Surface(edit) => {
                    apply(&mut material, edit);
                    overridden_at.get_or_insert(setting.at.line);
                }
                ObjectSetting::Transform(step) => steps.push(*step),
            }
        }
        let ObjectKind::Shape(shape) = kind;
        if !ok {
            return;
        }
        let base_material = match base {
            Base::Default => default_material(),
            Base::Definition(index) => self.definitions[index].material.clone(),
        };
        let own = (overridden_at.is_some() && material != base_material).then_some(material);
        if own.is_none() {
            match base {
                Base::Default => self.default_used = true,
                Base::Definition(index) => self.definitions[index].used = true,
            }
        }
        self.objects.push(PendingObject {
            shape,
            transform: scene_transform(&compose(&steps)),
            base,
            own,
            at: at.clone(),
        });
    }

    /// Names every material that is used (or is the last definition of its name), and
    /// the objects with the names of their materials; each object is checked against
    /// the scene rules.
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
        let needs_default =
            self.default_used || self.objects.iter().any(|o| matches!(o.base, Base::Default));
        let default_name = needs_default.then(|| unique(&mut taken, DEFAULT_MATERIAL_NAME.into()));
        if self.default_used
            && let Some(name) = &default_name
        {
            materials.insert(name.clone(), default_material());
        }

        let mut objects = Vec::new();
        for (index, pending) in std::mem::take(&mut self.objects).into_iter().enumerate() {
            let name = format!("{} {index}", pending.shape.name());
            let base_name = match pending.base {
                Base::Default => default_name.clone().unwrap_or_default(),
                Base::Definition(i) => definition_names[i].clone(),
            };
            let material = match pending.own {
                None => base_name,
                Some(own) => {
                    let own_name = unique(&mut taken, format!("{base_name} ({name})"));
                    materials.insert(own_name.clone(), own);
                    own_name
                }
            };
            let object = Object {
                name,
                shape: pending.shape,
                transform: pending.transform,
                material,
            };
            self.check_object(&object, &materials, &pending.at);
            objects.push(object);
        }
        (materials, objects)
    }

    fn check_object(&mut self, object: &Object, materials: &BTreeMap<String, Material>, at: &At) {
        let fragment = Scene {
            materials: materials
                .get_key_value(&object.material)
                .map(|(name, material)| (name.clone(), material.clone()))
                .into_iter()
                .collect(),
            objects: vec![object.clone()],
            ..Scene::empty()
        };
        self.check(&fragment, at, "this object cannot be imported");
    }
}

/// Applies one material keyword to a material.
fn apply(material: &mut Material, edit: &SurfaceEdit) {
    match *edit {
        SurfaceEdit::Colour(c) => {
            material.ambient = c;
            material.diffuse = c;
        }
        SurfaceEdit::Ambient(c) => material.ambient = c,
        SurfaceEdit::Diffuse(c) => material.diffuse = c,
        SurfaceEdit::Specular { colour, exponent } => {
            material.specular = colour;
            material.shininess = exponent;
        }
        SurfaceEdit::Mirror(c) => material.mirror = c,
    }
}

/// `wanted`, or `wanted 2`, `wanted 3`... whichever is free first; the name is then taken.
fn unique(taken: &mut HashSet<String>, wanted: String) -> String {
    let mut name = wanted.clone();
    let mut n = 2;
    while taken.contains(&name) {
        name = format!("{wanted} {n}");
        n += 1;
    }
    taken.insert(name.clone());
    name
}
