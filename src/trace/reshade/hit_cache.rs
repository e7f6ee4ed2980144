//! The hit cache: every ray the one-sample full-resolution pass traced, kept so that an
//! edit that moves nothing can be re-shaded instead of re-traced ([`crate::trace::render::cached`]).
//!
//! Per pixel it keeps the mirror chain of the pixel-centre sample, one entry per depth
//! traced (the closest hit, or the miss that ends the chain), and per entry and light
//! what that light's shadow ray met: clear, a blocker, or "not cast" (the shader did not
//! need it, e.g. the light was behind the surface or the material had no diffuse and no
//! specular); for a sphere light, how many of its rays reached it. Which rays a pixel needs depends on the materials, the switches and the
//! view; what each traced ray found depends only on the geometry (objects, camera, size)
//! and, for shadow rays, on where the light is. So:
//!
//! - the geometry changed: nothing cached is valid, re-trace ([`Reuse::Retrace`]);
//! - otherwise every cached hit is what the ray would find again, and every cached
//!   shadow answer too for each light whose shadow target (position, or direction for a
//!   directional light) is bit for bit the same; the other lights' shadow rays are cast
//!   again, and so is every ray the new scene needs that the cache lacks (a mirror made
//!   shiny, a deeper `max_depth`, a light in front of a surface that was behind it).

use std::sync::Arc;

use glam::{DAffine3, DVec3};

use super::chains::{CachedHit, Chains};
use super::dependence::TermDependence;
use super::keep_rule::{KeepRule, TileSummary};
use super::light_factors;
use super::light_factors::LightSlot;
use super::pixel_colour::PixelColour;
use crate::scene::{Camera, Material};
use crate::trace::film::RenderOptions;
use crate::trace::shapes::Primitive;
use crate::trace::terms::{TermSwitches, View};
use crate::trace::world::{CsgTree, SphereLight, World, WorldLight};

/// The most memory the preview's cache may take, as [`cache_fits`] estimates it: larger
/// previews re-trace every edit.
pub const MAX_CACHE_BYTES: usize = 512 << 20;

/// Whether the cache of `world` rendered at `width` x `height` stays under
/// [`MAX_CACHE_BYTES`], for two rays a pixel (the default scene has 1.6: some 160 MB at
/// 800 x 600 with its three lights, each ray 92 bytes and 32 more per light).
#[must_use]
pub fn cache_fits(world: &World, width: u32, height: u32) -> bool {
    let per_ray =
        size_of::<CachedHit>() + size_of::<u32>() + world.lights.len() * size_of::<LightSlot>();
    let per_pixel = 2 * per_ray + size_of::<PixelColour>() + size_of::<u32>();
    (width as usize)
        .saturating_mul(height as usize)
        .saturating_mul(per_pixel)
        <= MAX_CACHE_BYTES
}

/// Whether the cache can hold the rays of `world`: a chain of rays per pixel, and per
/// light at each hit a shadow answer (a sphere light's as the count of its rays that
/// reach it). A transmissive material makes trees (a mirror and a transmitted ray from
/// one hit); the preview traces such worlds afresh on every edit instead.
#[must_use]
pub fn cache_serves(world: &World) -> bool {
    world
        .materials
        .iter()
        .all(|material| material.transmission == DVec3::ZERO)
}

/// The cached rays of one tile. The chains and light slots are shared with the cache
/// before when an edit left them as they were (most edits add no ray), so a re-shade
/// copies nothing.
#[derive(Clone, Debug)]
pub(crate) struct TileHits {
    /// The pixels' mirror chains.
    pub chains: Arc<Chains>,
    /// Per entry of `chains.hits`, one slot per light of the cache: its shadow ray's
    /// answer (`NOT_CAST`, `CLEAR` or the blocker's world index) and what it gave the hit.
    pub slots: Arc<Vec<LightSlot>>,
    /// Each pixel's colour, row-major within the tile.
    pub colours: Arc<Vec<PixelColour>>,
    /// What its pixels depend on, all together: a whole tile kept in one test.
    pub summary: TileSummary,
}

/// Everything the shader reads besides the rays and the objects' materials: with all of
/// it unchanged, a pixel whose rays meet no object with a changed material keeps its
/// colour.
#[derive(Clone, Debug, PartialEq)]
struct Shading {
    switches: TermSwitches,
    view: View,
    lights: Vec<WorldLight>,
    /// Each light's sphere, if it has one (its size and ray count set its shadows).
    light_spheres: Vec<Option<SphereLight>>,
    ambient: DVec3,
    background: DVec3,
    max_depth: u32,
    /// How colours combine and clamp: a change shades every pixel again (from the
    /// cache's rays, none traced).
    conventions: crate::scene::Conventions,
}

impl Shading {
    fn of(world: &World, options: &RenderOptions) -> Self {
        Self {
            switches: options.switches,
            view: options.view,
            lights: world.lights.clone(),
            light_spheres: world.light_spheres.clone(),
            ambient: world.ambient,
            background: world.background,
            max_depth: world.max_depth,
            conventions: world.conventions,
        }
    }
}

/// Whether a CSG object's operands have more than one material between them.
fn mixes_materials(object: &crate::trace::WorldObject) -> bool {
    object.csg.as_ref().is_some_and(|tree| {
        tree.leaves
            .iter()
            .any(|leaf| leaf.material != object.material)
    })
}

/// Each object's material, by world object index.
fn object_materials(world: &World) -> Vec<Material> {
    world
        .objects
        .iter()
        .map(|o| world.materials[o.material].clone())
        .collect()
}

/// What a traced ray's answer depends on besides the light: the image size, the camera
/// and every object's shape and placement.
#[derive(Clone, Debug, PartialEq)]
struct RayGeometry {
    width: u32,
    height: u32,
    camera: Camera,
    /// Each object's shape, placement and (for a mesh) which triangles.
    objects: Vec<(Primitive, DAffine3, Option<u64>)>,
    /// The CSG trees, compared by value: a node's operands are its shape.
    trees: Vec<Option<Arc<CsgTree>>>,
    object_scene_index: Vec<usize>,
}

impl RayGeometry {
    fn of(world: &World, width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            camera: world.camera.clone(),
            objects: world
                .objects
                .iter()
                .map(|o| {
                    (
                        o.shape,
                        o.world_from_object,
                        o.mesh.as_ref().map(|m| m.id()),
                    )
                })
                .collect(),
            trees: world.objects.iter().map(|o| o.csg.clone()).collect(),
            object_scene_index: world.object_scene_index.clone(),
        }
    }
}

/// What a light's shadow rays depend on: where they go (bit for bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ShadowTarget {
    /// To a point (point and spot lights).
    Position([u64; 3]),
    /// To a sphere (point and spot lights with a radius): its centre, its radius and
    /// how many rays aim at it.
    Sphere([u64; 3], u64, u32),
    /// Towards a light at infinity.
    Direction([u64; 3]),
}

impl ShadowTarget {
    fn of(light: &WorldLight, sphere: Option<SphereLight>) -> Self {
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        match (*light, sphere) {
            (WorldLight::Point { position, .. } | WorldLight::Spot { position, .. }, None) => {
                Self::Position(bits(position))
            }
            (
                WorldLight::Point { position, .. } | WorldLight::Spot { position, .. },
                Some(sphere),
            ) => Self::Sphere(bits(position), sphere.radius.to_bits(), sphere.samples),
            (WorldLight::Directional { to_light, .. }, _) => Self::Direction(bits(to_light)),
        }
    }

    /// Per light of `world`, its target.
    fn all(world: &World) -> Vec<Self> {
        (world.lights.iter().zip(&world.light_spheres))
            .map(|(light, sphere)| Self::of(light, *sphere))
            .collect()
    }
}

/// Why a cache cannot serve a world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RetraceReason {
    /// Another image size.
    Size,
    /// The camera moved or changed its lens.
    Camera,
    /// An object was added, removed, hidden, shown, moved or given another shape.
    Objects,
}

/// Whether a cache can serve a world, and how.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reuse {
    /// Every cached ray is stale: trace again from scratch.
    Retrace(RetraceReason),
    /// Re-shade from the cache.
    Reshade {
        /// Per light of the new world, the cache's column of shadow answers that stays
        /// valid; `None` where that light's shadow rays must be cast again.
        kept_columns: Vec<Option<usize>>,
    },
}

impl Reuse {
    /// Whether this re-shades.
    #[must_use]
    pub fn is_reshade(&self) -> bool {
        matches!(self, Reuse::Reshade { .. })
    }

    /// The world light indices whose shadow rays are cast again (empty for a re-trace,
    /// where everything is).
    #[must_use]
    pub fn recast_lights(&self) -> Vec<usize> {
        match self {
            Reuse::Retrace(_) => Vec::new(),
            Reuse::Reshade { kept_columns } => (0..kept_columns.len())
                .filter(|&i| kept_columns[i].is_none())
                .collect(),
        }
    }
}

/// The rays of one one-sample full-resolution pass (see the module notes).
#[derive(Clone, Debug)]
pub struct HitCache {
    geometry: RayGeometry,
    /// Per light of the world it was traced in, its shadow target: the column of
    /// shadow answers serves any light with the same target, whatever its index.
    lights: Vec<ShadowTarget>,
    /// Per light likewise, its placement: the column of light factors serves any light
    /// placed alike.
    placements: Vec<[u64; 8]>,
    /// What the cached colours were shaded with.
    shading: Shading,
    object_materials: Vec<Material>,
    pub(crate) tiles: Vec<TileHits>,
}

impl HitCache {
    /// A cache of `tiles` traced and shaded in `world` with `options`.
    pub(crate) fn new(world: &World, options: &RenderOptions, tiles: Vec<TileHits>) -> Self {
        Self {
            geometry: RayGeometry::of(world, options.width, options.height),
            lights: ShadowTarget::all(world),
            placements: light_factors::placements(world),
            shading: Shading::of(world, options),
            object_materials: object_materials(world),
            tiles,
        }
    }

    /// For a world this cache can serve ([`Self::reuse`]): which pixels keep their
    /// colour (none of whose rays meets an object whose material changed, and that
    /// depend on no switch that changed); `None` when anything else the shader reads
    /// changed, and every pixel must be shaded again.
    pub(crate) fn keep_rule(&self, world: &World, options: &RenderOptions) -> Option<KeepRule> {
        let now = Shading::of(world, options);
        let switched = if now == self.shading {
            TermDependence::NONE
        } else {
            let (old, new) = (self.shading.switches, now.switches);
            let others_alike = Shading {
                switches: old,
                ..now
            } == self.shading;
            let view = options.view;
            match (others_alike, old.beauty_terms(view), new.beauty_terms(view)) {
                (true, Some(old), Some(new)) => TermDependence::switched(old, new),
                _ => return None,
            }
        };
        let now = object_materials(world);
        if now.len() != self.object_materials.len() {
            return None;
        }
        let changed: Vec<bool> = now
            .iter()
            .zip(&self.object_materials)
            .map(|(a, b)| a != b)
            .collect();
        Some(KeepRule::new(changed, switched))
    }

    /// Per light of `world`, the column of light factors that serves it.
    pub(crate) fn factor_columns(&self, world: &World) -> Vec<Option<usize>> {
        light_factors::factor_columns(&self.placements, world)
    }

    /// Per object of `world`, whether the lobes cached for it are stale.
    pub(crate) fn stale_lobes(&self, world: &World) -> Vec<bool> {
        light_factors::stale_lobes(&self.object_materials, world)
    }

    /// Lights per cached entry (the light slot columns).
    pub(crate) fn light_count(&self) -> usize {
        self.lights.len()
    }

    /// Whether this cache can serve `world` rendered at `width` x `height`.
    #[must_use]
    pub fn reuse(&self, world: &World, width: u32, height: u32) -> Reuse {
        let now = RayGeometry::of(world, width, height);
        let old = &self.geometry;
        if (now.width, now.height) != (old.width, old.height) {
            return Reuse::Retrace(RetraceReason::Size);
        }
        if now.camera != old.camera {
            return Reuse::Retrace(RetraceReason::Camera);
        }
        // The cache keys materials by object; a CSG object whose operands differ in
        // material is shaded by operand, so such a world is always traced again.
        if now != *old || world.objects.iter().any(mixes_materials) {
            return Reuse::Retrace(RetraceReason::Objects);
        }
        let kept_columns = ShadowTarget::all(world)
            .iter()
            .map(|target| self.lights.iter().position(|old| old == target))
            .collect();
        Reuse::Reshade { kept_columns }
    }

    /// Rays held (closest hits and misses; shadow answers not counted).
    #[must_use]
    pub fn ray_count(&self) -> usize {
        self.tiles.iter().map(|t| t.chains.len()).sum()
    }

    /// Approximate memory held, in bytes (parts shared with another cache included).
    #[must_use]
    pub fn bytes(&self) -> usize {
        self.tiles
            .iter()
            .map(|t| {
                t.chains.capacity() * (size_of::<CachedHit>() + size_of::<u32>())
                    + t.slots.capacity() * size_of::<LightSlot>()
                    + t.chains.pixel_capacity() * size_of::<u32>()
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::examples::EXAMPLE_SCENES;
    use crate::scene::parse_scene;

    #[test]
    fn the_cache_fits_a_usual_preview_and_not_a_huge_one_nor_one_with_many_lights() {
        let text = EXAMPLE_SCENES
            .iter()
            .find(|(n, _)| *n == "default.ron")
            .unwrap()
            .1;
        let mut scene = parse_scene(text).unwrap();
        let world = World::new(&scene).unwrap();
        assert!(cache_fits(&world, 800, 600));
        assert!(cache_fits(&world, 1280, 960));
        assert!(!cache_fits(&world, 4000, 3000));
        let light = scene.lights.last().unwrap().clone();
        scene.lights.extend(std::iter::repeat_n(light, 10));
        let many = World::new(&scene).unwrap();
        assert!(
            !cache_fits(&many, 1280, 960),
            "each light adds a slot to every ray"
        );
        assert!(cache_fits(&many, 640, 480));
    }
}
