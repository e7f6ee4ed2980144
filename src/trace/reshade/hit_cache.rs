//! The hit cache: every ray the one-sample full-resolution pass traced, kept so that an
//! edit that moves nothing can be re-shaded instead of re-traced ([`crate::trace::render::cached`]).
//!
//! Per pixel it keeps the tree of rays of the pixel-centre sample (`super::chains`): an
//! entry per ray traced (the closest hit, or the miss that ends a branch), each found by
//! its parent's entry and which of the parent's rays it is, and per entry and light what
//! that light's shadow ray met: clear, a blocker, or "not cast" (the shader did not
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
//!   shiny, glass made transmissive, a deeper `max_depth`, a light in front of a surface
//!   that was behind it);
//! - an object's `ior` changed: the rays it transmits bend another way, and the entries
//!   below them (only those) are dropped and traced again
//!   ([`super::ray_geometry::bent_objects`]).

use std::sync::Arc;

use glam::DVec3;

use super::cached_hit::CachedHit;
use super::chains::{Chains, Children};
use super::dependence::TermDependence;
use super::keep_rule::{KeepRule, TileSummary};
use super::light_factors;
use super::light_factors::LightSlot;
use super::object_materials::object_materials;
use super::pixel_colour::PixelColour;
use super::ray_geometry::{RayGeometry, ShadowTarget, bent_objects};
use crate::scene::Material;
use crate::trace::film::RenderOptions;
use crate::trace::terms::{TermSwitches, View};
use crate::trace::world::{SphereLight, World, WorldLight};

/// The most memory the preview's cache may take, as [`cache_fits`] estimates it: larger
/// previews re-trace every edit.
pub const MAX_CACHE_BYTES: usize = 512 << 20;

/// Whether the cache of `world` rendered at `width` x `height` stays under
/// [`MAX_CACHE_BYTES`], for two rays a pixel (the default scene has 1.6: some 160 MB at
/// 800 x 600 with its three lights, each ray 92 bytes and 32 more per light), or for
/// `rays` rays (closest-hit rays: camera, mirror and transmitted) where a pass traced
/// them already (`scenes/glass.ron` has 2.6 a pixel, each with 8 bytes of links more).
#[must_use]
pub fn cache_fits(world: &World, width: u32, height: u32, rays: Option<u64>) -> bool {
    let per_ray =
        size_of::<CachedHit>() + size_of::<u32>() + world.lights.len() * size_of::<LightSlot>();
    let pixels = (width as usize).saturating_mul(height as usize);
    let per_pixel = size_of::<PixelColour>() + size_of::<u32>();
    let rays = rays.map_or(pixels.saturating_mul(2), |rays| {
        usize::try_from(rays).unwrap_or(usize::MAX)
    });
    let links = if rays > pixels {
        size_of::<Children>()
    } else {
        0
    };
    rays.saturating_mul(per_ray + links)
        .saturating_add(pixels.saturating_mul(per_pixel))
        <= MAX_CACHE_BYTES
}

/// The cached rays of one tile. The chains and light slots are shared with the cache
/// before when an edit left them as they were (most edits add no ray), so a re-shade
/// copies nothing.
#[derive(Clone, Debug)]
pub(crate) struct TileHits {
    /// The pixels' entries.
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
        /// Some object's `ior` changed: the rays below its transmitted rays are traced
        /// again.
        bent: bool,
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
            Reuse::Reshade { kept_columns, .. } => (0..kept_columns.len())
                .filter(|&i| kept_columns[i].is_none())
                .collect(),
        }
    }

    /// Whether the re-shade casts again rays the cache held (a moved light's shadow
    /// rays, the rays below glass whose index changed): up to a traced frame's work.
    #[must_use]
    pub fn traces_again(&self) -> bool {
        match self {
            Reuse::Retrace(_) => false,
            Reuse::Reshade { kept_columns, bent } => {
                *bent || kept_columns.iter().any(Option::is_none)
            }
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

    /// Per object of `world`, whether its transmitted rays bend another way than when
    /// they were cached (the entries below them are stale); `None` where no object's do.
    pub(crate) fn bent_objects(&self, world: &World) -> Option<Vec<bool>> {
        Some(bent_objects(&self.object_materials, world)).filter(|bent| bent.contains(&true))
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
        let bent = bent_objects(&self.object_materials, world).contains(&true);
        Reuse::Reshade { kept_columns, bent }
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
                t.chains.capacity() * t.chains.entry_bytes()
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
        assert!(cache_fits(&world, 800, 600, None));
        assert!(cache_fits(&world, 1280, 960, None));
        assert!(!cache_fits(&world, 4000, 3000, None));
        let light = scene.lights.last().unwrap().clone();
        scene.lights.extend(std::iter::repeat_n(light, 10));
        let many = World::new(&scene).unwrap();
        assert!(
            !cache_fits(&many, 1280, 960, None),
            "each light adds a slot to every ray"
        );
        assert!(cache_fits(&many, 640, 480, None));
        // Counted rays: a tree of 8 rays a pixel does not fit where 2 would.
        assert!(!cache_fits(&world, 1280, 960, Some(8 * 1280 * 960)));
        assert!(cache_fits(&world, 1280, 960, Some(1280 * 960)));
    }
}
