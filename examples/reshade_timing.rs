//! How long the preview's one-sample pass takes after an edit, re-shaded from the hit
//! cache (`render_one_sample_cached`) or traced afresh (`render_samples`), without the
//! worker around it: the figures of docs/BENCHMARKS.md ("Glass and sphere lights").
//!
//! ```sh
//! cargo run --release --example reshade_timing -- default.ron material 15
//! cargo run --release --example reshade_timing -- glass.ron glass-diffuse 15
//! ```
//!
//! The scene is an embedded example at its own size (800x600). Edits, each flipped
//! between two states so that every pass is a change: `material` (the first object's
//! diffuse colour, as `raylab bench` edits it), `glass-diffuse`, `glass-kt` (the glass's
//! transmission colour), `glass-ior` (1.5 and 1.33), `transmission` (the term switched
//! off and on) and `trace` (no edit: the one-sample pass traced afresh, as the preview
//! does for a world its cache cannot serve). Prints the median of the runs and, per
//! run, the rays the pass traced. `worker` runs `raylab bench`'s edit-to-full-frame
//! measurement through the real preview worker instead, with the first glass object
//! moved to the front of the list (the bench edits the first object's material).

use std::time::Instant;

use glam::DVec3;
use raylab::scene::Scene;
use raylab::scene::examples::EXAMPLE_SCENES;
use raylab::trace::{
    RenderOptions, RenderProgress, Term, World, render_one_sample_cached, render_samples,
};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("default.ron", String::as_str);
    let edit = args.get(1).map_or("material", String::as_str);
    let runs: usize = args.get(2).and_then(|r| r.parse().ok()).unwrap_or(15);
    let text = EXAMPLE_SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("no example scene {name}"))
        .1;
    let mut scene = raylab::scene::parse_scene(text).expect("the example parses");
    if edit == "worker" {
        if let Some(at) = scene.objects.iter().position(|o| o.material == "glass") {
            let glass = scene.objects.remove(at);
            scene.objects.insert(0, glass);
        }
        let latency = raylab::bench::edit_latency(&scene, runs as u32).expect("measured");
        println!("{name} through the worker, to the first full frame (ms): {latency:?}");
        return;
    }
    let mut options = RenderOptions::from_scene(&scene);
    let progress = RenderProgress::default();
    let world = World::new(&scene).expect("the example compiles");
    let mut cache = render_one_sample_cached(&world, &options, None, &progress)
        .expect("not cancelled")
        .cache;
    let mut times = Vec::new();
    for run in 0..runs {
        let flip = run % 2 == 0;
        apply(edit, &mut scene, &mut options, flip);
        let world = World::new(&scene).expect("the example compiles");
        let started = Instant::now();
        if edit == "trace" {
            let one = RenderOptions {
                samples_per_pixel: 1,
                ..options.clone()
            };
            let sums = render_samples(&world, &one, 0..1, &progress).expect("not cancelled");
            times.push(started.elapsed().as_secs_f64() * 1e3);
            println!("run {run}: traced {:?}", sums.rays);
        } else {
            let pass = render_one_sample_cached(&world, &options, Some(&cache), &progress)
                .expect("not cancelled");
            times.push(started.elapsed().as_secs_f64() * 1e3);
            println!(
                "run {run}: traced {:?}, {} pixels shaded, {} from factors",
                pass.traced, pass.shaded_pixels, pass.quick_pixels
            );
            cache = pass.cache;
        }
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{name} {edit}: median {:.1} ms over {runs} runs (min {:.1}, max {:.1})",
        times[times.len() / 2],
        times[0],
        times[times.len() - 1]
    );
}

/// Applies edit `edit`, in its first state when `flip` and its second otherwise.
fn apply(edit: &str, scene: &mut Scene, options: &mut RenderOptions, flip: bool) {
    let glass = || "glass".to_owned();
    match edit {
        "trace" => {}
        "material" => {
            let name = scene.objects[0].material.clone();
            scene.materials.get_mut(&name).unwrap().diffuse = if flip {
                DVec3::new(0.8, 0.3, 0.2)
            } else {
                DVec3::new(0.2, 0.5, 0.7)
            };
        }
        "glass-diffuse" => {
            scene.materials.get_mut(&glass()).unwrap().diffuse = if flip {
                DVec3::new(0.3, 0.02, 0.02)
            } else {
                DVec3::new(0.02, 0.02, 0.02)
            };
        }
        "glass-kt" => {
            scene.materials.get_mut(&glass()).unwrap().transmission = if flip {
                DVec3::new(0.5, 0.7, 0.9)
            } else {
                DVec3::new(0.92, 0.95, 0.94)
            };
        }
        "glass-ior" => {
            scene.materials.get_mut(&glass()).unwrap().ior = if flip { 1.33 } else { 1.5 };
        }
        "transmission" => options.switches.set(Term::Transmission, !flip),
        other => panic!("unknown edit {other}"),
    }
}
