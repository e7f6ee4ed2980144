//! The course's conventions (`render.conventions`): mirrors added or blended, colour
//! clamped only at the pixel or on every ray, bytes rounded or truncated. Analytic
//! answers on a mirror facing the camera, the sum of solos under `EachRay`, the re-shade
//! cache under them, and `raylab render`'s flags.

mod common;
mod reshade_harness;

use common::*;
use glam::DVec3;
use raylab::scene::{ClampConvention, Conventions, Light, Material, MirrorConvention, Quantise};
use raylab::trace::{Ray, Term, TermSwitches};
use reshade_harness::{Shot, edit_chain, example};

/// A mirror square facing the camera, lit by ambient light only: its own colour is
/// `ka`, and its mirror ray goes straight back into the background.
fn mirror_facing_camera(ka: f64, km: f64, background: f64, conventions: Conventions) -> DVec3 {
    let scene = mirror_scene(ka, km, background, conventions);
    trace(&scene, camera_ray(), TermSwitches::ALL_ON)
}

/// The camera's ray at the mirror's centre.
fn camera_ray() -> Ray {
    Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z)
}

/// The scene of [`mirror_facing_camera`].
fn mirror_scene(
    ka: f64,
    km: f64,
    background: f64,
    conventions: Conventions,
) -> raylab::scene::Scene {
    let mut scene = bare_scene(Material {
        ambient: DVec3::splat(ka),
        mirror: DVec3::splat(km),
        ..Material::default()
    });
    scene.objects = vec![object(
        raylab::scene::Shape::Plane,
        DVec3::ZERO,
        DVec3::ZERO,
        DVec3::splat(3.0),
    )];
    scene.lights = vec![Light::Ambient {
        colour: DVec3::ONE,
        intensity: 1.0,
    }];
    scene.render.background = DVec3::splat(background);
    scene.render.conventions = conventions;
    scene
}

const BLEND: Conventions = Conventions {
    mirror: MirrorConvention::Blend,
    clamp: ClampConvention::Pixel,
    quantise: Quantise::Round,
};

const EACH_RAY: Conventions = Conventions {
    mirror: MirrorConvention::Add,
    clamp: ClampConvention::EachRay,
    quantise: Quantise::Round,
};

#[test]
fn a_mirror_adds_or_blends_its_reflection() {
    let add = mirror_facing_camera(0.4, 0.5, 0.8, Conventions::default());
    assert_colour(add, DVec3::splat(0.4 + 0.5 * 0.8));
    let blend = mirror_facing_camera(0.4, 0.5, 0.8, BLEND);
    assert_colour(blend, DVec3::splat(0.5 * 0.4 + 0.5 * 0.8));
}

#[test]
fn each_ray_is_clamped_before_a_mirror_uses_it() {
    // The background of 3 comes back through a half mirror: 0.1 + 0.5 * 3 = 1.6 with
    // only the pixel clamped (to 1 when written), 0.1 + 0.5 * 1 = 0.6 when each ray is.
    assert_colour(
        mirror_facing_camera(0.1, 0.5, 3.0, Conventions::default()),
        DVec3::splat(1.6),
    );
    assert_colour(
        mirror_facing_camera(0.1, 0.5, 3.0, EACH_RAY),
        DVec3::splat(0.6),
    );
    // The ray's own colour is clamped too: 1.5 + 0 is returned as 1.
    assert_colour(mirror_facing_camera(1.5, 0.5, 0.0, EACH_RAY), DVec3::ONE);
}

#[test]
fn without_a_mirror_ray_blend_leaves_the_local_colour_alone() {
    // Reflection switched off: no mirror ray, so nothing to blend with.
    let mut switches = TermSwitches::ALL_ON;
    switches.set(Term::Reflection, false);
    let scene = mirror_scene(0.4, 0.5, 0.0, BLEND);
    assert_colour(trace(&scene, camera_ray(), switches), DVec3::splat(0.4));
}

#[test]
fn under_each_ray_the_solos_sum_to_the_picture_where_no_ray_exceeds_one() {
    let mut scene = example("default.ron");
    scene.render.conventions = Conventions::COURSE;
    let camera = raylab::trace::PinholeCamera::new(&scene.camera, 40, 30);
    let solos = [
        Term::Ambient,
        Term::Diffuse,
        Term::Specular,
        Term::Reflection,
    ];
    let (mut compared, mut clamped) = (0, 0);
    for y in 0..30 {
        for x in 0..40 {
            let ray = camera.ray(glam::DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
            let full = trace(&scene, ray, TermSwitches::ALL_ON);
            // A solo's picture goes through the same clamps; their sum is the picture
            // only where no clamp bit, which the unclamped render shows.
            let mut contract = scene.clone();
            contract.render.conventions = Conventions::default();
            let unclamped = trace(&contract, ray, TermSwitches::ALL_ON);
            if unclamped.max_element() > 1.0 || full != unclamped {
                clamped += 1;
                continue;
            }
            let sum: DVec3 = solos
                .iter()
                .map(|&t| trace(&scene, ray, TermSwitches::ALL_ON.with_solo(Some(t))))
                .sum();
            assert!(
                (sum - full).abs().max_element() < 1e-9,
                "pixel {x},{y}: {sum} vs {full}"
            );
            compared += 1;
        }
    }
    assert!(
        compared > 600 && clamped > 0,
        "{compared} compared, {clamped} clamped"
    );
}

#[test]
fn the_re_shade_cache_answers_under_the_course_conventions_and_their_change() {
    let mut scene = example("default.ron");
    scene.render.conventions = Conventions::COURSE;
    let base = Shot::of(scene);
    let first_material = base.scene.materials.keys().next().unwrap().clone();
    let edits = [
        base.edited(|s, _| {
            s.materials.get_mut(&first_material).unwrap().ambient *= 4.0;
        }),
        base.edited(|s, _| s.render.conventions.mirror = MirrorConvention::Blend),
        base.edited(|s, _| s.render.conventions = Conventions::default()),
        base.edited(|_, o| o.switches = o.switches.with_solo(Some(Term::Reflection))),
    ];
    edit_chain(&base, &edits, "course conventions");
}

/// `raylab render` with `args`, decoded.
fn render_cli(args: &[&str]) -> image::RgbImage {
    let out = common::cli::out_dir("conventions")
        .join(format!("render{}.png", args.join("_").replace('-', "")));
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/default.ron");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_raylab"))
        .args(["render", scene, "--width", "80", "--spp", "1", "-o"])
        .arg(&out)
        .args(args)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    image::open(&out).unwrap().to_rgb8()
}

#[test]
fn the_command_line_truncates_and_takes_the_course_preset() {
    let round = render_cli(&[]);
    let truncate = render_cli(&["--quantise", "truncate"]);
    let pairs: Vec<(u8, u8)> = round
        .iter()
        .copied()
        .zip(truncate.iter().copied())
        .collect();
    assert!(
        pairs.iter().all(|&(r, t)| t <= r && r - t <= 1),
        "truncation is a floor"
    );
    assert!(pairs.iter().filter(|(r, t)| r != t).count() > pairs.len() / 4);
    // The course preset clamps each ray too: the mirror sphere's bright reflections
    // change, so more than truncation alone differs.
    let course = render_cli(&["--conventions", "course"]);
    assert!(course.iter().zip(truncate.iter()).any(|(c, t)| c != t));
    let same_as_course = render_cli(&[
        "--mirror",
        "add",
        "--clamp",
        "each-ray",
        "--quantise",
        "truncate",
    ]);
    assert_eq!(course, same_as_course);
}
