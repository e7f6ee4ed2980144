//! Sphere lights: a light half hidden behind an edge is seen by half its shadow rays; the
//! shadow mask and the lit picture scale by that fraction; a light of radius 0 is the
//! point light bit for bit; each pixel sample aims at other points of the light, so many
//! one-ray samples average to what many rays at one point give.

use glam::DVec3;
use raylab::scene::{Scene, parse_scene};
use raylab::trace::{
    RenderOptions, RenderProgress, Term, TermSwitches, View, World, inspect_pixel, render,
    traced_rays,
};

/// A floor at y = 0 seen from the side, under the slab; a light of `radius` and `samples` at (0, 5, 0); a
/// thin slab at y = 2.5 covering x < `edge`, so the floor's origin sees the light's disc
/// cut by the line x = `edge` * 2.
fn scene(radius: f64, samples: u32, edge: f64, spp: u32) -> Scene {
    parse_scene(&format!(
        r#"Scene(
            camera: (position: (0.0, 1.5, 3.0), look_at: (0.0, 0.0, 0.0), fov_deg: 30.0, width: 41, height: 41),
            render: (max_depth: 1, background: (0.0, 0.0, 0.0), samples_per_pixel: {spp}),
            materials: {{ "matte": (diffuse: (0.8, 0.8, 0.8), specular: (0.0, 0.0, 0.0), shininess: 1.0) }},
            lights: [Point(position: (0.0, 5.0, 0.0), colour: (1.0, 1.0, 1.0), intensity: 25.0, radius: {radius:?}, samples: {samples})],
            objects: [
                (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (20.0, 20.0, 1.0)), material: "matte"),
                (name: "edge", shape: Cube, transform: (translate: ({:?}, 2.5, 0.0), scale: (10.0, 0.01, 10.0)), material: "matte"),
            ],
        )"#,
        edge - 10.0
    ))
    .unwrap()
}

fn options(scene: &Scene, switches: TermSwitches, view: View) -> RenderOptions {
    RenderOptions {
        switches,
        view,
        ..RenderOptions::from_scene(scene)
    }
}

/// The centre pixel's light record: its visibility and the colour.
fn centre(scene: &Scene) -> ((f64, u32), DVec3) {
    let world = World::new(scene).unwrap();
    let report = inspect_pixel(
        &world,
        &options(scene, TermSwitches::ALL_ON, View::Beauty),
        20,
        20,
    );
    let hit = report.bounces[0]
        .hit
        .expect("the centre ray meets the floor");
    assert!(hit.p.length() < 1e-9, "the centre pixel sees the origin");
    (report.bounces[0].lights[0].visibility, report.clamped)
}

#[test]
fn a_sphere_light_half_behind_an_edge_is_half_seen() {
    let (visibility, half_lit) = centre(&scene(1.0, 256, 0.0, 1));
    assert_eq!(visibility.1, 256, "every ray counted");
    assert!(
        (visibility.0 - 0.5).abs() < 0.03,
        "half of the disc is hidden: {visibility:?}"
    );
    // Moved so the edge hides none or all of the disc (its shadow on the disc's plane is
    // twice as far from the centre: the slab is half way up).
    let (clear, lit) = centre(&scene(1.0, 256, -0.6, 1));
    assert_eq!(clear.0, 1.0);
    let (hidden, dark) = centre(&scene(1.0, 256, 0.6, 1));
    assert_eq!(hidden.0, 0.0);
    assert_eq!(dark, DVec3::ZERO);
    // The lit colour is the fraction of the unshadowed one.
    let expected = lit * visibility.0;
    assert!(
        (half_lit - expected).abs().max_element() < 1e-12,
        "{half_lit} vs {expected}"
    );
    // Every ray is in the ray list, each from the point to the light's disc.
    let world = World::new(&scene(1.0, 16, 0.0, 1)).unwrap();
    let report = inspect_pixel(
        &world,
        &options(&scene(1.0, 16, 0.0, 1), TermSwitches::ALL_ON, View::Beauty),
        20,
        20,
    );
    let shadows: Vec<_> = traced_rays(&report)
        .into_iter()
        .filter(|r| r.light == Some(0))
        .collect();
    assert_eq!(shadows.len(), 16);
    for ray in &shadows {
        let end = ray.at(ray.t_max.unwrap());
        assert!((end.y - 5.0).abs() < 1e-6 && end.length() < 5.0 + 1.0);
    }
    let blocked = shadows.iter().filter(|r| r.blocked_by.is_some()).count();
    assert!((4..=12).contains(&blocked), "{blocked} of 16 blocked");
}

#[test]
fn radius_zero_is_the_point_light_bit_for_bit() {
    let with_field = scene(0.0, 8, 0.0, 4);
    let mut plain = with_field.clone();
    plain.lights[0] = parse_scene(
        r#"Scene(camera: (position: (0.0, 1.5, 3.0), look_at: (0.0, 0.0, 0.0), fov_deg: 30.0, width: 41, height: 41),
                 lights: [Point(position: (0.0, 5.0, 0.0), colour: (1.0, 1.0, 1.0), intensity: 25.0)], objects: [])"#,
    )
    .unwrap()
    .lights[0]
        .clone();
    let image = |scene: &Scene| {
        let world = World::new(scene).unwrap();
        let options = options(scene, TermSwitches::ALL_ON, View::Beauty);
        render(&world, &options, &RenderProgress::default())
            .unwrap()
            .0
    };
    assert_eq!(image(&with_field).pixels, image(&plain).pixels);
}

#[test]
fn pixel_samples_aim_at_other_points_so_the_picture_converges_to_the_soft_shadow() {
    // One shadow ray per point over 64 pixel samples against 64 rays per point: the
    // penumbra's mean agrees, and the one-ray picture is not a hard shadow.
    let mean_mask = |samples: u32, spp: u32| {
        let scene = scene(1.0, samples, 0.0, spp);
        let world = World::new(&scene).unwrap();
        let solo = TermSwitches::ALL_ON.with_solo(Some(Term::Shadows));
        let options = options(&scene, solo, View::Beauty);
        let image = render(&world, &options, &RenderProgress::default())
            .unwrap()
            .0;
        // The middle rows: the floor near the origin, across the penumbra.
        let row: Vec<f32> = (0..41).map(|x| image.get(x, 20).x).collect();
        let grey = row.iter().filter(|v| **v > 0.02 && **v < 0.98).count();
        (row.iter().sum::<f32>() / 41.0, grey)
    };
    let (one_ray, grey_one) = mean_mask(1, 64);
    let (many_rays, grey_many) = mean_mask(64, 1);
    assert!(
        (one_ray - many_rays).abs() < 0.03,
        "{one_ray} vs {many_rays}"
    );
    assert!(
        grey_one >= 5 && grey_many >= 5,
        "{grey_one}, {grey_many} grey pixels"
    );
}

#[test]
fn bad_radius_and_samples_are_refused_with_a_clear_message() {
    for (radius, samples, message) in [
        ("-1.0", "4", "radius is -1; it cannot be negative"),
        ("0.5", "0", "samples is 0"),
    ] {
        let text = format!(
            r#"Scene(camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 30.0, width: 8, height: 8),
                     lights: [Point(position: (0.0, 5.0, 0.0), colour: (1.0, 1.0, 1.0), intensity: 1.0, radius: {radius}, samples: {samples})], objects: [])"#
        );
        let error = parse_scene(&text).unwrap_err().to_string();
        assert!(error.contains(message), "{error}");
    }
}
