//! The one-sample full-resolution pass, traced or re-shaded from a [`HitCache`], and the
//! cache it leaves for the next edit.
//!
//! Each pixel's rays are answered by [`PixelRays`]: from the previous cache where it can
//! serve the world ([`HitCache::reuse`]), by tracing otherwise, and every answer goes
//! into the new cache (what the old one held and this pass did not need is carried
//! over, so making a mirror dull and shiny again traces nothing twice). The shading is
//! [`Tracer`]'s own, through [`camera_sample`], so the sums are bit for bit those of
//! [`super::render_samples`] at one sample per pixel.

use super::camera::PinholeCamera;
use super::hit_cache::{
    CachedHit, HitCache, NOT_CAST, Reuse, TileHits, decode_blocker, encode_blocker,
};
use super::isolation::assert_compiled_for;
use super::ray::Ray;
use super::ray_source::{LiveRays, RaySource, ShadowQuery};
use super::render::{RenderOptions, RenderProgress, SampleSums, camera_sample, sample_point};
use super::shade::{RayCounts, Tracer};
use super::tiles::{TileRect, render_tiles_with, tile_count};
use super::world::{SurfacePoint, World};

/// What the one-sample pass made.
#[derive(Clone, Debug)]
pub struct CachedPass {
    /// The sums of the one sample per pixel (its rays are those the picture is made of,
    /// as a full trace counts them).
    pub sums: SampleSums,
    /// The rays this pass actually traced (the rest came from the previous cache).
    pub traced: RayCounts,
    /// Whether the previous cache served this pass.
    pub reused: bool,
    /// Every ray of this pass and those carried over, for the next edit.
    pub cache: HitCache,
}

/// Renders the one-sample pass of `options` (at its size, through pixel centres; its
/// `samples_per_pixel` is not used) in `world`, answering rays from `previous` where it
/// is still valid. `None` if cancelled.
///
/// # Panics
/// When `world` was compiled for other isolation switches than `options.isolation`.
#[must_use]
pub fn render_one_sample_cached(
    world: &World,
    options: &RenderOptions,
    previous: Option<&HitCache>,
    progress: &RenderProgress,
) -> Option<CachedPass> {
    let (width, height) = (options.width, options.height);
    assert_compiled_for(world, &options.isolation);
    let reuse = previous.and_then(|cache| match cache.reuse(world, width, height) {
        Reuse::Reshade { kept_columns } => Some((cache, kept_columns)),
        Reuse::Retrace(_) => None,
    });
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let lights = world.lights.len();
    let new_state = |index: u32, rect: TileRect| TileRays {
        old: reuse.as_ref().map(|(cache, columns)| OldTile {
            hits: &cache.tiles[index as usize],
            lights: cache.light_count(),
            kept_columns: columns,
        }),
        new: TileHits {
            chain_ends: Vec::with_capacity(rect.pixel_count()),
            ..TileHits::default()
        },
        lights,
        traced: RayCounts::default(),
    };
    let sample = |state: &mut TileRays, px: u32, py: u32, _index: u32, rays: &mut RayCounts| {
        let start = state.begin_pixel();
        let mut source = PixelRays {
            tile: &mut state.new,
            start,
            lights,
            traced: &mut state.traced,
        };
        let colour = camera_sample(
            &tracer,
            &camera,
            sample_point(px, py, 0, 1),
            &mut source,
            rays,
        );
        state.new.chain_ends.push(state.new.hits.len() as u32);
        colour
    };
    let mut sums = SampleSums::zero(width, height);
    let (_, states) = render_tiles_with(&mut sums, 0..1, progress, new_state, &sample)?;
    debug_assert_eq!(states.len(), tile_count(width, height) as usize);
    let mut traced = RayCounts::default();
    let tiles = states
        .into_iter()
        .map(|state| {
            traced.add(&state.traced);
            state.new
        })
        .collect();
    Some(CachedPass {
        sums,
        traced,
        reused: reuse.is_some(),
        cache: HitCache::new(world, width, height, tiles),
    })
}

/// The previous cache's rays of one tile, and which of its light columns still hold.
struct OldTile<'c> {
    hits: &'c TileHits,
    lights: usize,
    kept_columns: &'c [Option<usize>],
}

/// One tile's state during the pass: the old rays to read, the new ones being written.
struct TileRays<'c> {
    old: Option<OldTile<'c>>,
    new: TileHits,
    lights: usize,
    traced: RayCounts,
}

impl TileRays<'_> {
    /// Starts the next pixel (they come row-major within the tile): copies its old
    /// chain, shadow answers of the lights that kept them, into the new cache, and
    /// returns where the chain starts there.
    fn begin_pixel(&mut self) -> usize {
        let start = self.new.hits.len();
        let pixel = self.new.chain_ends.len();
        if let Some(old) = &self.old {
            let chain = old.hits.chain(pixel);
            for entry in chain {
                self.new.hits.push(old.hits.hits[entry]);
                let row = &old.hits.visibility[entry * old.lights..(entry + 1) * old.lights];
                self.new.visibility.extend(
                    old.kept_columns
                        .iter()
                        .map(|column| column.map_or(NOT_CAST, |c| row[c])),
                );
            }
        }
        debug_assert_eq!(self.new.visibility.len(), self.new.hits.len() * self.lights);
        start
    }
}

/// Answers one pixel's rays from its chain in the new cache, tracing (and appending)
/// whatever the chain lacks.
struct PixelRays<'t> {
    tile: &'t mut TileHits,
    /// Where the pixel's chain starts in `tile.hits`.
    start: usize,
    lights: usize,
    traced: &'t mut RayCounts,
}

impl RaySource for PixelRays<'_> {
    fn closest_hit(&mut self, world: &World, depth: u32, ray: &Ray) -> Option<SurfacePoint> {
        let entry = self.start + depth as usize;
        if let Some(cached) = self.tile.hits.get(entry) {
            return cached.point();
        }
        // The chain is walked depth by depth: the missing entry is the next one.
        debug_assert_eq!(entry, self.tile.hits.len());
        if depth == 0 {
            self.traced.primary += 1;
        } else {
            self.traced.reflection += 1;
        }
        let hit = LiveRays.closest_hit(world, depth, ray);
        self.tile.hits.push(CachedHit::new(hit.as_ref()));
        self.tile
            .visibility
            .extend(std::iter::repeat_n(NOT_CAST, self.lights));
        hit
    }

    fn occluder(&mut self, world: &World, query: &ShadowQuery) -> Option<usize> {
        let slot = (self.start + query.depth as usize) * self.lights + query.light;
        let code = self.tile.visibility[slot];
        if code != NOT_CAST {
            return decode_blocker(code);
        }
        self.traced.shadow += 1;
        let blocked_by = LiveRays.occluder(world, query);
        self.tile.visibility[slot] = encode_blocker(blocked_by);
        blocked_by
    }
}
