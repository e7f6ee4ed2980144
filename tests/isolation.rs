//! Isolating lights and objects: the solo images of all the lights add up to the full
//! picture (whatever the term switches), a muted light or hidden object is as if deleted
//! (no shadow, no reflection, no pick), indices stay the scene's, and `raylab render`
//! with the flags writes the library's pixels.

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

use glam::{DVec2, DVec3, Vec3};
use raylab::scene::{Light, Scene, load_scene};
use raylab::trace::{
    Image, Isolation, PinholeCamera, RenderOptions, RenderProgress, Term, TermSwitches, View,
    World, inspect_pixel, pick, render,
};

const WIDTH: u32 = 96;
const HEIGHT: u32 = 72;

fn scene() -> Scene {
    load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron")).unwrap()
}

fn options(switches: TermSwitches, view: View, isolation: &Isolation) -> RenderOptions {
    RenderOptions {
        width: WIDTH,
        height: HEIGHT,
        samples_per_pixel: 1,
        switches,
        view,
        isolation: isolation.clone(),
    }
}

fn render_view(scene: &Scene, switches: TermSwitches, view: View, isolation: &Isolation) -> Image {
    let world = World::isolated(scene, isolation).unwrap();
    render(
        &world,
        &options(switches, view, isolation),
        &RenderProgress::default(),
    )
    .unwrap()
    .0
}

fn render_with(scene: &Scene, switches: TermSwitches, isolation: &Isolation) -> Image {
    render_view(scene, switches, View::Beauty, isolation)
}

fn solo(light: usize) -> Isolation {
    Isolation {
        solo_lights: BTreeSet::from([light]),
        ..Isolation::NONE
    }
}

fn hidden(objects: &[usize]) -> Isolation {
    Isolation {
        hidden_objects: objects.iter().copied().collect(),
        ..Isolation::NONE
    }
}

/// Every pixel of the sum of `parts` equals `full` (relative tolerance for rounding).
fn assert_adds_up(parts: &[Image], full: &Image, what: &str) {
    for (i, expected) in full.pixels.iter().enumerate() {
        let sum: Vec3 = parts.iter().map(|p| p.pixels[i]).sum();
        let tolerance = 1e-5 * expected.abs().max_element().max(1.0);
        assert!(
            (sum - *expected).abs().max_element() <= tolerance,
            "{what}, pixel {i}: {sum} vs {expected}"
        );
    }
}

fn light_solos(scene: &Scene, switches: TermSwitches) -> Vec<Image> {
    (0..scene.lights.len())
        .map(|i| render_with(scene, switches, &solo(i)))
        .collect()
}

#[test]
fn the_solo_images_of_all_lights_add_up_to_the_full_picture_whatever_the_term_switches() {
    let scene = scene();
    let mut no_specular = TermSwitches::ALL_ON;
    no_specular.set(Term::Specular, false);
    let mut no_shadows = TermSwitches::ALL_ON;
    no_shadows.set(Term::Shadows, false);
    for (what, switches) in [
        ("all on", TermSwitches::ALL_ON),
        ("specular off", no_specular),
        ("shadows off", no_shadows),
        (
            "solo diffuse",
            TermSwitches::ALL_ON.with_solo(Some(Term::Diffuse)),
        ),
        (
            "solo reflection",
            TermSwitches::ALL_ON.with_solo(Some(Term::Reflection)),
        ),
    ] {
        let full = render_with(&scene, switches, &Isolation::NONE);
        assert_adds_up(&light_solos(&scene, switches), &full, what);
    }
    // Each light shows something of its own: no one solo does all the work.
    let solos = light_solos(&scene, TermSwitches::ALL_ON);
    for (i, image) in solos.iter().enumerate() {
        assert!(
            image.pixels.iter().any(|p| p.max_element() > 0.05),
            "light {i}"
        );
        assert!(
            solos
                .iter()
                .enumerate()
                .all(|(j, other)| j == i || other != image)
        );
    }
}

#[test]
fn a_solo_light_is_seen_through_mirrors_as_the_only_light() {
    let mut scene = scene();
    // On a black background, a light's solo is the picture with every other light muted.
    scene.render.background = DVec3::ZERO;
    for light in 0..scene.lights.len() {
        let others = Isolation {
            muted_lights: (0..scene.lights.len()).filter(|&i| i != light).collect(),
            ..Isolation::NONE
        };
        let alone = render_with(&scene, TermSwitches::ALL_ON, &solo(light));
        assert_eq!(alone, render_with(&scene, TermSwitches::ALL_ON, &others));
    }
    // The mirror ball (low on its front, where it reflects the floor) shows the solo
    // light's reflections, not the full picture's.
    let ball = pixel_of(&scene, 2, DVec3::new(0.0, -0.5, 0.85));
    let at = |image: &Image| image.get(ball.0, ball.1);
    let full = render_with(&scene, TermSwitches::ALL_ON, &Isolation::NONE);
    let point = render_with(&scene, TermSwitches::ALL_ON, &solo(1));
    let no_mirror = TermSwitches::ALL_ON.with_solo(Some(Term::Reflection));
    let reflected_point = render_with(&scene, no_mirror, &solo(1));
    let reflected_full = render_with(&scene, no_mirror, &Isolation::NONE);
    assert!(at(&reflected_point).max_element() > 0.0);
    assert!((at(&reflected_full) - at(&reflected_point)).max_element() > 0.01);
    assert!((at(&full) - at(&point)).max_element() > 0.01);
}

#[test]
fn the_background_goes_with_one_solo_with_two_ambient_lights_or_none() {
    let mut two = scene();
    two.render.background = DVec3::new(0.3, 0.4, 0.5);
    two.lights.push(Light::Ambient {
        colour: DVec3::new(0.05, 0.1, 0.0),
        intensity: 1.0,
    });
    let full = render_with(&two, TermSwitches::ALL_ON, &Isolation::NONE);
    assert_adds_up(
        &light_solos(&two, TermSwitches::ALL_ON),
        &full,
        "two ambient",
    );
    let sky = sky_pixel(&two);
    let background = two.render.background.as_vec3();
    let solo_at =
        |scene: &Scene, i| render_with(scene, TermSwitches::ALL_ON, &solo(i)).get(sky.0, sky.1);
    assert_eq!(solo_at(&two, 0), background, "the first ambient light");
    assert_eq!(solo_at(&two, 4), Vec3::ZERO, "the second ambient light");

    let mut none = two.clone();
    none.lights.retain(|l| !matches!(l, Light::Ambient { .. }));
    let full = render_with(&none, TermSwitches::ALL_ON, &Isolation::NONE);
    assert_adds_up(
        &light_solos(&none, TermSwitches::ALL_ON),
        &full,
        "no ambient",
    );
    assert_eq!(solo_at(&none, 0), background, "the first light");
    assert_eq!(solo_at(&none, 1), Vec3::ZERO);
}

#[test]
fn a_muted_light_or_hidden_object_is_as_if_deleted() {
    let scene = scene();
    let full = render_with(&scene, TermSwitches::ALL_ON, &Isolation::NONE);
    let mut without_light = scene.clone();
    without_light.lights.remove(1);
    let muted = Isolation {
        muted_lights: BTreeSet::from([1]),
        ..Isolation::NONE
    };
    let image = render_with(&scene, TermSwitches::ALL_ON, &muted);
    assert_eq!(
        image,
        render_with(&without_light, TermSwitches::ALL_ON, &Isolation::NONE)
    );
    assert_ne!(image, full);

    // The red ball's shadow on the floor and its picture in the mirror ball go with it.
    let mut without_ball = scene.clone();
    without_ball.objects.remove(1);
    let image = render_with(&scene, TermSwitches::ALL_ON, &hidden(&[1]));
    assert_eq!(
        image,
        render_with(&without_ball, TermSwitches::ALL_ON, &Isolation::NONE)
    );
    // Where the same object shows in both, hiding the ball only ever lights more.
    let view =
        |view, isolation: &Isolation| render_view(&scene, TermSwitches::ALL_ON, view, isolation);
    let (ids, ids_hidden) = (
        view(View::ObjectId, &Isolation::NONE),
        view(View::ObjectId, &hidden(&[1])),
    );
    let (mask, mask_hidden) = (
        view(View::ShadowMask, &Isolation::NONE),
        view(View::ShadowMask, &hidden(&[1])),
    );
    let same_object = |i: &usize| ids.pixels[*i] == ids_hidden.pixels[*i];
    let pixels: Vec<usize> = (0..ids.pixels.len()).filter(same_object).collect();
    assert!(
        pixels
            .iter()
            .all(|&i| mask_hidden.pixels[i].x >= mask.pixels[i].x)
    );
    let unshadowed = pixels
        .iter()
        .filter(|&&i| mask_hidden.pixels[i].x > mask.pixels[i].x);
    assert!(unshadowed.count() > 10, "the ball's shadow is gone");
    let mirror_only = TermSwitches::ALL_ON.with_solo(Some(Term::Reflection));
    assert_ne!(
        render_with(&scene, mirror_only, &hidden(&[1])),
        render_with(&scene, mirror_only, &Isolation::NONE)
    );
}

#[test]
fn picking_skips_hidden_objects_and_names_the_scene_index() {
    let scene = scene();
    let ball = pixel_of(&scene, 1, DVec3::ZERO);
    let boxed = pixel_of(&scene, 3, DVec3::ZERO);
    let at = |p: (u32, u32)| DVec2::new(f64::from(p.0) + 0.5, f64::from(p.1) + 0.5);
    let pick_in = |isolation: &Isolation, p| {
        pick(
            &World::isolated(&scene, isolation).unwrap(),
            WIDTH,
            HEIGHT,
            at(p),
        )
    };
    assert_eq!(pick_in(&Isolation::NONE, ball), Some(1));
    let behind = pick_in(&hidden(&[1]), ball);
    assert_ne!(behind, Some(1), "a hidden object cannot be picked");
    assert_eq!(behind, Some(0), "the floor behind it");
    assert_eq!(
        pick_in(&hidden(&[0, 1, 2]), boxed),
        Some(3),
        "the scene's index"
    );
}

#[test]
fn object_ids_and_light_indices_stay_the_scenes_when_some_are_left_out() {
    let scene = scene();
    let isolation = Isolation {
        muted_lights: BTreeSet::from([1]),
        hidden_objects: BTreeSet::from([1, 2]),
        ..Isolation::NONE
    };
    let ids = render_view(
        &scene,
        TermSwitches::ALL_ON,
        View::ObjectId,
        &Isolation::NONE,
    );
    let ids_hidden = render_view(&scene, TermSwitches::ALL_ON, View::ObjectId, &isolation);
    let boxed = pixel_of(&scene, 3, DVec3::ZERO);
    assert_eq!(ids.get(boxed.0, boxed.1), ids_hidden.get(boxed.0, boxed.1));

    let world = World::isolated(&scene, &isolation).unwrap();
    let options = options(TermSwitches::ALL_ON, View::Beauty, &isolation);
    let report = inspect_pixel(&world, &options, boxed.0, boxed.1);
    assert_eq!(report.bounces[0].hit.unwrap().object, 3);
    let mut blocked = 0;
    for py in (0..HEIGHT).step_by(2) {
        for px in (0..WIDTH).step_by(2) {
            for bounce in inspect_pixel(&world, &options, px, py).bounces {
                let object = bounce.hit.map(|h| h.object);
                assert!(object.is_none_or(|o| !isolation.hidden_objects.contains(&o)));
                for light in &bounce.lights {
                    assert!([2, 3].contains(&light.scene_index), "{}", light.scene_index);
                    if let Some(by) = light.blocked_by {
                        assert!(!isolation.hidden_objects.contains(&by), "blocked by {by}");
                        blocked += 1;
                    }
                }
            }
        }
    }
    assert!(blocked > 0, "some shadows remain");
}

#[test]
fn raylab_render_with_the_flags_writes_the_librarys_pixels_and_rejects_bad_ones() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron");
    let dir = std::env::temp_dir().join(format!("raylab-isolation-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("isolated.png");
    let run = |flags: &[&str]| {
        let mut args = vec![
            "render",
            path.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ];
        args.extend(["--width", "96", "--height", "72", "--spp", "1"]);
        args.extend(flags);
        Command::new(env!("CARGO_BIN_EXE_raylab"))
            .args(&args)
            .output()
            .unwrap()
    };
    let result = run(&[
        "--mute-light",
        "2",
        "--solo-light",
        "1,3",
        "--hide",
        "red ball,gold cone",
    ]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let isolation = Isolation {
        muted_lights: BTreeSet::from([2]),
        solo_lights: BTreeSet::from([1, 3]),
        hidden_objects: BTreeSet::from([1, 5]),
        hidden_parts: BTreeSet::new(),
    };
    let expected = render_with(&scene(), TermSwitches::ALL_ON, &isolation);
    let written = image::open(&out).unwrap().to_rgba8().into_raw();
    assert_eq!(written, expected.to_rgba8());

    for (flags, message) in [
        (
            vec!["--mute-light", "4"],
            "there is no light 4: the scene has 4 lights",
        ),
        (vec!["--solo-light", "x"], "invalid value"),
        (vec!["--hide", "lamp"], "no object named \"lamp\""),
    ] {
        let result = run(&flags);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{flags:?}");
        assert!(
            stderr.contains(message) && !stderr.contains("panicked"),
            "{stderr}"
        );
    }
}

/// The pixel of the `WIDTH` x `HEIGHT` image where object `index`'s point `p_object`
/// (object space) lands.
fn pixel_of(scene: &Scene, index: usize, p_object: DVec3) -> (u32, u32) {
    let camera = PinholeCamera::new(&scene.camera, WIDTH, HEIGHT);
    let p = scene.objects[index]
        .transform
        .world_from_object()
        .transform_point3(p_object);
    let image = camera.project(p).unwrap();
    (image.x as u32, image.y as u32)
}

/// A pixel whose camera ray hits nothing.
fn sky_pixel(scene: &Scene) -> (u32, u32) {
    let world = World::new(scene).unwrap();
    let centre = |x: u32, y: u32| DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
    (0..HEIGHT)
        .flat_map(|y| (0..WIDTH).map(move |x| (x, y)))
        .find(|&(x, y)| pick(&world, WIDTH, HEIGHT, centre(x, y)).is_none())
        .expect("the default scene shows some sky")
}
