//! Edit-to-picture latency of the preview worker on the default scene (800 x 600):
//! `cargo run --release --example preview_latency`.

use std::time::Duration;

use raylab::preview::measure_latency;
use raylab::scene::parse_scene;

fn main() {
    let scene = parse_scene(include_str!("../scenes/default.ron")).expect("default scene");
    let runs = 15;
    match measure_latency(&scene, runs, Duration::from_secs(60)) {
        Some(latency) => println!(
            "default scene {}x{}, median of {runs} edits: first frame ({:?}) {:.1} ms, full resolution {:.1} ms",
            scene.camera.width,
            scene.camera.height,
            latency.first_pass,
            latency.first_frame.as_secs_f64() * 1e3,
            latency.full_resolution.as_secs_f64() * 1e3
        ),
        None => eprintln!("the preview did not answer"),
    }
}
