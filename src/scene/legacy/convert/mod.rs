//! Typed legacy blocks to a [`Scene`]: materials resolved in file order, transforms
//! composed, lights and the camera converted, and the result checked against the scene
//! rules so an import always loads again.
//!
//! This file is the whole-file driver: it reads the dialect off the blocks, walks them in
//! file order, keeps the Scene block's settings and assembles the scene at the end, with
//! the course's conventions (`Conventions::COURSE`). Each concern has its own file:
//! `dialect` (2016 or 2020 framework), `materials` (material blocks and lookups),
//! `objects` (objects and trees), `naming` (names of objects and materials), `lights`,
//! `camera`, and `transform` (composing transform steps into a scene transform).

mod camera;
mod dialect;
mod lights;
mod materials;
mod naming;
mod objects;
mod transform;

use std::collections::HashMap;
use std::path::PathBuf;

use glam::{DAffine3, DVec3};

use super::error::{Diagnostics, LegacyError};
use super::syntax::{At, Block, Item, ParsedBlock, SceneSetting};
use crate::scene::{
    Conventions, FORMAT_VERSION, Light, MAX_DEPTH, MAX_IMAGE_SIDE, RenderSettings, Scene, validate,
};
pub use dialect::{Detected, Dialect};
use materials::Definition;
pub(super) use objects::LEGACY_TORUS_MINOR;
use objects::PendingObject;
pub(super) use transform::as_trs;

/// Legacy default image size.
pub const DEFAULT_RENDER_SIZE: (u32, u32) = (800, 600);
/// Legacy default mirror depth.
pub const DEFAULT_RAY_DEPTH: u32 = 3;

/// A converted scene and the dialect it was read in.
#[derive(Clone, Debug, PartialEq)]
pub struct Converted {
    /// The scene; meaningful only when no errors were pushed.
    pub scene: Scene,
    /// The dialect read, and why.
    pub dialect: Detected,
}

/// Converts parsed blocks, pushing every semantic error and warning. `folder` is the
/// scene file's folder, where `Mesh` files are looked for (none for text alone).
pub fn convert(
    blocks: &[ParsedBlock],
    folder: Option<PathBuf>,
    errors: &mut Diagnostics,
) -> Converted {
    let dialect = dialect::detect(blocks);
    if dialect.dialect == Dialect::Framework2020
        && let Some((line, what)) = dialect.signs_2016.first()
    {
        errors.warn(
            *line,
            format!(
                "{what} belongs to the 2016 framework, but the file also has {} (line {}): \
                 read as the 2020 framework's dialect (magenta default material)",
                dialect.signs_2020[0].1, dialect.signs_2020[0].0
            ),
        );
    }
    let mut converter = Converter::new(blocks, dialect, folder, errors);
    for block in blocks {
        converter.block(block);
    }
    converter.finish()
}

/// What the blocks read so far add up to.
struct Converter<'e> {
    errors: &'e mut Diagnostics,
    /// The dialect read, and why.
    dialect: Detected,
    /// Where `Mesh` files are looked for.
    folder: Option<PathBuf>,
    samples_per_pixel: u32,
    /// First line where each material name is defined, for "used before" messages.
    first_definition: HashMap<String, usize>,
    render_size: (u32, u32),
    background: DVec3,
    ambient_light: Option<DVec3>,
    ray_depth: u32,
    /// The last Camera block: focal length, placement and where it was.
    camera: Option<(f64, DAffine3, At)>,
    /// Every Material block, in file order.
    definitions: Vec<Definition>,
    /// The latest definition of each material name, as an index into `definitions`.
    latest: HashMap<String, usize>,
    /// Whether some object uses the default material unchanged.
    default_used: bool,
    objects: Vec<PendingObject>,
    lights: Vec<(Light, At)>,
}

impl<'e> Converter<'e> {
    fn new(
        blocks: &[ParsedBlock],
        dialect: Detected,
        folder: Option<PathBuf>,
        errors: &'e mut Diagnostics,
    ) -> Self {
        let mut first_definition = HashMap::new();
        for block in blocks {
            if let Block::Material { name, .. } = &block.block {
                first_definition
                    .entry(name.clone())
                    .or_insert(block.at.line);
            }
        }
        Self {
            errors,
            dialect,
            folder,
            samples_per_pixel: 1,
            first_definition,
            render_size: DEFAULT_RENDER_SIZE,
            background: DVec3::ZERO,
            ambient_light: None,
            ray_depth: DEFAULT_RAY_DEPTH,
            camera: None,
            definitions: Vec::new(),
            latest: HashMap::new(),
            default_used: false,
            objects: Vec::new(),
            lights: Vec::new(),
        }
    }

    fn warn(&mut self, line: usize, message: impl Into<String>) {
        self.errors.warn(line, message);
    }

    fn block(&mut self, parsed: &ParsedBlock) {
        match &parsed.block {
            Block::Scene(settings) => self.scene_block(settings),
            Block::Camera {
                focal_length,
                transforms,
            } => self.camera_block(*focal_length, transforms, &parsed.at),
            Block::Light {
                kind,
                settings,
                broken,
            } => self.light_block(*kind, settings, broken, &parsed.at),
            Block::Material { name, edits } => self.material_block(name, edits, &parsed.at),
            Block::Object(node) => self.object_block(node),
        }
    }

    fn scene_block(&mut self, settings: &[Item<SceneSetting>]) {
        for setting in settings {
            match &setting.value {
                SceneSetting::RenderSize { width, height } => {
                    self.render_size = (*width, *height);
                }
                SceneSetting::Background(colour) => self.background = *colour,
                SceneSetting::AmbientLight(colour) => self.ambient_light = Some(*colour),
                SceneSetting::RayDepth(depth) => {
                    self.ray_depth = self.capped_depth(*depth, &setting.at)
                }
                // The legacy output file name; raylab names images when it renders.
                SceneSetting::Filename(_) => {}
                SceneSetting::SamplesPerPixel(samples) => self.samples_per_pixel = *samples,
                SceneSetting::ScaleResolution(scale) => self.scale_resolution(*scale, &setting.at),
            }
        }
    }

    /// A `rayDepth` as raylab renders it: beyond [`MAX_DEPTH`] it is capped, with a
    /// warning (only a ray that bounces that often renders differently).
    fn capped_depth(&mut self, depth: f64, at: &At) -> u32 {
        if depth <= f64::from(MAX_DEPTH) {
            // Whole (the parser checked) and in range, so the conversion is exact.
            return depth as u32;
        }
        self.warn(
            at.line,
            format!(
                "rayDepth {depth}: raylab follows at most {MAX_DEPTH} mirror bounces, so \
                 it imports {MAX_DEPTH}; only a ray that bounces more often than that \
                 renders differently"
            ),
        );
        MAX_DEPTH
    }

    /// `scaleResolution s`: the size so far times s, truncated (a later `renderSize`
    /// replaces it); kept within 1 ..= [`MAX_IMAGE_SIDE`], with a warning.
    fn scale_resolution(&mut self, scale: f64, at: &At) {
        let side = |side: u32| (f64::from(side) * scale).trunc();
        let (width, height) = (side(self.render_size.0), side(self.render_size.1));
        let limit = f64::from(MAX_IMAGE_SIDE);
        if width < 1.0 || height < 1.0 || width > limit || height > limit {
            self.warn(
                at.line,
                format!(
                    "scaleResolution {scale} makes the image {width} x {height}; each side is \
                     kept within 1 to {MAX_IMAGE_SIDE} pixels"
                ),
            );
        }
        // Clamped to the accepted range, so the conversion is exact.
        let fit = |side: f64| side.clamp(1.0, limit) as u32;
        self.render_size = (fit(width), fit(height));
    }

    fn finish(mut self) -> Converted {
        let camera = self.camera();
        let (materials, objects) = self.materials_and_objects();
        let lights = self.scene_lights();
        let scene = Scene {
            format: FORMAT_VERSION,
            camera,
            render: RenderSettings {
                max_depth: self.ray_depth,
                background: self.background,
                samples_per_pixel: self.samples_per_pixel,
                conventions: Conventions::COURSE,
            },
            materials,
            objects,
            lights,
        };
        Converted {
            scene,
            dialect: self.dialect,
        }
    }

    /// Runs the scene rules on a one-item scene and reports a failure at `at`.
    fn check(&mut self, fragment: &Scene, at: &At, what: &str) {
        if let Err(error) = validate(fragment) {
            self.errors.push(LegacyError::new(
                at.line,
                &at.token,
                format!("{what}: {error}"),
            ));
        }
    }
}
