//! The one-sample full-resolution pass, traced or re-shaded from a [`HitCache`], and the
//! cache it leaves for the next edit.
//!
//! Each pixel's rays are answered by [`PixelRays`]: from the previous cache where it can
//! serve the world ([`HitCache::reuse`]), by tracing otherwise, and every answer goes
//! into the new cache (what the old one held and this pass did not need is carried
//! over, so making a mirror dull and shiny again traces nothing twice). A tile that
//! gained nothing shares its rays with the cache before instead of copying them. The shading is
//! [`Tracer`]'s own, through [`camera_sample`], so the sums are bit for bit those of
//! [`super::render_samples`] at one sample per pixel.

use std::sync::OnceLock;

use rayon::prelude::*;

use super::samples::{camera_sample, sample_point};
use super::tiles::{TileWork, render_tiles_with};
use crate::trace::cull::TileCull;
use crate::trace::film::{
    PinholeCamera, RenderOptions, RenderProgress, SampleSums, TileRect, tile_count,
};
use crate::trace::ray_counts::RayCounts;
use crate::trace::reshade::{
    DependenceRule, HitCache, PixelColour, PixelEntries, PixelRays, QuickShade, Reuse, SlotColumns,
    TermDependence, TileRays,
};
use crate::trace::shade::{LiveRays, Tracer};
use crate::trace::world::{World, assert_compiled_for};

/// What the one-sample pass made.
#[derive(Clone, Debug)]
pub struct CachedPass {
    /// The sums of the one sample per pixel (its rays are those the picture is made of,
    /// as a full trace counts them).
    pub sums: SampleSums,
    /// The rays this pass actually traced (the rest came from the previous cache).
    pub traced: RayCounts,
    /// Pixels shaded (the others kept their colour: no ray of theirs meets an object
    /// whose material changed, and nothing else the shader reads did).
    pub shaded_pixels: u64,
    /// Of those, the pixels shaded from their cached light factors alone
    /// ([`crate::trace::reshade::quick_shade`]).
    pub quick_pixels: u64,
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
        Reuse::Reshade { kept_columns, .. } => Some((
            cache,
            kept_columns,
            cache.factor_columns(world),
            cache.bent_objects(world),
        )),
        Reuse::Retrace(_) => None,
    });
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    // Built on first need: a pass re-shaded from the cache may trace no ray at all.
    let cull = OnceLock::new();
    let cull = || cull.get_or_init(|| TileCull::new(world, &camera, width, height));
    let lights = world.lights.len();
    // Only materials or switches changed (or nothing): pixels whose rays meet none of
    // the objects whose material changed, and that depend on no switch that changed,
    // keep their colour.
    let keep = reuse
        .as_ref()
        .and_then(|(cache, ..)| cache.keep_rule(world, options));
    // What each pixel shaded depends on, for the next edit's keep rule: the quick
    // re-shade works it out as it shades, the others from their chain afterwards.
    let dependence = tracer.beauty_terms().map(|_| DependenceRule::new(world));
    let depends = |entries: &PixelEntries| {
        dependence
            .as_ref()
            .map_or(TermDependence::ANY, |rule| rule.of_pixel(entries, lights))
    };
    let stale_lobes = reuse
        .as_ref()
        .map_or_else(Vec::new, |(cache, ..)| cache.stale_lobes(world));
    let quick = reuse
        .as_ref()
        .zip(dependence.as_ref())
        .and_then(|(_, rule)| QuickShade::new(&tracer, &stale_lobes, rule));
    let new_state = |index: u32, rect: TileRect| match &reuse {
        Some((cache, shadows, factors, bent)) => {
            let columns = SlotColumns {
                old_lights: cache.light_count(),
                shadows,
                factors,
                bent: bent.as_deref(),
            };
            TileRays::reading(&cache.tiles[index as usize], &columns)
        }
        None => {
            // Room for what the tile held before, as a geometry or camera edit changes
            // it little, and a few bounces more; else one bounce a pixel.
            let pixels = rect.pixel_count();
            let before = previous.and_then(|cache| cache.tiles.get(index as usize));
            let entries = before.map_or(2 * pixels, |tile| tile.chains.len() + pixels / 8);
            TileRays::fresh(pixels, lights, entries)
        }
    };
    let sample = |tile: &mut TileRays, px: u32, py: u32, _index: u32, rays: &mut RayCounts| {
        tile.begin_pixel();
        if let Some(kept) = keep.as_ref().and_then(|k| tile.unchanged_colour(k)) {
            rays.add(&kept.counts());
            tile.end_pixel(kept, true);
            return kept.colour;
        }
        tile.shaded += 1;
        let mut own = RayCounts::default();
        let quick = quick
            .as_ref()
            .and_then(|q| q.pixel(&tile.pixel_entries(), lights, &mut own));
        let (colour, depends) = match quick {
            Some(shaded) => {
                tile.quick += 1;
                shaded
            }
            None => {
                let point = sample_point(px, py, 0, 1);
                let source = &mut PixelRays {
                    tile: &mut *tile,
                    live: LiveRays::among(cull().candidates(point)),
                    stale_lobes: &stale_lobes,
                };
                let colour = camera_sample(&tracer, &camera, point, source, &mut own);
                (colour, depends(&tile.pixel_entries()))
            }
        };
        rays.add(&own);
        tile.end_pixel(PixelColour::of(colour, &own, depends), false);
        colour
    };
    // A tile whose every pixel keeps its colour or is quick-shaded goes in one loop.
    let whole = |tile: &mut TileRays| match &quick {
        Some(quick) => tile.whole_tile(keep.as_ref(), |entries, own| {
            quick.pixel(entries, lights, own)
        }),
        None if keep.is_some() => tile.whole_tile(keep.as_ref(), |_, _| None),
        None => None,
    };
    let work = TileWork {
        new_state,
        whole,
        batch: |_: &mut TileRays, _| None,
        sample: &sample,
    };
    let mut sums = SampleSums::unsummed(width, height);
    let (_, states) = render_tiles_with(&mut sums, 0..1, progress, &work)?;
    debug_assert_eq!(states.len(), tile_count(width, height) as usize);
    let mut traced = RayCounts::default();
    let (mut shaded_pixels, mut quick_pixels) = (0, 0);
    for state in &states {
        traced.add(&state.traced);
        shaded_pixels += state.shaded;
        quick_pixels += state.quick;
    }
    // In parallel: finishing a tile whose pixels went one by one sums it up again.
    let tiles = states.into_par_iter().map(TileRays::finish).collect();
    Some(CachedPass {
        sums,
        traced,
        shaded_pixels,
        quick_pixels,
        reused: reuse.is_some(),
        cache: HitCache::new(world, options, tiles),
    })
}
