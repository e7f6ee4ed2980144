//! The legacy file as typed blocks: what the parser produces and the converter reads.
//! Every item keeps the line and token it came from, for error messages.

use glam::DVec3;

use crate::scene::{LightKind, Shape};

/// Where an item came from: the 1-based line and the token that names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct At {
    /// 1-based line.
    pub line: usize,
    /// The token, as written.
    pub token: String,
}

/// A value and where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Item<T> {
    /// The parsed value.
    pub value: T,
    /// The keyword that introduced it.
    pub at: At,
}

/// A coordinate axis of `Rotate`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// Rotate about X.
    X,
    /// Rotate about Y.
    Y,
    /// Rotate about Z.
    Z,
}

/// One transform keyword; a sequence of them is applied in file order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransformStep {
    /// `Translate x y z`.
    Translate(DVec3),
    /// `Rotate X|Y|Z deg`.
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle in degrees (counter-clockwise looking down the axis).
        angle_deg: f64,
    },
    /// `Scale s`: uniform.
    Scale(f64),
    /// `Scale3 sx sy sz`.
    Scale3(DVec3),
}

/// One material keyword, in a Material block or overriding an object's copy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceEdit {
    /// `Colour R G B`: sets ambient and diffuse.
    Colour(DVec3),
    /// `Ambient R G B`.
    Ambient(DVec3),
    /// `Diffuse R G B`.
    Diffuse(DVec3),
    /// `Specular R G B EXP`.
    Specular {
        /// Specular colour.
        colour: DVec3,
        /// Phong exponent.
        exponent: f64,
    },
    /// `Mirror R G B`.
    Mirror(DVec3),
}

/// One keyword of the Scene block.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSetting {
    /// `renderSize W H`.
    RenderSize {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// `backgroundColour R G B`.
    Background(DVec3),
    /// `ambientLight R G B` (older files).
    AmbientLight(DVec3),
    /// `rayDepth N`: a whole number >= 0 as written, which may exceed what raylab renders.
    RayDepth(f64),
    /// `filename NAME`: the legacy output image; not used by the import.
    Filename(String),
}

/// One keyword of a Light block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightSetting {
    /// `Colour R G B`.
    Colour(DVec3),
    /// `Location x y z`.
    Location(DVec3),
    /// `Direction x y z`.
    Direction(DVec3),
    /// `Angle deg`.
    Angle(f64),
}

/// What an Object block draws.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectKind {
    /// One of the unit shapes the project draws (`Shape::ALL`).
    Shape(Shape),
}

/// One keyword of an Object block.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectSetting {
    /// `Material NAME`: copy a material defined earlier.
    Material(String),
    /// An override of the object's copy of its material.
    Surface(SurfaceEdit),
    /// A transform step.
    Transform(TransformStep),
}

/// A block's contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Block {
    /// `Scene ... End`.
    Scene(Vec<Item<SceneSetting>>),
    /// `Camera PinholeCamera F ... End`.
    Camera {
        /// Distance of the 2-unit-wide image plane.
        focal_length: f64,
        /// The camera's placement, in file order.
        transforms: Vec<Item<TransformStep>>,
    },
    /// `Light KIND ... End`.
    Light {
        /// Which kind.
        kind: LightKind,
        /// Its keywords, in file order.
        settings: Vec<Item<LightSetting>>,
        /// Keywords that had an error and so are missing from `settings`, as written;
        /// their absence is not reported a second time.
        broken: Vec<String>,
    },
    /// `Material NAME ... End`.
    Material {
        /// The name (case-sensitive).
        name: String,
        /// Its keywords, in file order.
        edits: Vec<Item<SurfaceEdit>>,
    },
    /// `Object SHAPE ... End`.
    Object {
        /// What it draws.
        kind: ObjectKind,
        /// Its keywords, in file order.
        settings: Vec<Item<ObjectSetting>>,
    },
}

/// A parsed block and the token that names it (`Scene`, the camera type, the light
/// kind, the material name or the shape).
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedBlock {
    /// The contents.
    pub block: Block,
    /// The naming token.
    pub at: At,
}
