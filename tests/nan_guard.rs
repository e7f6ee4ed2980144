//! The NaN/infinity guard: the renderer counts the samples that came out non-finite and
//! lists their pixels (the editor's guard view paints them), and `raylab render` reports
//! them with a non-zero exit. A scene that really makes one is caught; a light whose
//! strength overflows is refused by name; on every example scene, for every view and a
//! few term switches, the list stays empty.

mod common;

use std::path::Path;
use std::sync::Arc;
use std::time::Duration;

use common::LIGHT_ON_THE_SURFACE;
use common::cli::{out_dir, raylab};
use raylab::preview::{PreviewRequest, PreviewWorker};
use raylab::scene::{load_scene, parse_scene, read_scene_meshes};
use raylab::trace::{
    MeshStore, RenderOptions, RenderProgress, Term, TermSwitches, View, World, render_samples,
};

/// `raylab render SCENE -o OUT`.
fn render(scene: &Path, out: &Path) -> std::process::Output {
    raylab(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ])
}

fn temp_path(name: &str) -> std::path::PathBuf {
    out_dir("nan-guard").join(name)
}

#[test]
fn a_non_finite_sample_is_caught_listed_and_fails_the_command_line() {
    let scene = parse_scene(LIGHT_ON_THE_SURFACE).unwrap();
    let world = World::new(&scene).unwrap();
    let options = RenderOptions::from_scene(&scene);
    let sums = render_samples(&world, &options, 0..1, &RenderProgress::default()).unwrap();
    assert_eq!(
        sums.non_finite, 1,
        "the centre sample meets an infinite light"
    );
    assert_eq!(sums.non_finite_pixels, vec![16 * 33 + 16]);
    assert!(
        sums.sums.iter().all(|s| s.is_finite()),
        "kept out of the sums"
    );

    let path = temp_path("surface_light.ron");
    std::fs::write(&path, LIGHT_ON_THE_SURFACE).unwrap();
    let out = temp_path("surface_light.png");
    let result = render(&path, &out);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(!result.status.success(), "{stderr}");
    assert!(
        stderr.contains("1 pixels had non-finite samples") && stderr.contains("x 16, y 16"),
        "{stderr}"
    );
    assert!(out.exists(), "the image is written to be looked at");

    // The same scene with the light a little higher renders cleanly and exits 0.
    let fine = LIGHT_ON_THE_SURFACE.replace("1.0000001", "1.5");
    std::fs::write(&path, fine).unwrap();
    let result = render(&path, &out);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
}

#[test]
fn a_light_whose_colour_times_intensity_overflows_is_refused_by_name() {
    let text = LIGHT_ON_THE_SURFACE.replace("1.0000001", "3.0").replace(
        "colour: (1.0, 1.0, 1.0), intensity: 1e300",
        "colour: (1e10, 1.0, 1.0), intensity: 1e300",
    );
    let error = parse_scene(&text).and_then(|s| World::new(&s).map(|_| ()));
    let message = error.expect_err("refused").to_string();
    assert!(
        message.contains("lights[1] (Point)") && message.contains("overflows"),
        "{message}"
    );
    let path = temp_path("overflowing_light.ron");
    std::fs::write(&path, &text).unwrap();
    let out = temp_path("overflowing_light.png");
    let result = render(&path, &out);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(!result.status.success());
    assert!(stderr.contains("lights[1] (Point)"), "{stderr}");
}

/// The example scenes by file name, each with the meshes it refers to.
fn example_scenes() -> Vec<(String, raylab::scene::Scene, Arc<MeshStore>)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .map(|p| {
            let scene = load_scene(&p).unwrap();
            let meshes = read_scene_meshes(&scene, &dir).unwrap();
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, scene, Arc::new(MeshStore::build(&meshes)))
        })
        .collect();
    scenes.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(scenes.len() >= 6, "the example scenes are found");
    scenes
}

#[test]
fn no_example_scene_has_a_non_finite_sample_in_any_view() {
    for (name, scene, meshes) in example_scenes() {
        let world = World::with_meshes(&scene, &meshes).unwrap();
        let switches = [
            TermSwitches::ALL_ON,
            TermSwitches::ALL_ON.with_solo(Some(Term::Reflection)),
            TermSwitches::ALL_ON.with_solo(Some(Term::Shadows)),
        ];
        for view in View::ALL {
            for switches in switches {
                let options = RenderOptions {
                    width: scene.camera.width / 4,
                    height: scene.camera.height / 4,
                    samples_per_pixel: 4,
                    switches,
                    view,
                    isolation: Default::default(),
                };
                let sums =
                    render_samples(&world, &options, 0..4, &RenderProgress::default()).unwrap();
                assert_eq!(sums.non_finite, 0, "{name} {view} {switches:?}");
                assert!(sums.non_finite_pixels.is_empty(), "{name} {view}");
                assert!(sums.sums.iter().all(|s| s.is_finite()), "{name} {view}");
            }
        }
    }
}

#[test]
fn every_preview_frame_of_every_example_scene_reports_zero_non_finite_samples() {
    let mut worker = PreviewWorker::spawn(Box::new(|| {}));
    for (generation, (name, mut scene, meshes)) in (1..).zip(example_scenes()) {
        scene.camera.width /= 2;
        scene.camera.height /= 2;
        scene.render.samples_per_pixel = 4;
        worker.submit(PreviewRequest {
            meshes,
            ..PreviewRequest::for_scene(generation, scene)
        });
        let mut frames = 0;
        loop {
            let message = worker
                .recv_timeout(Duration::from_secs(60))
                .expect("a frame within the wait");
            assert_eq!(message.generation, generation);
            let frame = message.result.expect("the example scene renders");
            assert_eq!(frame.non_finite_samples, 0, "{name} {:?}", frame.pass);
            assert!(
                frame.non_finite_pixels.is_empty(),
                "{name} {:?}",
                frame.pass
            );
            frames += 1;
            if frame.is_final {
                break;
            }
        }
        assert!(frames >= 3, "{name}: coarse, full and sampled passes");
    }
}
