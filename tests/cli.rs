//! The command line: `raylab render` writes PNGs with the switches and views; bad input
//! gives a clear message and a non-zero exit, never a panic.

mod common;

use std::path::Path;

use common::cli::{out_dir, raylab};

fn scene(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

#[test]
fn render_writes_a_png_of_the_asked_size_keeping_the_aspect_ratio() {
    let out = out_dir("cli").join("small.png");
    let result = raylab(&[
        "render",
        &scene("default.ron"),
        "-o",
        out.to_str().unwrap(),
        "--width",
        "80",
        "--spp",
        "1",
    ]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let image = image::open(&out).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), (80, 60));
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("Mrays/s"), "{stderr}");
}

#[test]
fn switches_and_views_match_the_library() {
    use raylab::scene::load_scene;
    use raylab::trace::{RenderOptions, RenderProgress, Term, TermSwitches, View, World, render};
    let dir = out_dir("cli");
    let scene_path = scene("default.ron");
    let loaded = load_scene(Path::new(&scene_path)).unwrap();
    let world = World::new(&loaded).unwrap();
    let mut off = TermSwitches::ALL_ON;
    off.set(Term::Shadows, false);
    off.set(Term::Reflection, false);
    for (args, switches, view) in [
        (
            vec!["--solo", "diffuse"],
            TermSwitches::ALL_ON.with_solo(Some(Term::Diffuse)),
            View::Beauty,
        ),
        (vec!["--off", "shadows,reflection"], off, View::Beauty),
        (vec!["--view", "normal"], TermSwitches::ALL_ON, View::Normal),
        (
            vec!["--view", "object-id"],
            TermSwitches::ALL_ON,
            View::ObjectId,
        ),
    ] {
        let out = dir.join(format!("{}.png", args.join("_").replace(',', "_")));
        let mut all = vec![
            "render",
            &scene_path,
            "-o",
            out.to_str().unwrap(),
            "--width",
            "64",
            "--height",
            "48",
            "--spp",
            "2",
        ];
        all.extend(args.iter().copied());
        let result = raylab(&all);
        assert!(
            result.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&result.stderr)
        );
        let options = RenderOptions {
            width: 64,
            height: 48,
            samples_per_pixel: 2,
            switches,
            view,
            isolation: Default::default(),
        };
        let (expected, _) = render(&world, &options, &RenderProgress::default()).unwrap();
        let written = image::open(&out).unwrap().to_rgba8().into_raw();
        assert_eq!(written, expected.to_rgba8(), "{args:?}");
    }
}

#[test]
fn bad_input_is_a_message_and_a_failure_exit() {
    let out = out_dir("cli").join("never.png");
    let out = out.to_str().unwrap();
    for (args, expect) in [
        (
            vec!["render", "no/such/scene.ron", "-o", out],
            "cannot read",
        ),
        (
            vec!["render", &scene("default.ron"), "-o", out, "--solo", "glow"],
            "unknown term",
        ),
        (
            vec![
                "render",
                &scene("default.ron"),
                "-o",
                out,
                "--view",
                "x-ray",
            ],
            "unknown view",
        ),
        (
            vec!["render", &scene("default.ron"), "-o", out, "--width", "0"],
            "width",
        ),
        (
            vec![
                "render",
                &scene("default.ron"),
                "-o",
                "/no/such/folder/out.png",
                "--width",
                "8",
            ],
            "cannot write",
        ),
    ] {
        let result = raylab(&args);
        assert!(!result.status.success(), "{args:?}");
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(stderr.contains(expect), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    let broken = out_dir("cli").join("broken.ron");
    std::fs::write(
        &broken,
        "Scene(objects: [(shape: Sphere,, material: \"m\")])",
    )
    .unwrap();
    let result = raylab(&["render", broken.to_str().unwrap(), "-o", out]);
    assert!(!result.status.success());
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("line 1, column"), "{stderr}");
}
