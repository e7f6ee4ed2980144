//! The BVH finds exactly what the flat list finds.

mod common;

use common::*;
use glam::DVec3;
use proptest::prelude::*;
use raylab::scene::{Material, Shape};
use raylab::trace::{Acceleration, Ray, World};

fn crowded_scene(seed: u64, count: usize) -> raylab::scene::Scene {
    let mut next = unit_random(seed);
    let mut scene = bare_scene(Material {
        diffuse: DVec3::ONE,
        ..Material::default()
    });
    scene.objects.push(floor(-1.0, 30.0));
    for i in 0..count {
        let shape = &Shape::ALL[i % 5].clone();
        let translate = DVec3::new(next() * 20.0 - 10.0, next() * 4.0, next() * 20.0 - 10.0);
        let rotate = DVec3::new(next() * 360.0, next() * 360.0, next() * 360.0);
        let scale = DVec3::new(0.2 + next(), 0.2 + next(), 0.2 + next());
        scene
            .objects
            .push(object(shape.clone(), translate, rotate, scale));
    }
    scene
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn bvh_and_flat_list_agree(seed in any::<u64>(), origin in (-12.0..12.0f64, 0.0..8.0f64, -12.0..12.0f64), target in (-10.0..10.0f64, -1.0..4.0f64, -10.0..10.0f64)) {
        let scene = crowded_scene(seed % 8, 60);
        let mut flat = World::new(&scene).unwrap();
        flat.set_acceleration(Acceleration::Flat);
        let mut bvh = World::new(&scene).unwrap();
        bvh.set_acceleration(Acceleration::Bvh);
        let origin = DVec3::new(origin.0, origin.1, origin.2);
        let ray = Ray::new(origin, (DVec3::new(target.0, target.1, target.2) - origin).normalize_or(DVec3::Y));
        let (a, b) = (flat.intersect(&ray, f64::INFINITY), bvh.intersect(&ray, f64::INFINITY));
        prop_assert_eq!(a.map(|h| (h.object, h.t)), b.map(|h| (h.object, h.t)));
        prop_assert_eq!(a.map(|h| h.p), b.map(|h| h.p));
        // The same blocker: the first in scene order, not the first the tree meets.
        for limit in [a.map_or(50.0, |h| h.t * 0.999), 50.0] {
            prop_assert_eq!(flat.occluder(&ray, limit), bvh.occluder(&ray, limit));
        }
    }
}

/// The crowd's cubes stand on the floor, so rays meet some faces at exactly the floor's
/// `t`: the tree must give such ties to the earlier object, as the list does.
#[test]
fn ties_and_blockers_follow_scene_order() {
    let scene = raylab::bench::crossover::crowd(32);
    let mut flat = World::new(&scene).unwrap();
    flat.set_acceleration(Acceleration::Flat);
    let mut bvh = World::new(&scene).unwrap();
    bvh.set_acceleration(Acceleration::Bvh);
    let mut next = unit_random(12345);
    let mut point = || DVec3::new(next() * 10.0 - 5.0, next() * 2.0, next() * 10.0 - 5.0);
    for _ in 0..20_000 {
        let origin = point();
        let ray = Ray::new(origin, (point() - origin).normalize_or(DVec3::Y));
        let (a, b) = (flat.intersect(&ray, 20.0), bvh.intersect(&ray, 20.0));
        assert_eq!(a.map(|h| (h.object, h.t)), b.map(|h| (h.object, h.t)));
        assert_eq!(flat.occluder(&ray, 20.0), bvh.occluder(&ray, 20.0));
    }
}

/// 60 objects: culling covers them all; 80: tile queries list the first 64 and walk a
/// tree over the rest.
#[test]
fn large_scenes_build_a_bvh_and_render_the_same_picture() {
    for count in [60, 80] {
        same_picture_with_and_without_bvh(count);
    }
}

fn same_picture_with_and_without_bvh(count: usize) {
    use raylab::trace::{RenderOptions, RenderProgress, render};
    let mut scene = crowded_scene(3, count);
    scene
        .lights
        .push(point_light(DVec3::new(0.0, 10.0, 5.0), 100.0));
    scene.camera.position = DVec3::new(0.0, 6.0, 18.0);
    let auto = World::new(&scene).unwrap();
    let mut flat = auto.clone();
    flat.set_acceleration(Acceleration::Flat);
    let options = RenderOptions {
        width: 64,
        height: 48,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&scene)
    };
    let progress = RenderProgress::default();
    let a = render(&auto, &options, &progress).unwrap().0;
    let b = render(&flat, &options, &progress).unwrap().0;
    assert_eq!(a.to_rgba8(), b.to_rgba8());
}
