//! Typed legacy blocks to a [`Scene`]: materials resolved in file order, transforms
//! composed, lights and the camera converted, and the result checked against the scene
//! rules so an import always loads again.
//!
//! Naming: objects are "<Shape> <index>" (the scene format's default names, counting only
//! imported objects). An object that overrides its material gets a material of its own,
//! "<material> (<object>)". The default material is "default" (only added when used). A
//! material defined twice keeps its name for the last definition; objects before that
//! keep the earlier one as "<name> (line N)". Generated names never clash with names in
//! the file: a clash gets " 2", " 3"... appended.

use std::collections::{BTreeMap, HashMap, HashSet};

use glam::DVec3;

use super::camera::{camera_distortion, scene_camera};
use super::error::LegacyError;
use super::syntax::{
    At, Block, Item, LightKind, LightSetting, ObjectKind, ObjectSetting, ParsedBlock, SceneSetting,
    SurfaceEdit, TransformStep,
};
use super::transform::{compose, scene_transform};
use crate::scene::{Camera, Light, Material, Object, RenderSettings, Scene, Shape, Transform};
use crate::scene::{FORMAT_VERSION, validate};

/// Legacy default image size.
pub const DEFAULT_RENDER_SIZE: (u32, u32) = (800, 600);
/// Legacy default mirror depth.
pub const DEFAULT_RAY_DEPTH: u32 = 3;
/// Focal length of the unit camera used when a file has no Camera block.
pub const DEFAULT_FOCAL_LENGTH: f64 = 1.0;
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
    }
}

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

/// One Material block's result.
struct Definition {
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
struct PendingObject {
    shape: Shape,
    transform: Transform,
    base: Base,
    own: Option<Material>,
    at: At,
}

struct Converter<'e> {
    errors: &'e mut Vec<LegacyError>,
    warnings: Vec<String>,
    /// First line where each material name is defined, for "used before" messages.
    first_definition: HashMap<String, usize>,
    render_size: (u32, u32),
    background: DVec3,
    ambient_light: Option<DVec3>,
    ray_depth: u32,
    camera: Option<(f64, glam::DAffine3, At)>,
    definitions: Vec<Definition>,
    latest: HashMap<String, usize>,
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
            } => {
                if let Some((_, _, previous)) = &self.camera {
                    let line = previous.line;
                    self.warn(
                        parsed.at.line,
                        format!("this Camera replaces the one at line {line}"),
                    );
                }
                let world_from_camera = compose(transforms.iter().map(|t| &t.value));
                self.camera = Some((*focal_length, world_from_camera, parsed.at.clone()));
            }
            Block::Light {
                kind,
                settings,
                broken,
            } => self.light_block(*kind, settings, broken, &parsed.at),
            Block::Material { name, edits } => self.material_block(name, edits, &parsed.at),
            Block::Object { kind, settings } => self.object_block(*kind, settings, &parsed.at),
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
                SceneSetting::RayDepth(depth) => self.ray_depth = *depth,
                // The legacy output file name; raylab names images when it renders.
                SceneSetting::Filename(_) => {}
            }
        }
    }

    /// A light; the `broken` keywords are missing because they were wrong, and their
    /// absence is not reported again.
    fn light_block(
        &mut self,
        kind: LightKind,
        settings: &[Item<LightSetting>],
        broken: &[String],
        at: &At,
    ) {
        let (mut colour, mut location, mut direction, mut angle) = (None, None, None, None);
        for setting in settings {
            let used = match setting.value {
                LightSetting::Colour(c) => {
                    colour = Some(c);
                    true
                }
                LightSetting::Location(p) => {
                    location = Some(p);
                    matches!(kind, LightKind::Point | LightKind::Spot)
                }
                LightSetting::Direction(d) => {
                    direction = Some(d);
                    matches!(kind, LightKind::Directional | LightKind::Spot)
                }
                LightSetting::Angle(a) => {
                    angle = Some(a);
                    kind == LightKind::Spot
                }
            };
            if !used {
                self.warn(
                    setting.at.line,
                    format!(
                        "`{}` has no effect on a {}; ignored",
                        setting.at.token, at.token
                    ),
                );
            }
        }
        let colour = self.need(colour, "Colour", broken, at);
        let light = match kind {
            LightKind::Ambient => colour.map(|colour| Light::Ambient {
                colour,
                intensity: 1.0,
            }),
            LightKind::Point => {
                let position = self.need(location, "Location", broken, at);
                colour.zip(position).map(|(colour, position)| Light::Point {
                    position,
                    colour,
                    intensity: 1.0,
                })
            }
            LightKind::Directional => {
                let direction = self.need(direction, "Direction", broken, at);
                colour
                    .zip(direction)
                    .map(|(colour, direction)| Light::Directional {
                        direction,
                        colour,
                        intensity: 1.0,
                    })
            }
            LightKind::Spot => {
                let position = self.need(location, "Location", broken, at);
                let direction = self.need(direction, "Direction", broken, at);
                let angle_deg = self.need(angle, "Angle", broken, at);
                match (colour, position, direction, angle_deg) {
                    (Some(colour), Some(position), Some(direction), Some(angle_deg)) => {
                        Some(Light::Spot {
                            position,
                            direction,
                            angle_deg,
                            colour,
                            intensity: 1.0,
                        })
                    }
                    _ => None,
                }
            }
        };
        if let Some(light) = light {
            self.lights.push((light, at.clone()));
        }
    }

    /// `value`, or an error at the light's kind saying it needs `keyword` (unless the
    /// keyword is there but `broken`, which was reported already).
    fn need<T>(
        &mut self,
        value: Option<T>,
        keyword: &str,
        broken: &[String],
        at: &At,
    ) -> Option<T> {
        if value.is_none() && !broken.iter().any(|b| b == keyword) {
            let what = match keyword {
                "Angle" => "an `Angle` (its half-angle in degrees)".to_owned(),
                _ => format!("a `{keyword}`"),
            };
            self.errors.push(LegacyError::new(
                at.line,
                &at.token,
                format!("a {} needs {what}", at.token),
            ));
        }
        value
    }

    fn material_block(&mut self, name: &str, edits: &[Item<SurfaceEdit>], at: &At) {
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

    fn object_block(&mut self, kind: ObjectKind, settings: &[Item<ObjectSetting>], at: &At) {
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
        let shape = match kind {
            ObjectKind::Shape(shape) => shape,
            ObjectKind::Octahedron => {
                self.warn(
                    at.line,
                    "Octahedron: the legacy renderer parses octahedra but never draws them; skipped",
                );
                return;
            }
        };
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

    fn finish(mut self) -> Converted {
        let camera = self.camera();
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

        let mut lights = Vec::new();
        if let Some(colour) = self.ambient_light {
            lights.push(Light::Ambient {
                colour,
                intensity: 1.0,
            });
        }
        for (light, at) in std::mem::take(&mut self.lights) {
            let fragment = Scene {
                lights: vec![light.clone()],
                ..Scene::empty()
            };
            self.check(&fragment, &at, "this light cannot be imported");
            lights.push(light);
        }

        let scene = Scene {
            format: FORMAT_VERSION,
            camera,
            render: RenderSettings {
                max_depth: self.ray_depth,
                background: self.background,
                samples_per_pixel: 1,
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

    /// The scene camera, with a warning for what a pinhole camera cannot reproduce.
    fn camera(&mut self) -> Camera {
        let (width, height) = self.render_size;
        let Some((focal_length, world_from_camera, at)) = self.camera.clone() else {
            self.warnings.push(
                "no Camera block: the legacy unit camera is used (at the origin, looking \
                 along +Z, focal length 1)"
                    .to_owned(),
            );
            return scene_camera(
                DEFAULT_FOCAL_LENGTH,
                &glam::DAffine3::IDENTITY,
                width,
                height,
            );
        };
        if camera_distortion(&world_from_camera) {
            self.warn(
                at.line,
                "the camera's transform scales unevenly, shears or mirrors; the import keeps \
                 its position, view direction and up, so the picture may differ",
            );
        }
        let camera = scene_camera(focal_length, &world_from_camera, width, height);
        let fragment = Scene {
            camera: camera.clone(),
            ..Scene::empty()
        };
        self.check(&fragment, &at, "this camera cannot be imported");
        camera
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
