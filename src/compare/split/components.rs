//! raylab's picture split into channels, pixel by pixel: every camera sample traced once
//! through the tracer with the [`SampleRecorder`] listening (which also traces each ray
//! again without each tree node it may show, for the nodes that might be missing).
//!
//! A split under other conventions ([`Components::split_again`]) keeps the pixels whose
//! samples fold alike under both ([`FoldFlags`]) and traces only the others.
//!
//! Stored pixel-major (compressed rows): pixel `p`'s channels are
//! `entries[offsets[p]..offsets[p + 1]]`, sorted by channel.

use std::sync::atomic::Ordering;

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::context::Context;
use super::fold_watch::{FoldFlags, FoldWatch};
use super::folded_only::{FoldedOnly, filled_by_fold};
use super::recorder::{SampleRecorder, Tally};
use crate::compare::catalogue::{ChannelSpace, MISS, MissingNodes, Nodes, TriedNode, spot_worlds};
use crate::scene::{Conventions, Scene};
use crate::trace::sample_in_pixel;
use crate::trace::{
    Image, PinholeCamera, RayCounts, RenderProgress, TermSwitches, Tracer, View, World,
};

/// One channel's colour at one pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Entry {
    /// The channel.
    pub channel: u32,
    /// Its colour (averaged over the pixel's samples).
    pub value: [f32; 3],
}

/// raylab's picture and its channels.
#[derive(Clone, Debug)]
pub struct Components {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub samples_per_pixel: u32,
    /// The channel numbering.
    pub space: ChannelSpace,
    /// raylab's picture, linear and unclamped, as `render` makes it.
    pub beauty: Vec<[f64; 3]>,
    /// The leaf ([`Nodes::leaves`]) the first sample of each pixel hit, or [`MISS`].
    pub labels: Vec<u32>,
    /// Whether a pixel's samples saw more than one object (or some missed).
    pub mixed: Vec<bool>,
    /// The scene object the first sample of each pixel would hit were the scene object
    /// it hit missing, or [`MISS`] (nothing behind, or that object not tried missing).
    pub behind: Vec<u32>,
    /// Start of each pixel's entries; one more than there are pixels.
    pub offsets: Vec<u32>,
    /// The entries, pixel by pixel.
    pub entries: Vec<Entry>,
    /// Per channel: squared changes of the diffuse and the specular part (normal bugs).
    pub split: Vec<[f64; 2]>,
    /// Rays cast.
    pub rays: RayCounts,
    /// The nodes of the scene's trees, whose leaves the channels are per.
    pub nodes: Nodes,
    /// The nodes tried as missing.
    pub tried: Vec<TriedNode>,
    /// The conventions and depth limit the rays were folded under.
    pub folded_under: (Conventions, u32),
    /// Per pixel, what its samples' colours depend on: which pixels a split under other
    /// conventions may keep.
    pub fold: Vec<FoldFlags>,
}

impl Components {
    /// The entries of pixel `p`.
    #[must_use]
    pub fn pixel(&self, p: usize) -> &[Entry] {
        &self.entries[self.offsets[p] as usize..self.offsets[p + 1] as usize]
    }

    /// The scene object pixel `p`'s first sample hit (raylab's object-id view), or
    /// [`MISS`].
    #[must_use]
    pub fn object_label(&self, p: usize) -> u32 {
        match self.labels[p] {
            MISS => MISS,
            leaf => self.nodes.object_of_leaf(leaf as usize) as u32,
        }
    }

    /// Whether each pixel lies on an outline of raylab's objects (or of an object and
    /// the background): its samples saw more than one, or a 4-neighbour shows another.
    #[must_use]
    pub fn outline(&self) -> Vec<bool> {
        let (w, h) = (self.width as usize, self.height as usize);
        (0..w * h)
            .map(|p| {
                let (x, y) = (p % w, p / w);
                let here = self.object_label(p);
                self.mixed[p]
                    || (x > 0 && self.object_label(p - 1) != here)
                    || (x + 1 < w && self.object_label(p + 1) != here)
                    || (y > 0 && self.object_label(p - w) != here)
                    || (y + 1 < h && self.object_label(p + w) != here)
            })
            .collect()
    }

    /// raylab's picture as the renderer's [`Image`].
    #[must_use]
    pub fn image(&self) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .beauty
                .iter()
                .map(|c| DVec3::from_array(*c).as_vec3())
                .collect(),
        }
    }
}

/// One row's results.
struct Row {
    beauty: Vec<[f64; 3]>,
    labels: Vec<u32>,
    behind: Vec<u32>,
    mixed: Vec<bool>,
    counts: Vec<u32>,
    entries: Vec<Entry>,
    split: Vec<[f64; 2]>,
    rays: RayCounts,
    fold: Vec<FoldFlags>,
}

/// A split made before under other conventions, and the conventions and depth of this
/// one: its pixels whose samples fold alike under both are kept.
#[derive(Clone, Copy)]
struct Before<'b> {
    split: &'b Components,
    now: (Conventions, u32),
}

impl Before<'_> {
    /// Whether pixel `p` is the same split now.
    fn keeps(&self, p: usize) -> bool {
        self.split.fold[p].same_under(self.split.folded_under, self.now)
    }

    /// Whether the rays are the same as before's (the same depth limit): then what the
    /// recorder fills while shading is before's, and only the fold is worked out again.
    fn same_rays(&self) -> bool {
        self.split.folded_under.1 == self.now.1
    }
}

impl Components {
    /// raylab's picture of `scene` (compiled as `world`) split as [`render_components`]
    /// splits it, where this split is of the same scene at the same size and samples
    /// under other conventions (or depth limit): the pixels whose samples fold alike
    /// under both are this split's, bit for bit; only the others are traced. `None` if
    /// cancelled through `progress`.
    ///
    /// The conventions change only how each ray tree is folded, so what the recorder
    /// works out while the tree is shaded (the lights, shadows and bug terms, and the
    /// normal bugs' `split`) is the same, and so are the rays cast.
    #[must_use]
    pub fn split_again(
        &self,
        scene: &Scene,
        world: &World,
        progress: &RenderProgress,
    ) -> Option<Components> {
        let before = Before {
            split: self,
            now: (world.conventions, world.max_depth),
        };
        let size = (self.width, self.height);
        split(
            scene,
            world,
            size,
            self.samples_per_pixel,
            progress,
            Some(before),
        )
    }
}

/// Splits raylab's `width` x `height` picture of `scene` (compiled as `world`) at `spp`
/// samples per pixel into channels; `None` if cancelled through `progress`.
#[must_use]
pub fn render_components(
    scene: &Scene,
    world: &World,
    size: (u32, u32),
    spp: u32,
    progress: &RenderProgress,
) -> Option<Components> {
    split(scene, world, size, spp, progress, None)
}

/// [`render_components`], keeping what of `before` is the same.
fn split(
    scene: &Scene,
    world: &World,
    (width, height): (u32, u32),
    spp: u32,
    progress: &RenderProgress,
    before: Option<Before>,
) -> Option<Components> {
    let nodes = Nodes::new(scene, world);
    let missing = MissingNodes::new(scene, world, &nodes);
    let tried = missing.tried_nodes();
    let spot = spot_worlds(scene, world);
    let ctx = Context::new(world, scene.lights.len(), &nodes, missing, spot);
    let space = ctx.space;
    let camera = PinholeCamera::new(&world.camera, width, height);
    let spp = spp.max(1);
    // one batch per row here
    progress
        .batches_total
        .store(height as usize, Ordering::Relaxed);
    progress.batches_done.store(0, Ordering::Relaxed);
    let rows: Vec<Option<Row>> = (0..height)
        .into_par_iter()
        .map(|y| {
            if progress.is_cancelled() {
                return None;
            }
            let row = render_row(&ctx, &camera, (width, y), spp, before);
            progress.batches_done.fetch_add(1, Ordering::Relaxed);
            Some(row)
        })
        .collect();
    let rows: Vec<Row> = rows.into_iter().collect::<Option<_>>()?;
    let pixels = width as usize * height as usize;
    let mut components = Components {
        width,
        height,
        samples_per_pixel: spp,
        space,
        beauty: Vec::with_capacity(pixels),
        labels: Vec::with_capacity(pixels),
        behind: Vec::with_capacity(pixels),
        mixed: Vec::with_capacity(pixels),
        offsets: Vec::with_capacity(pixels + 1),
        entries: Vec::new(),
        split: vec![[0.0; 2]; space.count()],
        rays: RayCounts::default(),
        nodes,
        tried,
        folded_under: (world.conventions, world.max_depth),
        fold: Vec::with_capacity(pixels),
    };
    components.offsets.push(0);
    for row in rows {
        components.beauty.extend(row.beauty);
        components.labels.extend(row.labels);
        components.behind.extend(row.behind);
        components.mixed.extend(row.mixed);
        components.fold.extend(row.fold);
        let base = components.entries.len() as u32;
        let mut end = base;
        for count in row.counts {
            end += count;
            components.offsets.push(end);
        }
        components.entries.extend(row.entries);
        for (sum, part) in components.split.iter_mut().zip(row.split) {
            sum[0] += part[0];
            sum[1] += part[1];
        }
        components.rays.add(&row.rays);
    }
    if let Some(before) = before {
        // What was traced only in part: the shading's, the same as before's whole.
        components.split.clone_from(&before.split.split);
        components.rays = before.split.rays;
    }
    Some(components)
}

/// Splits row `y` (of `width` pixels); with `before`, its pixels that are the same
/// under this split's conventions are copied from it.
fn render_row(
    ctx: &Context,
    camera: &PinholeCamera,
    (width, y): (u32, u32),
    spp: u32,
    before: Option<Before>,
) -> Row {
    let tracer = Tracer::new(ctx.world, TermSwitches::ALL_ON, View::Beauty);
    let clamp = ctx.world.conventions.clamp;
    let scale = 1.0 / f64::from(spp);
    let mut recorder = SampleRecorder::new(ctx);
    let mut row = Row {
        beauty: Vec::with_capacity(width as usize),
        labels: Vec::with_capacity(width as usize),
        behind: Vec::with_capacity(width as usize),
        mixed: Vec::with_capacity(width as usize),
        counts: Vec::with_capacity(width as usize),
        entries: Vec::new(),
        split: Vec::new(),
        rays: RayCounts::default(),
        fold: Vec::with_capacity(width as usize),
    };
    let mut pixel = Tally::default();
    let fold_only = before.is_some_and(|b| b.same_rays());
    for x in 0..width {
        let p = y as usize * width as usize + x as usize;
        if let Some(before) = before.filter(|b| b.keeps(p)) {
            let kept = before.split;
            row.beauty.push(kept.beauty[p]);
            row.labels.push(kept.labels[p]);
            row.behind.push(kept.behind[p]);
            row.mixed.push(kept.mixed[p]);
            row.counts.push(kept.pixel(p).len() as u32);
            row.entries.extend_from_slice(kept.pixel(p));
            row.fold.push(kept.fold[p]);
            continue;
        }
        pixel.entries.clear();
        let mut sum = DVec3::ZERO;
        let mut labels = Vec::with_capacity(1);
        let mut behind = MISS;
        let mut fold = FoldFlags::default();
        for index in 0..spp {
            let point = DVec2::new(f64::from(x), f64::from(y)) + sample_in_pixel(x, y, index, spp);
            let ray = camera.ray(point);
            recorder.start();
            let colour = if fold_only {
                let mut folded = FoldedOnly(&mut recorder);
                let mut watch = FoldWatch::new(&mut folded, clamp);
                let colour = tracer.trace_primary(&ray, &mut row.rays, &mut watch);
                fold |= watch.flags;
                colour
            } else {
                let mut watch = FoldWatch::new(&mut recorder, clamp);
                let colour = tracer.trace_primary(&ray, &mut row.rays, &mut watch);
                fold |= watch.flags;
                colour
            };
            fold |= recorder.fold;
            if recorder.primary_leaf().is_some() {
                for k in 0..ctx.spot.len() {
                    // A world with only its spot light changed has the same rays: its
                    // mirror rays are this tree's, its colours are not watched.
                    let flag = if ctx.spot_alike[k] {
                        FoldFlags::UNCLAMPED
                    } else {
                        FoldFlags::SPOT
                    };
                    // Asked only while it would tell the pixel something new.
                    if !fold.contains(flag) && recorder.spot_may_change(k) {
                        fold |= flag;
                    }
                }
            }
            if !colour.is_finite() {
                continue; // the renderer's guard: a non-finite sample adds nothing
            }
            sum += colour;
            if labels.is_empty() {
                behind = recorder.behind;
            }
            labels.push(recorder.primary_leaf().map_or(MISS, |l| l as u32));
            pixel.absorb(&recorder.tally);
        }
        row.beauty.push((sum * scale).to_array());
        let first = labels.first().copied().unwrap_or(MISS);
        row.labels.push(first);
        row.behind.push(behind);
        row.mixed.push(labels.iter().any(|&l| l != first));
        row.fold.push(fold);
        pixel.entries.sort_unstable_by_key(|(c, _)| *c);
        let entries = pixel.entries.iter().map(|&(channel, v)| Entry {
            channel,
            value: (v * scale).as_vec3().to_array(),
        });
        match before.filter(|_| fold_only) {
            Some(before) => {
                let folded: Vec<Entry> = entries.collect();
                let all = merged(&ctx.space, before.split.pixel(p), &folded);
                row.counts.push(all.len() as u32);
                row.entries.extend(all);
            }
            None => {
                row.counts.push(pixel.entries.len() as u32);
                row.entries.extend(entries);
            }
        }
    }
    row.split = recorder.split;
    row
}

/// A pixel's entries: `shaded`'s channels filled while shading (the first split's),
/// and `folded`'s filled by the fold (worked out again), sorted by channel.
fn merged(space: &ChannelSpace, shaded: &[Entry], folded: &[Entry]) -> Vec<Entry> {
    let by_fold = |e: &&Entry| filled_by_fold(space.decode(e.channel).0);
    let mut entries: Vec<Entry> = shaded.iter().filter(|e| !by_fold(e)).copied().collect();
    entries.extend(folded.iter().filter(by_fold).copied());
    entries.sort_unstable_by_key(|e| e.channel);
    entries
}
