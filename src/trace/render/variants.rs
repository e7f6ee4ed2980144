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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{ClampConvention, MirrorConvention, Quantise, Scene, parse_scene};
    use crate::trace::film::RenderOptions;
    use crate::trace::render::render;

    /// Two mirrors facing each other (a ray between them bounces to any depth), a bright
    /// ball that each-ray clamping changes, glass that splits rays, 2 samples a pixel.
    const SCENE: &str = r#"Scene(
        camera: (position: (0.0, 1.5, 6.0), look_at: (0.0, 1.0, 0.0), fov_deg: 60.0, width: 40, height: 30),
        render: (max_depth: 8, background: (0.2, 0.3, 0.4), samples_per_pixel: 2),
        materials: {
            "floor": (ambient: (0.2, 0.2, 0.2), diffuse: (0.6, 0.6, 0.6)),
            "mirror": (ambient: (0.1, 0.1, 0.1), diffuse: (0.3, 0.2, 0.1), specular: (0.9, 0.9, 0.9), shininess: 20.0, mirror: (0.8, 0.7, 0.9)),
            "bright": (ambient: (0.9, 0.5, 0.2), diffuse: (1.5, 0.9, 0.4), specular: (1.0, 1.0, 1.0), shininess: 10.0),
            "glass": (ambient: (0.0, 0.0, 0.0), diffuse: (0.1, 0.1, 0.1), transmission: (0.8, 0.9, 0.8), ior: 1.5),
        },
        objects: [
            (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (10.0, 10.0, 1.0)), material: "floor"),
            (name: "left", shape: Plane, transform: (translate: (-3.0, 1.0, 0.0), rotate_deg: (0.0, 90.0, 0.0), scale: (5.0, 3.0, 1.0)), material: "mirror"),
            (name: "right", shape: Plane, transform: (translate: (3.0, 1.0, 0.0), rotate_deg: (0.0, -90.0, 0.0), scale: (5.0, 3.0, 1.0)), material: "mirror"),
            (name: "ball", shape: Sphere, transform: (translate: (-0.8, 1.0, 0.0), scale: (0.7, 0.7, 0.7)), material: "bright"),
            (name: "lens", shape: Sphere, transform: (translate: (1.0, 0.8, 1.0), scale: (0.5, 0.5, 0.5)), material: "glass"),
        ],
        lights: [
            Ambient(colour: (0.3, 0.3, 0.3)),
            Point(position: (0.0, 5.0, 3.0), colour: (1.0, 1.0, 1.0), intensity: 30.0),
        ],
    )"#;

    /// `render`'s picture of `scene` under `variant`.
    fn rendered(scene: &Scene, variant: Variant) -> Image {
        let mut scene = scene.clone();
        scene.render.conventions = variant.conventions;
        scene.render.max_depth = variant.max_depth;
        let world = World::new(&scene).unwrap();
        let options = RenderOptions::from_scene(&scene);
        render(&world, &options, &RenderProgress::default())
            .unwrap()
            .0
    }

    #[test]
    fn each_variant_is_the_render_under_its_conventions_and_depth_bit_for_bit() {
        let scene = parse_scene(SCENE).unwrap();
        let mut variants = Vec::new();
        for mirror in [MirrorConvention::Add, MirrorConvention::Blend] {
            for clamp in [ClampConvention::Pixel, ClampConvention::EachRay] {
                for max_depth in [0, 1, 3, 8] {
                    let conventions = Conventions {
                        mirror,
                        clamp,
                        quantise: Quantise::Round,
                    };
                    variants.push(Variant {
                        conventions,
                        max_depth,
                    });
                }
            }
        }
        let world = World::new(&scene).unwrap();
        let size = (scene.camera.width, scene.camera.height);
        let spp = scene.render.samples_per_pixel;
        let pictures =
            render_variants(&world, size, spp, &variants, &RenderProgress::default()).unwrap();
        assert_eq!(pictures.len(), variants.len());
        for (picture, &variant) in pictures.iter().zip(&variants) {
            let expected = rendered(&scene, variant);
            assert_eq!(picture.pixels, expected.pixels, "{variant:?}");
        }
        // The variants do differ, so the comparison tells them apart: (Add, Pixel, 8)
        // against a shallower depth, the blend and the each-ray clamp.
        let differs = |a: usize, b: usize| pictures[a].pixels != pictures[b].pixels;
        assert!(differs(3, 2) && differs(3, 11) && differs(3, 7));
    }

    #[test]
    fn a_cancelled_render_gives_nothing() {
        let scene = parse_scene(SCENE).unwrap();
        let world = World::new(&scene).unwrap();
        let progress = RenderProgress::default();
        progress.cancel();
        let variant = Variant {
            conventions: scene.render.conventions,
            max_depth: 1,
        };
        assert!(render_variants(&world, (8, 6), 1, &[variant], &progress).is_none());
    }
}
