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

use super::camera::PinholeCamera;
use std::sync::Arc;

use super::hit_cache::{
    CachedHit, Chains, HitCache, NOT_CAST, PixelColour, Reuse, TileHits, decode_blocker,
    encode_blocker,
};
use super::isolation::assert_compiled_for;
use super::ray::Ray;
use super::ray_source::{LiveRays, RaySource, ShadowQuery};
use super::render::{RenderOptions, RenderProgress, SampleSums, camera_sample, sample_point};
use super::shade::{RayCounts, Tracer};
use super::tile_cull::TileCull;
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
    /// Pixels shaded (the others kept their colour: no ray of theirs meets an object
    /// whose material changed, and nothing else the shader reads did).
    pub shaded_pixels: u64,
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
    let cull = TileCull::new(world, &camera, width, height);
    let lights = world.lights.len();
    // Only materials changed (or nothing): pixels whose rays meet none of the objects
    // whose material changed keep their colour.
    let changed = reuse
        .as_ref()
        .and_then(|(cache, _)| cache.changed_objects(world, options));
    let new_state = |index: u32, rect: TileRect| match &reuse {
        Some((cache, columns)) => {
            TileRays::reading(&cache.tiles[index as usize], cache.light_count(), columns)
        }
        None => TileRays::fresh(rect.pixel_count(), lights),
    };
    let sample = |tile: &mut TileRays, px: u32, py: u32, _index: u32, rays: &mut RayCounts| {
        tile.begin_pixel();
        let kept = changed.as_deref().and_then(|c| tile.unchanged_colour(c));
        let (colour, pixel_rays) = match kept {
            Some(kept) => (kept.colour, kept.rays.map(u64::from)),
            None => {
                tile.shaded += 1;
                let point = sample_point(px, py, 0, 1);
                let mut own = RayCounts::default();
                let source = &mut PixelRays {
                    tile: &mut *tile,
                    live: LiveRays::among(cull.candidates(point)),
                };
                let colour = camera_sample(&tracer, &camera, point, source, &mut own);
                (colour, [own.primary, own.shadow, own.reflection])
            }
        };
        rays.primary += pixel_rays[0];
        rays.shadow += pixel_rays[1];
        rays.reflection += pixel_rays[2];
        tile.end_pixel(PixelColour {
            colour,
            rays: pixel_rays.map(|n| u32::try_from(n).unwrap_or(u32::MAX)),
        });
        colour
    };
    let mut sums = SampleSums::zero(width, height);
    let (_, states) = render_tiles_with(&mut sums, 0..1, progress, new_state, &sample)?;
    debug_assert_eq!(states.len(), tile_count(width, height) as usize);
    let mut traced = RayCounts::default();
    let mut shaded_pixels = 0;
    let tiles = states
        .into_iter()
        .map(|state| {
            traced.add(&state.traced);
            shaded_pixels += state.shaded;
            state.finish()
        })
        .collect();
    Some(CachedPass {
        sums,
        traced,
        shaded_pixels,
        reused: reuse.is_some(),
        cache: HitCache::new(world, options, tiles),
    })
}

/// One tile's rays during the pass. It reads the previous cache's chains in place, shared,
/// until a pixel needs a ray the cache lacks; from then on the tile's chains are rebuilt
/// (the pixels before copied at once, each later one as it comes). Shadow answers are
/// written into the shared visibility on first change (copied once per tile).
struct TileRays {
    chains: Arc<Chains>,
    visibility: Arc<Vec<u32>>,
    /// The rebuilt chains and visibility, once one chain had to grow.
    grown: Option<(Chains, Vec<u32>)>,
    /// The pixels' colours in the cache read (none for a fresh tile), and in this pass.
    old_colours: Option<Arc<Vec<PixelColour>>>,
    colours: Vec<PixelColour>,
    /// Pixels shaded so far.
    shaded: u64,
    /// The pixel being shaded, row-major within the tile.
    pixel: usize,
    lights: usize,
    traced: RayCounts,
}

impl TileRays {
    /// Reading `old`, traced with `old_lights` lights, for a world whose light `i` keeps
    /// the old column `kept_columns[i]` of shadow answers (`None`: cast again).
    fn reading(old: &TileHits, old_lights: usize, kept_columns: &[Option<usize>]) -> Self {
        let same_lights = kept_columns.len() == old_lights
            && kept_columns.iter().enumerate().all(|(i, c)| *c == Some(i));
        let visibility = if same_lights {
            Arc::clone(&old.visibility)
        } else {
            // Entry by entry, not chunks of the old rows: the old world may have had no
            // light at all.
            let remapped = (0..old.chains.hits.len()).flat_map(|entry| {
                let row = &old.visibility[entry * old_lights..(entry + 1) * old_lights];
                kept_columns
                    .iter()
                    .map(|column| column.map_or(NOT_CAST, |c| row[c]))
            });
            Arc::new(remapped.collect())
        };
        Self {
            chains: Arc::clone(&old.chains),
            visibility,
            grown: None,
            old_colours: Some(Arc::clone(&old.colours)),
            colours: Vec::with_capacity(old.colours.len()),
            shaded: 0,
            pixel: 0,
            lights: kept_columns.len(),
            traced: RayCounts::default(),
        }
    }

    /// A tile with nothing cached, for a world with `lights` lights.
    fn fresh(pixels: usize, lights: usize) -> Self {
        let nothing = Chains {
            chain_ends: vec![0; pixels],
            hits: Vec::new(),
        };
        let growing = Chains {
            chain_ends: Vec::with_capacity(pixels),
            hits: Vec::with_capacity(pixels),
        };
        Self {
            chains: Arc::new(nothing),
            visibility: Arc::new(Vec::new()),
            grown: Some((growing, Vec::with_capacity(pixels * lights))),
            old_colours: None,
            colours: Vec::with_capacity(pixels),
            shaded: 0,
            pixel: 0,
            lights,
            traced: RayCounts::default(),
        }
    }

    /// Starts the next pixel: once rebuilding, copies its cached chain across.
    fn begin_pixel(&mut self) {
        if let Some((chains, visibility)) = &mut self.grown {
            let chain = self.chains.chain(self.pixel);
            let lights = self.lights;
            visibility
                .extend_from_slice(&self.visibility[chain.start * lights..chain.end * lights]);
            chains.hits.extend_from_slice(&self.chains.hits[chain]);
        }
    }

    /// The current pixel's cached colour, if none of its rays meets an object with
    /// `changed[object]` set (and so its rays and colour are what they were).
    fn unchanged_colour(&self, changed: &[bool]) -> Option<PixelColour> {
        let old = self.old_colours.as_ref()?;
        let hits = match &self.grown {
            Some((chains, _)) => &chains.hits,
            None => &self.chains.hits,
        };
        let touched = hits[self.chain()]
            .iter()
            .any(|hit| hit.object().is_some_and(|o| changed[o]));
        (!touched).then(|| old[self.pixel])
    }

    /// Ends the pixel, which came out `colour`.
    fn end_pixel(&mut self, colour: PixelColour) {
        if let Some((chains, _)) = &mut self.grown {
            chains.chain_ends.push(chains.hits.len() as u32);
        }
        self.colours.push(colour);
        self.pixel += 1;
    }

    /// Where the current pixel's chain is, in the chains read or rebuilt.
    fn chain(&self) -> std::ops::Range<usize> {
        match &self.grown {
            Some((chains, _)) => {
                let start = chains.chain_ends.last().map_or(0, |&end| end as usize);
                start..chains.hits.len()
            }
            None => self.chains.chain(self.pixel),
        }
    }

    /// Starts rebuilding, copying every chain up to and including the current pixel's.
    fn grow(&mut self) -> &mut (Chains, Vec<u32>) {
        let (pixel, lights) = (self.pixel, self.lights);
        let (chains, visibility) = (&self.chains, &self.visibility);
        self.grown.get_or_insert_with(|| {
            let end = chains.chain(pixel).end;
            let mut hits = Vec::with_capacity(chains.hits.len() + chains.chain_ends.len() / 4);
            hits.extend_from_slice(&chains.hits[..end]);
            let copied = Chains {
                chain_ends: chains.chain_ends[..pixel].to_vec(),
                hits,
            };
            (copied, visibility[..end * lights].to_vec())
        })
    }

    /// The tile's rays for the new cache.
    fn finish(self) -> TileHits {
        match self.grown {
            Some((chains, visibility)) => TileHits {
                chains: Arc::new(chains),
                visibility: Arc::new(visibility),
                colours: Arc::new(self.colours),
            },
            None => TileHits {
                chains: self.chains,
                visibility: self.visibility,
                colours: Arc::new(self.colours),
            },
        }
    }
}

/// Answers one pixel's rays from its tile, tracing (and keeping) whatever it lacks.
struct PixelRays<'t, 'c> {
    tile: &'t mut TileRays,
    /// What traces the rays the cache lacks (culled for the camera ray's tile).
    live: LiveRays<'c>,
}

impl RaySource for PixelRays<'_, '_> {
    fn closest_hit(&mut self, world: &World, depth: u32, ray: &Ray) -> Option<SurfacePoint> {
        let chain = self.tile.chain();
        let depth = depth as usize;
        if depth < chain.len() {
            let hits = match &self.tile.grown {
                Some((chains, _)) => &chains.hits,
                None => &self.tile.chains.hits,
            };
            return hits[chain.start + depth].point();
        }
        // The chain is walked depth by depth: the missing entry is the next one.
        debug_assert_eq!(depth, chain.len());
        if depth == 0 {
            self.tile.traced.primary += 1;
        } else {
            self.tile.traced.reflection += 1;
        }
        let hit = self.live.closest_hit(world, depth as u32, ray);
        let lights = self.tile.lights;
        let (chains, visibility) = self.tile.grow();
        chains.hits.push(CachedHit::new(hit.as_ref()));
        visibility.extend(std::iter::repeat_n(NOT_CAST, lights));
        hit
    }

    fn occluder(
        &mut self,
        world: &World,
        depth: u32,
        light: usize,
        query: impl FnOnce() -> ShadowQuery,
    ) -> Option<usize> {
        let slot = (self.tile.chain().start + depth as usize) * self.tile.lights + light;
        let code = match &self.tile.grown {
            Some((_, visibility)) => visibility[slot],
            None => self.tile.visibility[slot],
        };
        if code != NOT_CAST {
            return decode_blocker(code);
        }
        self.tile.traced.shadow += 1;
        let blocked_by = self.live.occluder(world, depth, light, query);
        let code = encode_blocker(blocked_by);
        match &mut self.tile.grown {
            Some((_, visibility)) => visibility[slot] = code,
            // Copied once per tile, while the cache before still holds the original.
            None => Arc::make_mut(&mut self.tile.visibility)[slot] = code,
        }
        blocked_by
    }
}
