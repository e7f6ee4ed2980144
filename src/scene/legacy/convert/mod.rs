//! Typed legacy blocks to a [`Scene`]: materials resolved in file order, transforms
//! composed, lights and the camera converted, and the result checked against the scene
//! rules so an import always loads again.
//!
//! This file is the whole-file driver: it walks the blocks in file order, keeps the Scene
//! block's settings and assembles the scene at the end. Each concern has its own file:
//! `materials` (material blocks, objects and the names of their materials), `lights`,
//! `camera`, and `transform` (composing transform steps into a scene transform).

mod camera;
mod lights;
mod materials;
mod transform;

use std::collections::HashMap;

use glam::{DAffine3, DVec3};

use super::error::LegacyError;
use super::syntax::{At, Block, Item, ParsedBlock, SceneSetting};
use crate::scene::{FORMAT_VERSION, Light, MAX_DEPTH, RenderSettings, Scene, validate};
use materials::{Definition, PendingObject};

/// Legacy default image size.
pub const DEFAULT_RENDER_SIZE: (u32, u32) = (800, 600);
/// Legacy default mirror depth.
pub const DEFAULT_RAY_DEPTH: u32 = 3;

/// A converted scene and the warnings met on the way ("line N: ...").
#[derive(Clone, Debug, PartialEq)]
pub struct Converted {
    /// The scene; meaningful only when no errors were pushed.
    pub scene: Scene,
    /// Things imported with a caveat, or skipped.
    pub warnings: Vec<String>,
}

/// Converts parsed blocks, pushing every semantic error.
pub fn convert(blocks: &[ParsedBlock], errors: &mut Vec<LegacyError>) -> Converted {
    let mut converter = Converter::new(blocks, errors);
    for block in blocks {
        converter.block(block);
    }
    converter.finish()
}

/// What the blocks read so far add up to.
struct Converter<'e> {
    errors: &'e mut Vec<LegacyError>,
    warnings: Vec<String>,
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
    fn new(blocks: &[ParsedBlock], errors: &'e mut Vec<LegacyError>) -> Self {
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
            warnings: Vec::new(),
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

    fn warn(&mut self, line: usize, message: impl AsRef<str>) {
        self.warnings
            .push(format!("line {line}: {}", message.as_ref()));
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
            Block::Object { kind, settings } => {
                self.object_block(kind.clone(), settings, &parsed.at)
            }
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
                samples_per_pixel: 1,
                conventions: Default::default(),
            },
            materials,
            objects,
            lights,
        };
        Converted {
            scene,
            warnings: self.warnings,
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
