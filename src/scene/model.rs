//! The scene data model: plain data that serialises to the RON contract of
//! `shared/SCENE_FORMAT.md`. Field names here are the file format; do not rename them.
//!
//! The model is `Clone + PartialEq` and uses names, not pointers, so the editor can
//! snapshot it for undo and send it to the preview worker as an immutable value.

use std::collections::BTreeMap;

use glam::DVec3;
use serde::{Deserialize, Serialize};

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
        }
    }
}

/// The five unit shapes, in object space (see the table in SCENE_FORMAT.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Shape {
    /// Centre at the origin, radius 1.
    Sphere,
    /// The two-sided square z = 0, -1 <= x, y <= 1.
    Plane,
    /// The cube [-1, 1]^3.
    Cube,
    /// x^2 + y^2 = 1 for -1 <= z <= 1, closed by disc caps.
    Cylinder,
    /// x^2 + y^2 = z^2 for 0 <= z <= 1, apex at the origin, capped at z = 1.
    Cone,
}

impl Shape {
    /// Every shape, in menu order.
    pub const ALL: [Shape; 5] = [
        Shape::Sphere,
        Shape::Plane,
        Shape::Cube,
        Shape::Cylinder,
        Shape::Cone,
    ];

    /// The name used in files and menus.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Shape::Sphere => "Sphere",
            Shape::Plane => "Plane",
            Shape::Cube => "Cube",
            Shape::Cylinder => "Cylinder",
            Shape::Cone => "Cone",
        }
    }
}

/// One object: a unit shape, its placement and its material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Object {
    /// Display name; when left out of a file it becomes "<shape> <index>".
    #[serde(default)]
    pub name: String,
    /// Which unit shape.
    pub shape: Shape,
    /// Object-to-world placement.
    #[serde(default)]
    pub transform: Transform,
    /// Name of an entry in `Scene::materials`.
    pub material: String,
}

/// A light. Strength is `colour * intensity`; point and spot lights fall off as 1/d^2.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Light {
    /// Adds `ka * colour * intensity` everywhere.
    Ambient {
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    /// A point light.
    Point {
        /// World position.
        position: DVec3,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    /// A light at infinity; `direction` is the way the light travels.
    Directional {
        /// The way the light travels (need not be unit length).
        direction: DVec3,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    /// A point light restricted to a cone with a hard edge.
    Spot {
        /// World position of the apex.
        position: DVec3,
        /// Axis of the cone: the way the light travels.
        direction: DVec3,
        /// Half-angle of the cone in degrees, in (0, 180]: 90 lights a half-space, 180
        /// every direction.
        angle_deg: f64,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
}

fn default_intensity() -> f64 {
    1.0
}

/// The four kinds of light, without their values: for menus, messages and importers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightKind {
    /// [`Light::Ambient`].
    Ambient,
    /// [`Light::Point`].
    Point,
    /// [`Light::Directional`].
    Directional,
    /// [`Light::Spot`].
    Spot,
}

impl LightKind {
    /// Every kind, in menu order.
    pub const ALL: [LightKind; 4] = [
        LightKind::Ambient,
        LightKind::Point,
        LightKind::Directional,
        LightKind::Spot,
    ];

    /// The kind's name, as in files: the variant name of [`Light`].
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LightKind::Ambient => "Ambient",
            LightKind::Point => "Point",
            LightKind::Directional => "Directional",
            LightKind::Spot => "Spot",
        }
    }
}

impl Light {
    /// Which kind of light this is.
    #[must_use]
    pub fn kind(&self) -> LightKind {
        match self {
            Light::Ambient { .. } => LightKind::Ambient,
            Light::Point { .. } => LightKind::Point,
            Light::Directional { .. } => LightKind::Directional,
            Light::Spot { .. } => LightKind::Spot,
        }
    }

    /// The kind's name, as in files and menus.
    #[must_use]
    pub fn kind_name(&self) -> &'static str {
        self.kind().name()
    }

    /// The light's colour, before `intensity`.
    #[must_use]
    pub fn colour(&self) -> DVec3 {
        match *self {
            Light::Ambient { colour, .. }
            | Light::Point { colour, .. }
            | Light::Directional { colour, .. }
            | Light::Spot { colour, .. } => colour,
        }
    }

    /// The multiplier of the light's colour.
    #[must_use]
    pub fn intensity(&self) -> f64 {
        match *self {
            Light::Ambient { intensity, .. }
            | Light::Point { intensity, .. }
            | Light::Directional { intensity, .. }
            | Light::Spot { intensity, .. } => intensity,
        }
    }

    /// The light's colour times its intensity.
    #[must_use]
    pub fn strength(&self) -> DVec3 {
        self.colour() * self.intensity()
    }
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
    pub fn fill_default_names(&mut self) {
        for (index, object) in self.objects.iter_mut().enumerate() {
            if object.name.is_empty() {
                object.name = format!("{} {index}", object.shape.name());
            }
        }
    }
}
