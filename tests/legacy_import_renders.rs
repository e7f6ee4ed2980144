//! Imported legacy scenes rendered: camera rays against the legacy formula, pixels
//! against hand-computed colours (mirror depth, wide spot lights, a zero Phong exponent,
//! a spot light that lights nothing), and a RON round trip that renders the same.

mod common;

use common::legacy::{import_file, import_text, legacy_text, render_scene};
use common::trace;
use glam::{DAffine3, DVec2, DVec3, Vec3};
use raylab::scene::{Light, LightSource, parse_scene, scene_to_ron};
use raylab::trace::{PinholeCamera, Ray, RenderOptions, Term, TermSwitches, World, inspect_pixel};

#[test]
fn imported_camera_rays_are_the_legacy_rays() {
    // The legacy ray through pixel (u, v) is M (x, y, F) with x = -1 + (u + 0.5) 2/W and
    // y = -H/W + (v + 0.5) 2/W, M the camera's transform in file order.
    let cases: [(&str, DAffine3); 3] = [
        ("", DAffine3::IDENTITY),
        (
            "Rotate Y 30 Rotate Z -20 Translate 1 2 3",
            DAffine3::from_translation(DVec3::new(1.0, 2.0, 3.0))
                * DAffine3::from_rotation_z((-20f64).to_radians())
                * DAffine3::from_rotation_y(30f64.to_radians()),
        ),
        (
            "Scale 2 Rotate X 180 Rotate Y 90 Translate -4 0 1",
            DAffine3::from_translation(DVec3::new(-4.0, 0.0, 1.0))
                * DAffine3::from_rotation_y(90f64.to_radians())
                * DAffine3::from_rotation_x(180f64.to_radians())
                * DAffine3::from_scale(DVec3::splat(2.0)),
        ),
    ];
    let (width, height, focal) = (7u32, 5u32, 1.5);
    for (steps, world_from_camera) in cases {
        let text = format!(
            "Scene renderSize {width} {height} End Camera PinholeCamera {focal} {steps} End"
        );
        let scene = import_text(&text).scene;
        let camera = PinholeCamera::new(&scene.camera, width, height);
        for v in 0..height {
            for u in 0..width {
                let x = -1.0 + (f64::from(u) + 0.5) * 2.0 / f64::from(width);
                let y = -f64::from(height) / f64::from(width)
                    + (f64::from(v) + 0.5) * 2.0 / f64::from(width);
                let legacy = world_from_camera
                    .transform_vector3(DVec3::new(x, y, focal))
                    .normalize();
                let ray = camera.ray(DVec2::new(f64::from(u) + 0.5, f64::from(v) + 0.5));
                assert!(
                    (ray.dir - legacy).length() < 1e-12,
                    "{steps}: pixel ({u}, {v}): {} vs {legacy}",
                    ray.dir
                );
                assert!((ray.origin - world_from_camera.translation).length() < 1e-12);
            }
        }
    }
}

#[test]
fn a_sphere_at_a_known_place_lands_on_the_expected_pixel() {
    let scene = import_file("camera_pixel.txt").scene;
    // Hand-computed in the file: pixel (30, 10) looks at (3.625, 3.125, -7).
    let camera = PinholeCamera::new(&scene.camera, 40, 30);
    let centre = camera
        .project(DVec3::new(3.625, 3.125, -7.0))
        .expect("in front");
    assert!(
        (centre - DVec2::new(30.5, 10.5)).length() < 1e-9,
        "{centre}"
    );

    let image = render_scene(&scene);
    let magenta = Vec3::new(1.0, 0.0, 1.0);
    let background = Vec3::new(0.0, 0.5, 0.0);
    assert_eq!(image.get(30, 10), magenta);
    for (x, y) in [
        (29, 10),
        (31, 10),
        (30, 9),
        (30, 11),
        (9, 19),
        (0, 0),
        (39, 29),
    ] {
        assert_eq!(image.get(x, y), background, "pixel ({x}, {y})");
    }
    let lit = image.pixels.iter().filter(|&&p| p == magenta).count();
    assert_eq!(lit, 1);
}

#[test]
fn a_lit_sphere_matches_the_hand_computed_colour() {
    let scene = import_file("lit_sphere.txt").scene;
    let image = render_scene(&scene);
    let centre = image.get(10, 10);
    let expected = Vec3::new(0.8, 0.5, 0.35);
    assert!(
        (centre - expected).abs().max_element() < 1e-6,
        "{centre} expected {expected}"
    );
    assert_eq!(image.get(0, 0), Vec3::ZERO);
}

#[test]
fn ray_depth_counts_mirror_bounces() {
    let text = legacy_text("mirror.txt");
    let one_bounce = import_text(&text).scene;
    assert_eq!(one_bounce.render.max_depth, 1);
    let centre = render_scene(&one_bounce).get(10, 10);
    let expected = Vec3::new(0.3, 0.1, 0.2);
    assert!(
        (centre - expected).abs().max_element() < 1e-6,
        "{centre} expected {expected}"
    );

    let no_bounce = import_text(&text.replace("rayDepth 1", "rayDepth 0")).scene;
    assert_eq!(no_bounce.render.max_depth, 0);
    assert_eq!(render_scene(&no_bounce).get(10, 10), Vec3::ZERO);
}

#[test]
fn round_trip_through_ron_renders_identical_pixels() {
    for name in [
        "full.txt",
        "camera_pixel.txt",
        "lit_sphere.txt",
        "mirror.txt",
        "mirrors_depth_100.txt",
        "spot_without_angle.txt",
        "spot_wide.txt",
        "shininess_zero.txt",
        "camera_target.txt",
    ] {
        let imported = import_file(name).scene;
        let text = scene_to_ron(&imported);
        let loaded = parse_scene(&text).unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        assert_eq!(loaded, imported, "{name}");
        let direct = render_scene(&imported);
        let again = render_scene(&loaded);
        assert_eq!(direct.pixels, again.pixels, "{name}");
    }
}

#[test]
fn two_facing_perfect_mirrors_bounce_a_hundred_times_and_a_thousand() {
    // Hand-computed in the file: the centre ray and 100 mirror rays each add 0.001.
    let text = legacy_text("mirrors_depth_100.txt");
    for (depth, expected) in [(100u32, 0.101f64), (1000, 1.001)] {
        let mut scene =
            import_text(&text.replace("rayDepth 100", &format!("rayDepth {depth}"))).scene;
        assert_eq!(scene.render.max_depth, depth);
        // Imports carry the course's conventions, which clamp each ray's colour: 1.001
        // comes back as 1. The sums below are the contract's model, without them.
        let course = World::new(&scene).expect("valid");
        let clamped = inspect_pixel(&course, &RenderOptions::from_scene(&scene), 10, 10);
        assert!(
            (clamped.unclamped - DVec3::splat(expected.min(1.0)))
                .abs()
                .max_element()
                < 1e-12
        );
        scene.render.conventions = Default::default();
        let world = World::new(&scene).expect("valid");
        let report = inspect_pixel(&world, &RenderOptions::from_scene(&scene), 10, 10);
        assert_eq!(report.bounces.len(), depth as usize + 1);
        assert!(
            (report.unclamped - DVec3::splat(expected))
                .abs()
                .max_element()
                < 1e-12,
            "{}",
            report.unclamped
        );
        // Each bounce returns what it added plus what the next one brought back.
        for (index, bounce) in report.bounces.iter().enumerate() {
            let rays_left = (depth as usize - index + 1) as f64;
            assert!(
                (bounce.colour.x - 0.001 * rays_left).abs() < 1e-12,
                "{index}"
            );
        }
        let image = render_scene(&scene);
        assert_eq!(image.get(10, 10), report.unclamped.as_vec3());
    }
}

/// A ray straight down onto the floor at (x, 0, 0).
fn down_at(x: f64) -> Ray {
    Ray::new(DVec3::new(x, 5.0, 0.0), DVec3::NEG_Y)
}

#[test]
fn spot_lights_wider_than_ninety_degrees_light_what_their_angle_says() {
    // Hand-computed in the file: lit colour 2 / (x^2 + 1)^1.5; at 120 degrees only
    // |x| >= sqrt(3) is lit, at 180 degrees everything.
    let lit = |x: f64| 2.0 / (x * x + 1.0f64).powf(1.5);
    let text = legacy_text("spot_wide.txt");
    // The contract's model: imports carry the course's each-ray clamp, which would cut
    // the lit colour at 1 (checked at the end).
    let contract = |mut scene: raylab::scene::Scene| {
        scene.render.conventions = Default::default();
        scene
    };
    let wide = contract(import_text(&text).scene);
    let all = contract(import_text(&text.replace("Angle 120", "Angle 180")).scene);
    for (x, at_120) in [
        (0.0, false),
        (1.0, false),
        (1.7, false),
        (1.75, true),
        (2.5, true),
    ] {
        let expected = |on: bool| DVec3::splat(if on { lit(x) } else { 0.0 });
        let colour = trace(&wide, down_at(x), TermSwitches::ALL_ON);
        assert!(
            (colour - expected(at_120)).abs().max_element() < 1e-12,
            "120, x = {x}: {colour}"
        );
        let colour = trace(&all, down_at(x), TermSwitches::ALL_ON);
        assert!(
            (colour - expected(true)).abs().max_element() < 1e-12,
            "180, x = {x}: {colour}"
        );
    }
    let course = import_text(&text.replace("Angle 120", "Angle 180")).scene;
    assert_eq!(
        trace(&course, down_at(0.0), TermSwitches::ALL_ON),
        DVec3::ONE
    );
}

#[test]
fn a_zero_phong_exponent_gives_one_wherever_r_dot_v_is_positive() {
    let scene = import_file("shininess_zero.txt").scene;
    let specular = TermSwitches::ALL_ON.with_solo(Some(Term::Specular));
    // At the floor's centre L = 1 and r = +y: views with r.v = 1, 0.32 and 0.02 all see
    // ks * L * 1 = 1; with exponent 1 they would see r.v itself.
    for eye in [
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(3.0, 1.0, 0.0),
        DVec3::new(0.0, 0.1, -5.0),
    ] {
        let ray = Ray::new(eye, -eye.normalize());
        assert!(
            (trace(&scene, ray, specular) - DVec3::ONE)
                .abs()
                .max_element()
                < 1e-12,
            "{eye}"
        );
        assert_eq!(
            trace(&scene, ray, TermSwitches::ALL_ON),
            trace(&scene, ray, specular)
        );
    }
    // At (1, 0, 0), r = (1, 1, 0) / sqrt 2: a view from the far side has r.v < 0 and
    // sees no specular, although the light is in front of the surface.
    let p = DVec3::new(1.0, 0.0, 0.0);
    let to_eye = DVec3::new(-1.0, 0.1, 0.0).normalize();
    let ray = Ray::new(p + 5.0 * to_eye, -to_eye);
    assert_eq!(trace(&scene, ray, specular), DVec3::ZERO);
}

#[test]
fn a_spot_light_without_angle_lights_nothing() {
    let scene = import_file("spot_without_angle.txt").scene;
    let without_spot = {
        let mut scene = scene.clone();
        scene
            .lights
            .retain(|light| !matches!(light, Light::Spot { .. }));
        scene
    };
    let image = render_scene(&scene);
    assert_eq!(image.pixels, render_scene(&without_spot).pixels);
    // The comparison can tell: with its intensity back, the spot lights the floor.
    let mut lit = scene.clone();
    if let Some(Light::Spot {
        source: LightSource { intensity, .. },
        ..
    }) = lit.lights.get_mut(1)
    {
        *intensity = 1.0;
    }
    assert_ne!(render_scene(&lit).pixels, image.pixels);
    assert!(
        image.get(10, 10).max_element() > 0.0,
        "the point light still lights"
    );
}
