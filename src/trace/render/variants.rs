//! One picture under several conventions and depth limits from one trace: the ray tree
//! of every camera sample does not depend on how the colours its rays bring back are
//! combined and clamped, nor, below a depth limit, on that limit. Each sample's tree is
//! traced once, to the deepest limit asked for, then folded once per variant.
//!
//! Each picture is the one [`super::render`] makes of the world with that variant's
//! conventions and depth, bit for bit: the same samples, the same shading, the same
//! fold, the same guard against non-finite colours and the same average. What `raylab
//! diff` uses to try the course's other conventions at the cost of one render, not one
//! per convention.

use std::sync::atomic::Ordering;

use glam::DVec3;
use rayon::prelude::*;

use super::samples::sample_point;
use crate::scene::Conventions;
use crate::trace::film::{Image, PinholeCamera, RenderProgress};
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{Tracer, fold_within};
use crate::trace::terms::{TermSwitches, View};
use crate::trace::world::World;

/// How one of the pictures combines its rays' colours, and how deep they go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Variant {
    /// The conventions its rays' colours are folded with.
    pub conventions: Conventions,
    /// Its depth limit: at most the world's `max_depth`.
    pub max_depth: u32,
}

/// The lit pictures of `world` (all terms on, at `width` x `height`, `spp` samples per
/// pixel) under each of `variants`, in their order; `None` if cancelled through
/// `progress` (which counts rows).
///
/// # Panics
/// When a variant goes deeper than the world's `max_depth` (its rays were not traced).
#[must_use]
pub fn render_variants(
    world: &World,
    (width, height): (u32, u32),
    spp: u32,
    variants: &[Variant],
    progress: &RenderProgress,
) -> Option<Vec<Image>> {
    assert!(
        variants.iter().all(|v| v.max_depth <= world.max_depth),
        "a variant deeper than the world traces"
    );
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    let spp = spp.max(1);
    let scale = 1.0 / f64::from(spp);
    progress
        .batches_total
        .store(height as usize, Ordering::Relaxed);
    progress.batches_done.store(0, Ordering::Relaxed);
    let rows: Vec<Option<Vec<Vec<DVec3>>>> = (0..height)
        .into_par_iter()
        .map(|y| {
            if progress.is_cancelled() {
                return None;
            }
            let mut rays = RayCounts::default();
            let mut sums = vec![vec![DVec3::ZERO; width as usize]; variants.len()];
            for x in 0..width {
                for index in 0..spp {
                    let ray = camera.ray(sample_point(x, y, index, spp));
                    let tree = tracer.ray_tree(&ray, &mut rays);
                    for (sum, variant) in sums.iter_mut().zip(variants) {
                        let colour = fold_within(&tree, &variant.conventions, variant.max_depth);
                        // The renderer's guard: a non-finite sample adds nothing.
                        if colour.is_finite() {
                            sum[x as usize] += colour;
                        }
                    }
                }
            }
            progress.batches_done.fetch_add(1, Ordering::Relaxed);
            Some(sums)
        })
        .collect();
    let rows: Vec<Vec<Vec<DVec3>>> = rows.into_iter().collect::<Option<_>>()?;
    let images = (0..variants.len())
        .map(|v| Image {
            width,
            height,
            pixels: rows
                .iter()
                .flat_map(|row| row[v].iter().map(|s| (*s * scale).as_vec3()))
                .collect(),
        })
        .collect();
    Some(images)
}
