//! The NaN/infinity guard: the renderer counts the samples that came out non-finite and
//! lists their pixels (the editor's guard view paints them). On every example scene, for
//! every view and a few term switches, the list stays empty.

use std::path::Path;
use std::time::Duration;

use raylab::preview::{PreviewRequest, PreviewWorker};
use raylab::scene::load_scene;
use raylab::trace::{
    RenderOptions, RenderProgress, Term, TermSwitches, View, World, render_samples,
};

fn example_scenes() -> Vec<(String, raylab::scene::Scene)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .map(|p| {
            let scene = load_scene(&p).unwrap();
            (p.file_name().unwrap().to_string_lossy().into_owned(), scene)
        })
        .collect();
    scenes.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(scenes.len() >= 6, "the example scenes are found");
    scenes
}

#[test]
fn no_example_scene_has_a_non_finite_sample_in_any_view() {
    for (name, scene) in example_scenes() {
        let world = World::new(&scene).unwrap();
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
    for (generation, (name, mut scene)) in (1..).zip(example_scenes()) {
        scene.camera.width /= 2;
        scene.camera.height /= 2;
        scene.render.samples_per_pixel = 4;
        worker.submit(PreviewRequest::for_scene(generation, scene));
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
