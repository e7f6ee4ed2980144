//! Material blocks in file order, the material an object's `Material NAME` copies, and
//! the material keywords.
//!
//! Naming (done with the objects, in `objects`): an object that overrides its material
//! gets a material of its own, "<material> (<object>)". The default material is "default"
//! (only added when used). A material defined twice keeps its name for the last
//! definition; objects before that keep the earlier one as "<name> (line N)". Generated
//! names never clash with names in the file: a clash gets " 2", " 3"... appended.

use std::collections::HashSet;

use glam::DVec3;

use super::super::error::LegacyError;
use super::super::syntax::{At, Item, SurfaceEdit};
use super::converter::Converter;
use super::dialect::Dialect;
use super::pending::Definition;
use crate::scene::Material;

/// Preferred name of the legacy default material.
pub const DEFAULT_MATERIAL_NAME: &str = "default";

/// The legacy default material: ambient and diffuse magenta (white in the 2016
/// framework), nothing else. Material blocks start from it too.
#[must_use]
pub fn default_material(dialect: Dialect) -> Material {
    let colour = match dialect {
        Dialect::Framework2016 => DVec3::ONE,
        Dialect::Framework2020 => DVec3::new(1.0, 0.0, 1.0),
    };
    Material {
        ambient: colour,
        diffuse: colour,
        specular: DVec3::ZERO,
        shininess: 1.0,
        mirror: DVec3::ZERO,
        transmission: DVec3::ZERO,
        ior: 1.0,
    }
}

impl Converter<'_> {
    pub(super) fn material_block(&mut self, name: &str, edits: &[Item<SurfaceEdit>], at: &At) {
        let mut material = self.default_material();
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

    /// The definition an object's `Material NAME` copies: the latest one of that name,
    /// else the only one whose name matches ignoring case (the 2016 framework upper-cases
    /// lines), with a warning. An error when there is none, or several ignoring case.
    pub(super) fn lookup_material(&mut self, name: &str, at: &At) -> Option<usize> {
        if let Some(&index) = self.latest.get(name) {
            return Some(index);
        }
        let folded: Vec<(&String, usize)> = self
            .latest
            .iter()
            .filter(|(defined, _)| defined.eq_ignore_ascii_case(name))
            .map(|(defined, &index)| (defined, index))
            .collect();
        match folded.as_slice() {
            [(defined, index)] => {
                let (defined, index) = ((*defined).clone(), *index);
                self.warn(
                    at.line,
                    format!(
                        "material `{name}` is taken to be `{defined}` (names are matched \
                         ignoring case, as the 2016 framework upper-cases lines)"
                    ),
                );
                Some(index)
            }
            [] => {
                let first = self.first_definition.iter().find(|(defined, _)| {
                    defined.as_str() == name || defined.eq_ignore_ascii_case(name)
                });
                let message = match first {
                    Some((_, line)) => format!(
                        "material used before it is defined (its definition is at line {line})"
                    ),
                    None => "material used but never defined".to_owned(),
                };
                self.errors.push(LegacyError::new(at.line, name, message));
                None
            }
            several => {
                let mut names: Vec<String> =
                    several.iter().map(|(n, _)| format!("`{n}`")).collect();
                names.sort();
                self.errors.push(LegacyError::new(
                    at.line,
                    name,
                    format!(
                        "no material has this exact name, and several match it ignoring case: {}",
                        names.join(", ")
                    ),
                ));
                None
            }
        }
    }

    /// The default material of the file's dialect.
    pub(super) fn default_material(&self) -> Material {
        default_material(self.dialect.dialect)
    }
}

/// Applies one material keyword to a material.
pub(super) fn apply(material: &mut Material, edit: &SurfaceEdit) {
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
        // kt = 1 - a, grey; the local colour is not reduced (the readers' model).
        SurfaceEdit::Opacity(a) => material.transmission = DVec3::splat(1.0 - a),
        SurfaceEdit::RefractiveIndex(n) => material.ior = n,
    }
}

/// `wanted`, or `wanted 2`, `wanted 3`... whichever is free first; the name is then taken.
pub(super) fn unique(taken: &mut HashSet<String>, wanted: String) -> String {
    let mut name = wanted.clone();
    let mut n = 2;
    while taken.contains(&name) {
        name = format!("{wanted} {n}");
        n += 1;
    }
    taken.insert(name.clone());
    name
}
