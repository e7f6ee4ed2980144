//! The lighting model term by term, against values computed by hand.

mod common;

use common::*;
use glam::DVec3;
use raylab::scene::{Light, LightSource, Material, Shape};
use raylab::trace::{Ray, Term, TermSwitches};

fn unit_sphere_scene(material: Material) -> raylab::scene::Scene {
    let mut scene = bare_scene(material);
    scene
        .objects
        .push(object(Shape::Sphere, DVec3::ZERO, DVec3::ZERO, DVec3::ONE));
    scene
}

/// The ray from the camera at (0, 0, 5) to the sphere's pole (0, 0, 1).
fn ray_to_pole() -> Ray {
    Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z)
}

#[test]
fn ambient_is_ka_times_the_sum_of_ambient_lights() {
    let mut scene = unit_sphere_scene(Material {
        ambient: DVec3::new(0.5, 0.25, 1.0),
        ..Material::default()
    });
    scene.lights.push(Light::Ambient {
        colour: DVec3::new(0.2, 0.4, 0.1),
        intensity: 1.0,
    });
    scene.lights.push(Light::Ambient {
        colour: DVec3::ONE,
        intensity: 0.5,
    });
    let colour = trace(&scene, ray_to_pole(), TermSwitches::ALL_ON);
    assert_colour(colour, DVec3::new(0.5 * 0.7, 0.25 * 0.9, 1.0 * 0.6));
}

#[test]
fn diffuse_and_specular_for_an_oblique_point_light() {
    // Hit p = (0,0,1), n = v = +z. Light at p + (0, 3, 4): d = 5, l = (0, 0.6, 0.8).
    // L = 50 / 25 = 2. n.l = 0.8. r = 2 (n.l) n - l = (0, -0.6, 0.8), r.v = 0.8.
    let material = Material {
        diffuse: DVec3::new(0.5, 0.25, 0.125),
        specular: DVec3::new(0.3, 0.3, 0.3),
        shininess: 3.0,
        ..Material::default()
    };
    let mut scene = unit_sphere_scene(material);
    scene
        .lights
        .push(point_light(DVec3::new(0.0, 3.0, 5.0), 50.0));
    let colour = trace(&scene, ray_to_pole(), TermSwitches::ALL_ON);
    let diffuse = DVec3::new(0.5, 0.25, 0.125) * 2.0 * 0.8;
    let specular = DVec3::splat(0.3 * 2.0 * 0.8f64.powi(3));
    assert_colour(colour, diffuse + specular);
    let only_diffuse = TermSwitches::ALL_ON.with_solo(Some(Term::Diffuse));
    assert_colour(trace(&scene, ray_to_pole(), only_diffuse), diffuse);
    let only_specular = TermSwitches::ALL_ON.with_solo(Some(Term::Specular));
    assert_colour(trace(&scene, ray_to_pole(), only_specular), specular);
}

#[test]
fn a_zero_exponent_makes_the_lobe_one_where_r_dot_v_is_positive() {
    // The oblique light above (L = 2, r.v = 0.8) with s = 0: ks * L * 0.8^0 = 0.3 * 2.
    let mut scene = unit_sphere_scene(Material {
        specular: DVec3::splat(0.3),
        shininess: 0.0,
        ..Material::default()
    });
    scene
        .lights
        .push(point_light(DVec3::new(0.0, 3.0, 5.0), 50.0));
    assert_colour(
        trace(&scene, ray_to_pole(), TermSwitches::ALL_ON),
        DVec3::splat(0.6),
    );
}

#[test]
fn the_side_facing_away_from_the_light_stays_black_for_every_exponent() {
    for shininess in [0.0, 0.5, 1.0, 2.0] {
        let material = Material {
            diffuse: DVec3::splat(0.8),
            specular: DVec3::splat(0.8),
            shininess,
            ..Material::default()
        };
        let mut scene = unit_sphere_scene(material);
        // The light is behind the sphere: n.l = -1 at the pole the camera sees.
        scene
            .lights
            .push(point_light(DVec3::new(0.0, 0.0, -5.0), 100.0));
        scene.lights.push(Light::Directional {
            direction: DVec3::new(0.0, 0.0, 1.0),
            colour: DVec3::ONE,
            intensity: 1.0,
        });
        let mut no_shadows = TermSwitches::ALL_ON;
        no_shadows.set(Term::Shadows, false);
        for switches in [TermSwitches::ALL_ON, no_shadows] {
            assert_eq!(
                trace(&scene, ray_to_pole(), switches),
                DVec3::ZERO,
                "s = {shininess}"
            );
        }
    }
}

#[test]
fn negative_r_dot_v_adds_no_specular_even_with_a_fractional_exponent() {
    // A floor seen at 45 degrees from (0, -4, 4)-ish; light low on the viewer's side:
    // n = +z, v = (0, -1, 1)/sqrt2, l = (0, -0.8, 0.6): n.l = 0.6 > 0 but r.v < 0.
    for shininess in [0.0, 0.5, 1.0, 2.0] {
        let material = Material {
            specular: DVec3::ONE,
            shininess,
            ..Material::default()
        };
        let mut scene = bare_scene(material);
        scene.objects.push(object(
            Shape::Plane,
            DVec3::ZERO,
            DVec3::ZERO,
            DVec3::splat(10.0),
        ));
        scene.lights.push(Light::Directional {
            direction: -DVec3::new(0.0, -0.8, 0.6),
            colour: DVec3::ONE,
            intensity: 1.0,
        });
        let ray = Ray::new(
            DVec3::new(0.0, -4.0, 4.0),
            DVec3::new(0.0, 1.0, -1.0).normalize(),
        );
        let colour = trace(&scene, ray, TermSwitches::ALL_ON);
        assert_eq!(colour, DVec3::ZERO, "s = {shininess}");
    }
}

#[test]
fn directional_light_has_no_falloff() {
    let material = Material {
        diffuse: DVec3::ONE,
        ..Material::default()
    };
    let mut scene = unit_sphere_scene(material);
    scene.lights.push(Light::Directional {
        direction: DVec3::new(0.0, 0.0, -2.0),
        colour: DVec3::new(0.5, 0.5, 0.5),
        intensity: 1.5,
    });
    assert_colour(
        trace(&scene, ray_to_pole(), TermSwitches::ALL_ON),
        DVec3::splat(0.75),
    );
}

/// A floor at y = 0 seen straight down from above at (x, 0, 0).
fn floor_scene() -> raylab::scene::Scene {
    let mut scene = bare_scene(Material {
        diffuse: DVec3::ONE,
        ..Material::default()
    });
    scene.objects.push(floor(0.0, 20.0));
    scene
}

fn ray_down_at(x: f64) -> Ray {
    Ray::new(DVec3::new(x, 10.0, 0.0), -DVec3::Y)
}

#[test]
fn spot_light_lights_inside_its_cone_only() {
    let mut scene = floor_scene();
    // 4 units up, 30 degree half-angle: the lit disc has radius 4 tan 30 = 2.309.
    scene.lights.push(Light::Spot {
        position: DVec3::new(0.0, 4.0, 0.0),
        direction: -DVec3::Y,
        angle_deg: 30.0,
        source: LightSource::point(DVec3::ONE, 20.0),
    });
    // At x = 2: d^2 = 20, n.l = 4 / sqrt(20).
    let expected = 20.0 / 20.0 * (4.0 / 20f64.sqrt());
    assert_colour(
        trace(&scene, ray_down_at(2.0), TermSwitches::ALL_ON),
        DVec3::splat(expected),
    );
    assert_eq!(
        trace(&scene, ray_down_at(2.4), TermSwitches::ALL_ON),
        DVec3::ZERO
    );
    assert_colour(
        trace(&scene, ray_down_at(0.0), TermSwitches::ALL_ON),
        DVec3::splat(20.0 / 16.0),
    );
}

#[test]
fn a_180_degree_spot_lights_every_direction_even_straight_behind_it() {
    // Pointing up, 4 units above the floor: the floor point below is straight behind.
    let spot = |angle_deg: f64| Light::Spot {
        position: DVec3::new(0.0, 4.0, 0.0),
        direction: DVec3::Y,
        angle_deg,
        source: LightSource::point(DVec3::ONE, 16.0),
    };
    let mut scene = floor_scene();
    scene.lights.push(spot(180.0));
    for x in [0.0f64, 1e-9, 3.0] {
        let expected = 16.0 / (16.0 + x * x) * (4.0 / (16.0 + x * x).sqrt());
        assert_colour(
            trace(&scene, ray_down_at(x), TermSwitches::ALL_ON),
            DVec3::splat(expected),
        );
    }
    // Just under 180 degrees, straight behind is outside the cone.
    scene.lights[0] = spot(179.9);
    assert_eq!(
        trace(&scene, ray_down_at(0.0), TermSwitches::ALL_ON),
        DVec3::ZERO
    );
}

#[test]
fn every_light_kind_is_shadowed_by_a_blocker_and_unshadowed_without_shadows() {
    let lights = [
        point_light(DVec3::new(0.0, 6.0, 0.0), 36.0),
        Light::Directional {
            direction: -DVec3::Y,
            colour: DVec3::ONE,
            intensity: 1.0,
        },
        Light::Spot {
            position: DVec3::new(0.0, 6.0, 0.0),
            direction: -DVec3::Y,
            angle_deg: 20.0,
            source: LightSource::point(DVec3::ONE, 36.0),
        },
    ];
    for light in lights {
        let mut scene = floor_scene();
        scene.lights.push(light.clone());
        let lit = trace(&scene, ray_down_at(0.0), TermSwitches::ALL_ON);
        assert_colour(lit, DVec3::ONE);
        // A blocker between the floor point and the light; the camera ray starts below it.
        scene.objects.push(object(
            Shape::Cube,
            DVec3::new(0.0, 3.0, 0.0),
            DVec3::ZERO,
            DVec3::splat(0.5),
        ));
        let below_blocker = Ray::new(DVec3::new(0.0, 1.0, 0.0), -DVec3::Y);
        assert_eq!(
            trace(&scene, below_blocker, TermSwitches::ALL_ON),
            DVec3::ZERO,
            "{light:?}"
        );
        let mut no_shadows = TermSwitches::ALL_ON;
        no_shadows.set(Term::Shadows, false);
        assert_colour(trace(&scene, below_blocker, no_shadows), DVec3::ONE);
    }
}

#[test]
fn a_light_just_above_a_surface_is_not_shadowed_by_it() {
    let mut scene = floor_scene();
    scene
        .lights
        .push(point_light(DVec3::new(1.0, 1e-6, 0.0), 1.0));
    let colour = trace(&scene, ray_down_at(0.0), TermSwitches::ALL_ON);
    assert!(colour.x > 0.0, "{colour}");
}

#[test]
fn mirror_adds_km_times_the_reflected_colour_up_to_max_depth() {
    let mut scene = bare_scene(Material {
        mirror: DVec3::splat(0.5),
        ..Material::default()
    });
    scene.render.background = DVec3::new(0.2, 0.4, 0.6);
    scene.objects.push(object(
        Shape::Plane,
        DVec3::ZERO,
        DVec3::ZERO,
        DVec3::splat(10.0),
    ));
    let ray = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
    assert_colour(
        trace(&scene, ray, TermSwitches::ALL_ON),
        DVec3::new(0.1, 0.2, 0.3),
    );
    scene.render.max_depth = 0;
    assert_eq!(trace(&scene, ray, TermSwitches::ALL_ON), DVec3::ZERO);
}

#[test]
fn two_facing_mirrors_bounce_exactly_max_depth_times() {
    // Between two mirrors km = 0.5 facing each other, a ray along the axis bounces
    // max_depth times; the last bounce's ray sees ambient ka = 1 * 1.
    let mut scene = bare_scene(Material {
        ambient: DVec3::ONE,
        mirror: DVec3::splat(0.5),
        ..Material::default()
    });
    scene.lights.push(Light::Ambient {
        colour: DVec3::ONE,
        intensity: 1.0,
    });
    scene.objects.push(object(
        Shape::Plane,
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::ZERO,
        DVec3::splat(10.0),
    ));
    scene.objects.push(object(
        Shape::Plane,
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::ZERO,
        DVec3::splat(10.0),
    ));
    scene.render.max_depth = 3;
    let ray = Ray::new(DVec3::ZERO, -DVec3::Z);
    // 1 + 0.5 (1 + 0.5 (1 + 0.5 * 1)) = 1.875
    assert_colour(
        trace(&scene, ray, TermSwitches::ALL_ON),
        DVec3::splat(1.875),
    );
}

/// Two perfect mirrors (km = 1, ka = 0.001) facing each other across the origin, lit by
/// an ambient light of 1: a ray along their axis adds 0.001 per ray until `max_depth`.
fn perfect_mirrors(max_depth: u32) -> raylab::scene::Scene {
    let mut scene = bare_scene(Material {
        ambient: DVec3::splat(0.001),
        mirror: DVec3::ONE,
        ..Material::default()
    });
    scene.lights.push(Light::Ambient {
        colour: DVec3::ONE,
        intensity: 1.0,
    });
    for z in [-1.0, 1.0] {
        scene.objects.push(object(
            Shape::Plane,
            DVec3::new(0.0, 0.0, z),
            DVec3::ZERO,
            DVec3::splat(10.0),
        ));
    }
    scene.render.max_depth = max_depth;
    scene
}

#[test]
fn any_depth_up_to_the_limit_runs_in_a_small_stack() {
    // The mirror chain is a loop: 1000 bounces, and the largest depth a scene may ask
    // for, fit in a thread stack of 256 KiB, which a recursion of that depth overflows.
    for depth in [1000, raylab::scene::MAX_DEPTH] {
        let colour = std::thread::Builder::new()
            .stack_size(256 * 1024)
            .spawn(move || {
                let ray = Ray::new(DVec3::ZERO, -DVec3::Z);
                trace(&perfect_mirrors(depth), ray, TermSwitches::ALL_ON)
            })
            .expect("spawn")
            .join()
            .expect("no stack overflow");
        let expected = 0.001 * f64::from(depth + 1);
        assert!(
            (colour - DVec3::splat(expected)).abs().max_element() < 1e-9,
            "depth {depth}: {colour}"
        );
    }
}
