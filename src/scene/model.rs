//! The scene data model: plain data that serialises to the RON contract of
//! `shared/SCENE_FORMAT.md`. Field names here are the file format; do not rename them.
//!
//! The model is `Clone + PartialEq` and uses names, not pointers, so the editor can
//! snapshot it for undo and send it to the preview worker as an immutable value.

use std::collections::BTreeMap;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::conventions::Conventions;
use super::light::Light;
use super::shape::Shape;
use super::transform::Transform;

/// The current (and only) version of the file format.
pub const FORMAT_VERSION: u32 = 1;

/// A whole scene: camera, render settings, materials, objects and lights.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// File format version; always 1.
    #[serde(default = "format_version")]
    pub format: u32,
    /// The pinhole camera and the output size.
    #[serde(default)]
    pub camera: Camera,
    /// Ray depth, background and anti-aliasing.
    #[serde(default)]
    pub render: RenderSettings,
    /// Materials by name; objects refer to them by name.
    #[serde(default)]
    pub materials: BTreeMap<String, Material>,
    /// The objects, each a unit shape placed by a transform.
    pub objects: Vec<Object>,
    /// The lights.
    #[serde(default)]
    pub lights: Vec<Light>,
}

fn format_version() -> u32 {
    FORMAT_VERSION
}

/// A pinhole camera. `fov_deg` is the vertical field of view.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    /// Eye position in world space.
    pub position: DVec3,
    /// The point the camera looks at; the image centre.
    pub look_at: DVec3,
    /// Which way is up; need not be perpendicular to the view direction.
    #[serde(default = "default_up")]
    pub up: DVec3,
    /// Vertical field of view in degrees.
    pub fov_deg: f64,
    /// Output width in pixels.
    pub width: u32,
    /// Output height in pixels.
    pub height: u32,
}

fn default_up() -> DVec3 {
    DVec3::Y
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            position: DVec3::new(0.0, 1.5, 6.0),
            look_at: DVec3::new(0.0, 0.5, 0.0),
            up: DVec3::Y,
            fov_deg: 45.0,
            width: 800,
            height: 600,
        }
    }
}

/// Global render settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSettings {
    /// Maximum number of mirror bounces, at most [`crate::scene::MAX_DEPTH`].
    #[serde(default = "default_max_depth")]
    pub max_depth: u32,
    /// Colour of rays that hit nothing.
    #[serde(default)]
    pub background: DVec3,
    /// Anti-aliasing target: stratified samples per pixel.
    #[serde(default = "default_samples_per_pixel")]
    pub samples_per_pixel: u32,
    /// The course framework's mirror, clamp and quantise habits; default the contract's.
    #[serde(default, skip_serializing_if = "Conventions::is_default")]
    pub conventions: Conventions,
}

fn default_max_depth() -> u32 {
    5
}

fn default_samples_per_pixel() -> u32 {
    16
}

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            max_depth: default_max_depth(),
            background: DVec3::ZERO,
            samples_per_pixel: default_samples_per_pixel(),
            conventions: Conventions::default(),
        }
    }
}

/// A Phong material. Every field defaults to zero (shininess to 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Reflectance for ambient lights (ka).
    #[serde(default)]
    pub ambient: DVec3,
    /// Lambertian reflectance (kd).
    #[serde(default)]
    pub diffuse: DVec3,
    /// Phong specular reflectance (ks).
    #[serde(default)]
    pub specular: DVec3,
    /// Phong exponent (s), any value >= 0; 0 makes the lobe 1 wherever r.v > 0.
    #[serde(default = "default_shininess")]
    pub shininess: f64,
    /// Mirror reflectance (km).
    #[serde(default)]
    pub mirror: DVec3,
    /// Transmittance (kt) of the refraction term; default 0 (opaque).
    #[serde(default, skip_serializing_if = "is_zero_colour")]
    pub transmission: DVec3,
    /// Index of refraction of the object's inside (the outside is 1); default 1.
    #[serde(default = "default_ior", skip_serializing_if = "is_unit_ior")]
    pub ior: f64,
}

impl Material {
    /// The grey plastic that new scenes and new objects start with.
    #[must_use]
    pub fn grey() -> Self {
        Self {
            ambient: DVec3::splat(0.1),
            diffuse: DVec3::splat(0.6),
            specular: DVec3::splat(0.3),
            shininess: 32.0,
            ..Self::default()
        }
    }
}

fn default_ior() -> f64 {
    1.0
}

fn is_unit_ior(ior: &f64) -> bool {
    *ior == 1.0
}

fn is_zero_colour(colour: &DVec3) -> bool {
    *colour == DVec3::ZERO
}

fn default_shininess() -> f64 {
    1.0
}

impl Default for Material {
    fn default() -> Self {
        Self {
            ambient: DVec3::ZERO,
            diffuse: DVec3::ZERO,
            specular: DVec3::ZERO,
            shininess: default_shininess(),
            mirror: DVec3::ZERO,
            transmission: DVec3::ZERO,
            ior: default_ior(),
        }
    }
}

/// One object: a shape (or a node of an object tree), its placement and its material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Object {
    /// Display name; when left out of a file it becomes "<shape> <index>".
    #[serde(default)]
    pub name: String,
    /// Which shape, or which tree node.
    pub shape: Shape,
    /// Placement: object-to-world, or object-to-parent inside a tree.
    #[serde(default)]
    pub transform: Transform,
    /// Name of an entry in `Scene::materials`; empty inside a tree means the parent's
    /// (a group's children and CSG operands may leave it out), and a group has none.
    #[serde(default)]
    pub material: String,
}

impl Scene {
    /// An empty scene with the default camera and settings.
    #[must_use]
    pub fn empty() -> Self {
        Self {
            format: FORMAT_VERSION,
            camera: Camera::default(),
            render: RenderSettings::default(),
            materials: BTreeMap::new(),
            objects: Vec::new(),
            lights: Vec::new(),
        }
    }

    /// Gives every unnamed object its default name, "<shape> <index>".
    /// Inside a tree each child is numbered among its siblings.
    pub fn fill_default_names(&mut self) {
        fill_default_names(&mut self.objects);
    }
}

fn fill_default_names(objects: &mut [Object]) {
    // A loop over a work list, not recursion: trees may be deep.
    let mut pending = vec![objects];
    while let Some(level) = pending.pop() {
        for (index, object) in level.iter_mut().enumerate() {
            if object.name.is_empty() {
                object.name = format!("{} {index}", object.shape.name());
            }
            if let Some(children) = object.shape.children_mut() {
                pending.push(children);
            }
        }
    }
}
