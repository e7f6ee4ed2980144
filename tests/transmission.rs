//! Transmission (Whitted's refraction) against analytic answers: a glass slab shifts a
//! ray by the textbook amount and leaves it parallel; a sphere of index 1 changes nothing
//! but its highlight; total internal reflection starts at the critical angle; the term's
//! solo adds up with the others; `--off transmission` on the command line writes the
//! library's pixels.

use std::path::Path;
use std::process::Command;

use glam::{DVec3, Vec3};
use raylab::scene::{Scene, parse_scene};
use raylab::trace::{
    Image, Isolation, RayKind, RenderOptions, RenderProgress, Term, TermSwitches, TracedRay, View,
    World, inspect_pixel, render, traced_rays,
};

const GLASS: &str = r#""glass": (diffuse: (0.0, 0.0, 0.0), specular: (0.0, 0.0, 0.0), shininess: 1.0,
                     transmission: (1.0, 1.0, 1.0), ior: IOR)"#;

/// A scene seen from `camera` (a RON camera body), with the glass material of index
/// `ior`, a backdrop material, and `objects` (RON object entries).
fn scene(camera: &str, ior: f64, objects: &str) -> Scene {
    let glass = GLASS.replace("IOR", &format!("{ior:?}"));
    parse_scene(&format!(
        r#"Scene(
            camera: ({camera}, fov_deg: 40.0, width: 41, height: 41),
            render: (max_depth: 8, background: (0.1, 0.2, 0.3), samples_per_pixel: 1),
            materials: {{
                {glass},
                "wall": (ambient: (0.2, 0.2, 0.2), diffuse: (0.6, 0.5, 0.4), specular: (0.5, 0.5, 0.5), shininess: 20.0, mirror: (0.2, 0.2, 0.2)),
            }},
            lights: [
                Ambient(colour: (1.0, 1.0, 1.0)),
                Point(position: (2.0, 3.0, 6.0), colour: (1.0, 1.0, 1.0), intensity: 30.0),
            ],
            objects: [{objects}],
        )"#
    ))
    .unwrap()
}

fn options(scene: &Scene, switches: TermSwitches) -> RenderOptions {
    RenderOptions {
        switches,
        ..RenderOptions::from_scene(scene)
    }
}

fn rays_of_centre_pixel(scene: &Scene) -> Vec<TracedRay> {
    let world = World::new(scene).unwrap();
    let report = inspect_pixel(&world, &options(scene, TermSwitches::ALL_ON), 20, 20);
    traced_rays(&report)
}

fn render_with(scene: &Scene, switches: TermSwitches) -> Image {
    let world = World::new(scene).unwrap();
    let progress = RenderProgress::default();
    render(&world, &options(scene, switches), &progress)
        .unwrap()
        .0
}

/// A slab of glass 2h thick, turned `degrees` about y, in front of the camera on the z
/// axis: the centre pixel's ray meets it at that angle.
fn slab(degrees: f64, half_thickness: f64, ior: f64) -> Scene {
    let slab = format!(
        r#"(name: "slab", shape: Cube, transform: (rotate_deg: (0.0, {degrees:?}, 0.0), scale: (20.0, 20.0, {half_thickness:?})), material: "glass")"#
    );
    scene(
        "position: (0.0, 0.0, 10.0), look_at: (0.0, 0.0, 0.0)",
        ior,
        &slab,
    )
}

#[test]
fn a_glass_slab_shifts_a_ray_by_the_textbook_amount_and_leaves_it_parallel() {
    for (degrees, half, ior) in [(30.0, 0.5, 1.5), (60.0, 1.0, 1.33), (10.0, 0.25, 2.4)] {
        let rays = rays_of_centre_pixel(&slab(degrees, half, ior));
        let refracted: Vec<&TracedRay> = rays
            .iter()
            .filter(|r| r.kind == RayKind::Refraction)
            .collect();
        assert_eq!(refracted.len(), 2, "{degrees} degrees: in, then out");
        let (inside, out) = (refracted[0], refracted[1]);
        let (theta_i, theta_t) = {
            let t = f64::to_radians(degrees);
            (t, (t.sin() / ior).asin())
        };
        // Inside, Snell's angle to the slab's normal.
        let normal = DVec3::new(theta_i.sin(), 0.0, theta_i.cos());
        let cos_inside = -inside.direction.dot(normal);
        assert!(
            (cos_inside - theta_t.cos()).abs() < 1e-12,
            "{degrees}: inside the slab the ray makes {} with the normal, not {}",
            cos_inside.acos().to_degrees(),
            theta_t.to_degrees()
        );
        // Out: parallel to the camera ray, shifted sideways by d sin(i - t) / cos t.
        assert!(
            (out.direction - DVec3::NEG_Z).length() < 1e-12,
            "{degrees}: the ray leaves parallel, {}",
            out.direction
        );
        let expected = 2.0 * half * (theta_i - theta_t).sin() / theta_t.cos();
        let shift = out.origin.truncate().length();
        assert!(
            (shift - expected).abs() < 1e-9,
            "{degrees}: shifted {shift}, expected {expected}"
        );
    }
}

#[test]
fn a_sphere_of_index_one_is_invisible_but_for_its_highlight() {
    let wall = r#"(name: "wall", shape: Plane, transform: (translate: (0.0, 0.0, -3.0), scale: (10.0, 10.0, 1.0)), material: "wall")"#;
    let ball =
        r#"(name: "ball", shape: Sphere, transform: (scale: (1.5, 1.5, 1.5)), material: "glass")"#;
    let camera = "position: (0.0, 0.5, 8.0), look_at: (0.0, 0.0, 0.0)";
    let with_ball = scene(camera, 1.0, &format!("{wall}, {ball}"));
    let without = scene(camera, 1.0, wall);
    // Its shadow is hard (a transmissive object blocks shadow rays, as in Whitted's
    // tracer): compared with shadows off, and its highlight is zero (ks = 0).
    let mut no_shadows = TermSwitches::ALL_ON;
    no_shadows.set(Term::Shadows, false);
    let seen = render_with(&with_ball, no_shadows);
    let expected = render_with(&without, no_shadows);
    for (i, (a, b)) in seen.pixels.iter().zip(&expected.pixels).enumerate() {
        assert!(
            (*a - *b).abs().max_element() < 1e-6,
            "pixel {i}: {a} through the ball, {b} without it"
        );
    }
    // Rays did go through the ball.
    let world = World::new(&with_ball).unwrap();
    let report = inspect_pixel(&world, &options(&with_ball, no_shadows), 20, 20);
    assert!(
        report.bounces.len() >= 3,
        "the centre ray enters and leaves the ball"
    );
}

#[test]
fn total_internal_reflection_starts_at_the_critical_angle() {
    // The camera sits inside a block of glass and looks at its top face from below, at
    // an angle to the face's normal just under and just over asin(1 / 1.5) = 41.81°.
    let critical = (1.0f64 / 1.5).asin().to_degrees();
    for (degrees, expected) in [
        (critical - 0.5, RayKind::Refraction),
        (critical + 0.5, RayKind::InternalReflection),
    ] {
        let t = degrees.to_radians();
        let look = DVec3::new(t.sin(), t.cos(), 0.0);
        let camera = format!(
            "position: (0.0, 0.0, 0.0), look_at: ({:?}, {:?}, 0.0), up: (0.0, 0.0, 1.0)",
            look.x, look.y
        );
        let block = r#"(name: "block", shape: Cube, transform: (scale: (50.0, 1.0, 50.0)), material: "glass")"#;
        let rays = rays_of_centre_pixel(&scene(&camera, 1.5, block));
        assert_eq!(rays[0].kind, RayKind::Primary);
        assert_eq!(
            rays[1].kind, expected,
            "{degrees:.2} degrees: {:?}",
            rays[1]
        );
        if expected == RayKind::InternalReflection {
            // Along the mirror direction: down again, at the same angle.
            let d = rays[1].direction;
            assert!(
                (d - DVec3::new(look.x, -look.y, 0.0)).length() < 1e-12,
                "{d}"
            );
        }
    }
}

#[test]
fn the_transmission_solo_adds_up_with_the_other_terms_and_off_removes_it() {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/glass.ron"))
            .unwrap();
    let mut scene = parse_scene(&text).unwrap();
    scene.camera.width = 80;
    scene.camera.height = 60;
    let full = render_with(&scene, TermSwitches::ALL_ON);
    let solos: Vec<Image> = [
        Term::Ambient,
        Term::Diffuse,
        Term::Specular,
        Term::Reflection,
        Term::Transmission,
    ]
    .into_iter()
    .map(|term| render_with(&scene, TermSwitches::ALL_ON.with_solo(Some(term))))
    .collect();
    let mut glass_pixels = 0;
    for (i, expected) in full.pixels.iter().enumerate() {
        let sum: Vec3 = solos.iter().map(|p| p.pixels[i]).sum();
        let tolerance = 1e-5 * expected.abs().max_element().max(1.0);
        assert!(
            (sum - *expected).abs().max_element() <= tolerance,
            "pixel {i}: the solos add to {sum}, the picture is {expected}"
        );
        glass_pixels += usize::from(solos[4].pixels[i] != Vec3::ZERO);
    }
    assert!(
        glass_pixels > 200,
        "the glass shows in {glass_pixels} pixels"
    );
    // Off: the glass shows only its own colour, and the picture loses what it let through.
    let mut off = TermSwitches::ALL_ON;
    off.set(Term::Transmission, false);
    let without = render_with(&scene, off);
    for (i, ((a, b), t)) in without
        .pixels
        .iter()
        .zip(&full.pixels)
        .zip(&solos[4].pixels)
        .enumerate()
    {
        if *t == Vec3::ZERO {
            assert_eq!(a, b, "pixel {i} shows no glass");
        }
    }
    assert_ne!(without.pixels, full.pixels);
}

#[test]
fn raylab_render_off_transmission_writes_the_librarys_pixels() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/glass.ron");
    let dir = std::env::temp_dir().join(format!("raylab-transmission-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = parse_scene(&std::fs::read_to_string(&path).unwrap()).unwrap();
    for (flags, switches) in [
        (vec!["--off", "transmission"], {
            let mut s = TermSwitches::ALL_ON;
            s.set(Term::Transmission, false);
            s
        }),
        (
            vec!["--solo", "transmission"],
            TermSwitches::ALL_ON.with_solo(Some(Term::Transmission)),
        ),
    ] {
        let out = dir.join("glass.png");
        let mut args = vec![
            "render",
            path.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ];
        args.extend(["--width", "64", "--height", "48", "--spp", "1"]);
        args.extend(&flags);
        let result = Command::new(env!("CARGO_BIN_EXE_raylab"))
            .args(&args)
            .output()
            .unwrap();
        assert!(
            result.status.success(),
            "{}",
            String::from_utf8_lossy(&result.stderr)
        );
        let world = World::new(&scene).unwrap();
        let options = RenderOptions {
            width: 64,
            height: 48,
            samples_per_pixel: 1,
            switches,
            view: View::Beauty,
            isolation: Isolation::NONE,
        };
        let expected = render(&world, &options, &RenderProgress::default())
            .unwrap()
            .0;
        let written = image::open(&out).unwrap().to_rgba8().into_raw();
        assert_eq!(written, expected.to_rgba8(), "{flags:?}");
    }
}
