//! The converter: what the blocks read so far add up to, each block handed to its concern,
//! the Scene block's settings kept, and the scene assembled at the end.

use std::collections::HashMap;
use std::path::PathBuf;

use glam::{DAffine3, DVec3};

use super::super::error::{Diagnostics, LegacyError};
use super::super::syntax::{At, Block, Item, ParsedBlock, SceneSetting};
use super::dialect::Detected;
use super::pending::{Definition, PendingObject};
use crate::scene::{
    Conventions, FORMAT_VERSION, Light, MAX_DEPTH, MAX_IMAGE_SIDE, RenderSettings, Scene, validate,
};

/// Legacy default image size.
const DEFAULT_RENDER_SIZE: (u32, u32) = (800, 600);
/// Legacy default mirror depth.
const DEFAULT_RAY_DEPTH: u32 = 3;

/// A converted scene and the dialect it was read in.
#[derive(Clone, Debug, PartialEq)]
pub struct Converted {
    /// The scene; meaningful only when no errors were pushed.
    pub scene: Scene,
    /// The dialect read, and why.
    pub dialect: Detected,
}

/// What the blocks read so far add up to.
pub(super) struct Converter<'e> {
    pub(super) errors: &'e mut Diagnostics,
    /// The dialect read, and why.
    pub(super) dialect: Detected,
    /// Where `Mesh` files are looked for.
    pub(super) folder: Option<PathBuf>,
    pub(super) samples_per_pixel: u32,
    /// First line where each material name is defined, for "used before" messages.
    pub(super) first_definition: HashMap<String, usize>,
    pub(super) render_size: (u32, u32),
    pub(super) background: DVec3,
    pub(super) ambient_light: Option<DVec3>,
    pub(super) ray_depth: u32,
    /// The last Camera block: focal length, placement and where it was.
    pub(super) camera: Option<(f64, DAffine3, At)>,
    /// Every Material block, in file order.
    pub(super) definitions: Vec<Definition>,
    /// The latest definition of each material name, as an index into `definitions`.
    pub(super) latest: HashMap<String, usize>,
    /// Whether some object uses the default material unchanged.
    pub(super) default_used: bool,
    pub(super) objects: Vec<PendingObject>,
    pub(super) lights: Vec<(Light, At)>,
}

impl<'e> Converter<'e> {
    pub(super) fn new(
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

    pub(super) fn warn(&mut self, line: usize, message: impl Into<String>) {
        self.errors.warn(line, message);
    }

    pub(super) fn block(&mut self, parsed: &ParsedBlock) {
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

    pub(super) fn finish(mut self) -> Converted {
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
    pub(super) fn check(&mut self, fragment: &Scene, at: &At, what: &str) {
        if let Err(error) = validate(fragment) {
            self.errors.push(LegacyError::new(
                at.line,
                &at.token,
                format!("{what}: {error}"),
            ));
        }
    }
}
