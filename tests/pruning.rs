//! Pruned renders (issue 50): rays left out only where they cannot change a written
//! byte. The PNG of `render_pruned` is the full trace's byte for byte on every example
//! scene and on random scenes of glass and mirrors (depths 1 to 12, the contract's and
//! the course's conventions, 1 and 16 samples); it traces fewer rays on glass.ron; and
//! the pixel inspector still shows every ray.

mod common;

use std::collections::BTreeMap;

use common::*;
use glam::{DVec2, DVec3};
use raylab::scene::{
    ClampConvention, Conventions, Light, Material, MirrorConvention, Quantise, Scene, Shape,
    parse_scene,
};
use raylab::trace::{
    NoRecorder, PRUNE_BUDGET, PinholeCamera, RayCounts, RenderOptions, RenderProgress,
    SubtreeBound, TermSwitches, Tracer, View, World, inspect_pixel, render, render_pruned,
};

/// A budget forty times the render's: far more rays left out and pixels traced again,
/// so the retrace is exercised hard (the bytes must still be the full trace's).
const LARGE_BUDGET: f64 = 4.0 / 255.0;

/// What one comparison saw.
#[derive(Default)]
struct Seen {
    pixels: u64,
    pruned: u64,
    retraced: u64,
}

/// Renders `scene` in full and pruned with `budget` at `width` x `height` and `spp`,
/// asserts the PNGs are identical, and adds what the pruning did to `seen`.
fn assert_same_png(
    name: &str,
    scene: &Scene,
    size: (u32, u32),
    spp: u32,
    budget: f64,
    seen: &mut Seen,
) {
    let world = World::new(scene).unwrap();
    let options = RenderOptions {
        width: size.0,
        height: size.1,
        samples_per_pixel: spp,
        ..RenderOptions::from_scene(scene)
    };
    let progress = RenderProgress::default();
    let (full, _) = render(&world, &options, &progress).unwrap();
    let pruned = render_pruned(&world, &options, budget, &progress).unwrap();
    let quantise = scene.render.conventions.quantise;
    let image = pruned.sums.average(spp);
    if image.png_bytes_as(quantise) != full.png_bytes_as(quantise) {
        let differing = (0..full.pixels.len())
            .filter(|&i| {
                let bytes =
                    |p: glam::Vec3| p.to_array().map(|c| raylab::trace::encode(c, quantise));
                bytes(image.pixels[i]) != bytes(full.pixels[i])
            })
            .count();
        panic!(
            "{name} ({:?}, {spp} spp, budget {:.2} steps): {differing} pixels differ from the \
             full trace ({} pruned, {} traced again)",
            scene.render.conventions,
            budget * 255.0,
            pruned.pruned_pixels,
            pruned.retraced_pixels
        );
    }
    seen.pixels += u64::from(size.0 * size.1);
    seen.pruned += pruned.pruned_pixels;
    seen.retraced += pruned.retraced_pixels;
}

/// The contract's conventions, the course's, and the two mixed.
fn conventions_sets() -> [Conventions; 4] {
    [
        Conventions::default(),
        Conventions::COURSE,
        Conventions {
            mirror: MirrorConvention::Blend,
            clamp: ClampConvention::EachRay,
            quantise: Quantise::Round,
        },
        Conventions {
            mirror: MirrorConvention::Blend,
            clamp: ClampConvention::Pixel,
            quantise: Quantise::Truncate,
        },
    ]
}

#[test]
fn every_example_scene_writes_the_full_traces_png_pruned() {
    let mut seen = Seen::default();
    for (name, text) in raylab::scene::examples::EXAMPLE_SCENES {
        let mut scene = parse_scene(text).unwrap();
        for conventions in [Conventions::default(), Conventions::COURSE] {
            scene.render.conventions = conventions;
            for spp in [1, 4] {
                for budget in [PRUNE_BUDGET, LARGE_BUDGET] {
                    assert_same_png(name, &scene, (48, 36), spp, budget, &mut seen);
                }
            }
        }
    }
    assert!(
        seen.pruned > 0 && seen.retraced > 0,
        "pruned {}, retraced {}",
        seen.pruned,
        seen.retraced
    );
}

/// A random scene of glass, mirrors and matte objects on a floor, lit from above.
fn random_scene(seed: u64) -> Scene {
    let mut next = unit_random(seed);
    let mut range = |lo: f64, hi: f64| lo + (hi - lo) * next();
    let colour = |range: &mut dyn FnMut(f64, f64) -> f64, lo: f64, hi: f64| {
        DVec3::new(range(lo, hi), range(lo, hi), range(lo, hi))
    };
    let glass = Material {
        ambient: colour(&mut range, 0.0, 0.05),
        diffuse: colour(&mut range, 0.0, 0.2),
        specular: colour(&mut range, 0.0, 1.0),
        shininess: range(1.0, 400.0),
        mirror: colour(&mut range, 0.0, 0.3),
        transmission: colour(&mut range, 0.5, 1.0),
        ior: range(1.1, 1.9),
    };
    let mirror = Material {
        ambient: colour(&mut range, 0.0, 0.1),
        diffuse: colour(&mut range, 0.0, 0.3),
        specular: colour(&mut range, 0.0, 0.5),
        shininess: range(1.0, 100.0),
        mirror: colour(&mut range, 0.3, 1.0),
        ..Material::default()
    };
    let matte = Material {
        ambient: colour(&mut range, 0.0, 0.3),
        diffuse: colour(&mut range, 0.2, 0.9),
        specular: colour(&mut range, 0.0, 0.5),
        shininess: range(1.0, 60.0),
        mirror: colour(&mut range, 0.0, 0.2),
        ..Material::default()
    };
    let mut scene = bare_scene(matte.clone());
    scene.materials = BTreeMap::from([
        ("m".to_owned(), matte),
        ("glass".to_owned(), glass),
        ("mirror".to_owned(), mirror),
    ]);
    scene.camera.position = DVec3::new(0.0, 2.0, 6.0);
    scene.camera.look_at = DVec3::new(0.0, 0.8, 0.0);
    scene.objects.push(floor(0.0, 8.0));
    let shapes = [Shape::Sphere, Shape::Cube, Shape::Cylinder, Shape::Sphere];
    let count = 2 + (range(0.0, 3.0) as usize);
    for i in 0..count {
        let shape = shapes[range(0.0, 4.0) as usize % 4].clone();
        let translate = DVec3::new(range(-1.8, 1.8), range(0.4, 1.6), range(-1.5, 1.5));
        let rotate = DVec3::new(range(0.0, 90.0), range(0.0, 90.0), 0.0);
        let scale = DVec3::splat(range(0.3, 0.9));
        let mut o = object(shape, translate, rotate, scale);
        o.name = format!("object {i}");
        o.material = ["m", "glass", "mirror", "glass"][range(0.0, 4.0) as usize % 4].to_owned();
        scene.objects.push(o);
    }
    scene.lights = vec![
        Light::Ambient {
            colour: DVec3::splat(range(0.05, 0.4)),
            intensity: 1.0,
        },
        point_light(
            DVec3::new(range(-4.0, 4.0), range(5.0, 8.0), range(-2.0, 6.0)),
            range(10.0, 60.0),
        ),
        Light::Directional {
            direction: DVec3::new(range(-0.5, 0.5), -1.0, range(-0.5, 0.5)),
            colour: colour(&mut range, 0.1, 0.6),
            intensity: 1.0,
        },
    ];
    scene.render.background = colour(&mut range, 0.0, 0.3);
    scene
}

#[test]
fn random_glass_and_mirror_scenes_write_the_full_traces_png_pruned() {
    let mut seen = [Seen::default(), Seen::default()];
    let sets = conventions_sets();
    for seed in 0..24u64 {
        let mut scene = random_scene(seed + 1);
        // Depths 1 to 12, every set of conventions, 1 and 16 samples.
        scene.render.max_depth = 1 + (seed % 12) as u32;
        scene.render.conventions = sets[(seed % 4) as usize];
        let spp = if (seed / 4) % 2 == 0 { 1 } else { 16 };
        for (budget, seen) in [PRUNE_BUDGET, LARGE_BUDGET].into_iter().zip(&mut seen) {
            assert_same_png(&format!("seed {seed}"), &scene, (20, 15), spp, budget, seen);
        }
    }
    for (seen, budget) in seen.iter().zip(["the render's", "the large"]) {
        assert!(seen.pruned > 0, "{budget} budget pruned nothing");
    }
    assert!(
        seen[1].retraced > 0,
        "the large budget traced nothing again"
    );
}

#[test]
fn pruning_traces_fewer_rays_on_glass() {
    let scene = parse_scene(include_str!("../scenes/glass.ron")).unwrap();
    let world = World::new(&scene).unwrap();
    let options = RenderOptions {
        width: 200,
        height: 150,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&scene)
    };
    let progress = RenderProgress::default();
    let (full, full_rays) = render(&world, &options, &progress).unwrap();
    let pruned = render_pruned(&world, &options, PRUNE_BUDGET, &progress).unwrap();
    let rays = pruned.sums.rays;
    assert!(
        rays.total() < full_rays.total(),
        "pruned {rays:?} against full {full_rays:?}"
    );
    assert!(rays.reflection + rays.transmission < full_rays.reflection + full_rays.transmission);
    assert_eq!(
        rays.primary,
        full_rays.primary + pruned.retraced_pixels,
        "one sample each"
    );
    let quantise = scene.render.conventions.quantise;
    assert_eq!(
        pruned.sums.average(1).png_bytes_as(quantise),
        full.png_bytes_as(quantise)
    );
}

/// The path weight of each ray of a report: the product of the km and kt factors from
/// the camera ray down to it.
fn path_weights(report: &raylab::trace::PixelReport) -> Vec<DVec3> {
    let mut weights: Vec<DVec3> = Vec::with_capacity(report.bounces.len());
    for bounce in &report.bounces {
        let weight = match bounce.from {
            None => DVec3::ONE,
            Some((parent, branch)) => {
                let parent_bounce = &report.bounces[parent];
                let k = if branch.is_transmitted() {
                    parent_bounce.transmission.unwrap().0
                } else {
                    parent_bounce.reflection.unwrap().0
                };
                weights[parent] * k
            }
        };
        weights.push(weight);
    }
    weights
}

#[test]
fn the_inspector_shows_the_rays_a_pruned_render_leaves_out() {
    let scene = parse_scene(include_str!("../scenes/glass.ron")).unwrap();
    let world = World::new(&scene).unwrap();
    let options = RenderOptions {
        width: 80,
        height: 60,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&scene)
    };
    // A render with pruning first: the inspector keeps no state of it either way.
    render_pruned(&world, &options, PRUNE_BUDGET, &RenderProgress::default()).unwrap();
    let bound = SubtreeBound::new(&world).unwrap();
    let camera = PinholeCamera::new(&world.camera, 80, 60);
    let tracer = Tracer::new(&world, TermSwitches::ALL_ON, View::Beauty);
    let mut prunable_shown = 0;
    for (px, py) in (0..60).flat_map(|y| (0..80).map(move |x| (x, y))) {
        let report = inspect_pixel(&world, &options, px, py);
        // Every ray of the full trace of that ray is in the report.
        let mut rays = RayCounts::default();
        let ray = camera.ray(DVec2::new(f64::from(px) + 0.5, f64::from(py) + 0.5));
        tracer.trace_primary(&ray, &mut rays, &mut NoRecorder);
        assert_eq!(
            report.bounces.len() as u64,
            rays.primary + rays.reflection + rays.transmission
        );
        let weights = path_weights(&report);
        prunable_shown += report
            .bounces
            .iter()
            .zip(&weights)
            .filter(|&(b, &w)| {
                b.depth > 0 && bound.of(w, b.depth).cmple(DVec3::splat(PRUNE_BUDGET)).all()
            })
            .count();
    }
    assert!(
        prunable_shown > 0,
        "no ray the pruning would leave out was found"
    );
}
