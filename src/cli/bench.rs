//! `raylab bench`: the benchmark report (see docs/BENCHMARKS.md).

use std::path::{Path, PathBuf};

use clap::Args;

use crate::bench::convergence::ConvergencePlan;
use crate::bench::plot::plot_curve;
use crate::bench::{
    BenchReport, bvh_crossover, convergence_curves, curve_checks, edit_latency, precision_cost,
    scene_throughput,
};
use crate::scene::examples::EXAMPLE_SCENES;
use crate::scene::{Scene, load_scene, parse_scene};

/// Arguments of `raylab bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// A short run (well under a minute on 2 cores): fewer runs, smaller convergence images.
    #[arg(long)]
    pub quick: bool,
    /// Print one JSON object instead of the tables.
    #[arg(long)]
    pub json: bool,
    /// Also draw the error-against-time plot to this PNG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Measure the RON scenes of this folder instead of the embedded example scenes.
    #[arg(long)]
    pub scenes: Option<PathBuf>,
    /// Only the diff's accuracy: plant bugs in the example scenes and in this many
    /// random scenes (of the measured seeds, never tuned on), diff each picture, and
    /// print the confusion table (with `--json`, the whole report).
    #[arg(long, value_name = "RANDOM_SCENES")]
    pub diff_accuracy: Option<u64>,
    /// With `--diff-accuracy`: random scenes of the tuning seeds instead (the ones the
    /// diff's thresholds may be set on; the figures reported use the measured seeds).
    #[arg(long, requires = "diff_accuracy")]
    pub tuning: bool,
}

/// Runs the benchmark and prints the report.
///
/// # Errors
/// A message when a scene cannot be loaded or the plot cannot be written.
pub fn run(args: &BenchArgs) -> Result<(), String> {
    if let Some(count) = args.diff_accuracy {
        return run_diff_accuracy(args, count);
    }
    let report = measure(args)?;
    if let Some(path) = &args.plot {
        let title = format!(
            "default scene, {}: error against time",
            if args.quick { "quick run" } else { "full run" }
        );
        plot_curve(&report.curve, path, &title)?;
    }
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
        );
    } else {
        print_tables(&report);
    }
    Ok(())
}

/// `raylab bench --diff-accuracy N`: the long accuracy run.
fn run_diff_accuracy(args: &BenchArgs, count: u64) -> Result<(), String> {
    use crate::bench::diff_accuracy::{
        MEASURED_SEEDS, Plan, TUNING_SEEDS, accuracy_run, calibration, confusion_table,
    };
    let examples = example_scenes(args.scenes.as_deref())?;
    let start = if args.tuning {
        TUNING_SEEDS.start
    } else {
        MEASURED_SEEDS.start
    };
    let plan = Plan {
        alone: 40,
        pairs: 8,
        threes: 4,
    };
    let report = accuracy_run(start..start + count, &examples, 200, plan)?;
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
        );
        return Ok(());
    }
    for line in confusion_table(&report) {
        println!("{line}");
    }
    print_accuracy(&report);
    for (at_least, count, right) in calibration(&report) {
        println!(
            "claims with confidence >= {at_least:.2}: {count}, right {:.1}%",
            100.0 * right
        );
    }
    Ok(())
}

/// The accuracy figures in one paragraph.
fn print_accuracy(report: &crate::bench::diff_accuracy::AccuracyReport) {
    println!(
        "bugs alone: {} planted, first {:.1}%, top two {:.1}%; pairs: {} bugs, top two {:.1}%, top three {:.1}%; threes: {} bugs, top three {:.1}%",
        report.alone.0,
        100.0 * report.top1(),
        100.0 * report.top2(),
        report.pairs.0,
        100.0 * report.pair_top2(),
        100.0 * f64::from(report.pairs.2) / f64::from(report.pairs.0.max(1)),
        report.threes.0,
        100.0 * f64::from(report.threes.1) / f64::from(report.threes.0.max(1)),
    );
    println!(
        "correct pictures: {}, a bug claimed in {} ({:.1}%); verdicts called high: {}, right {:.1}%",
        report.no_bug.0,
        report.no_bug.1,
        100.0 * report.false_verdicts(),
        report.high.0,
        100.0 * report.high_right()
    );
}

/// The scenes to measure, by file name: the embedded examples, or a folder's RON files
/// (those without meshes).
fn example_scenes(folder: Option<&Path>) -> Result<Vec<(String, Scene)>, String> {
    let Some(folder) = folder else {
        return EXAMPLE_SCENES
            .iter()
            .map(|(name, text)| {
                parse_scene(text)
                    .map(|scene| ((*name).to_owned(), scene))
                    .map_err(|e| format!("{name}: {e}"))
            })
            .collect();
    };
    let mut paths: Vec<PathBuf> = std::fs::read_dir(folder)
        .map_err(|e| format!("cannot read {}: {e}", folder.display()))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    paths.sort();
    paths
        .iter()
        .map(|path| {
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            load_scene(path)
                .map(|scene| (name.into_owned(), scene))
                .map_err(|e| format!("{}: {e}", path.display()))
        })
        // Scenes with meshes are measured by the mesh section, not per scene.
        .filter(|loaded| {
            !loaded
                .as_ref()
                .is_ok_and(|(_, scene)| !crate::scene::mesh_objects(scene).is_empty())
        })
        .collect()
}

fn measure(args: &BenchArgs) -> Result<BenchReport, String> {
    let runs = if args.quick { 2 } else { 5 };
    let examples = example_scenes(args.scenes.as_deref())?;
    let default_scene = examples
        .iter()
        .find(|(name, _)| name == "default.ron")
        .map(|(_, scene)| scene.clone())
        .ok_or("the scenes folder has no default.ron")?;
    let mut scenes = Vec::new();
    for (name, scene) in &examples {
        eprintln!("throughput: {name}");
        scenes.push(scene_throughput(name, scene, 800, 600, runs)?);
    }
    let default = scenes
        .iter()
        .find(|s| s.scene == "default.ron")
        .ok_or("the scenes folder has no default.ron")?
        .clone();
    eprintln!("speed against error: default scene");
    let plan = if args.quick {
        ConvergencePlan {
            width: 200,
            height: 150,
            reference_spp: 256,
            uniform_spp: vec![1, 2, 4, 8, 16],
            adaptive_spp: vec![4, 8, 16],
        }
    } else {
        ConvergencePlan {
            width: 400,
            height: 300,
            reference_spp: 1024,
            uniform_spp: vec![1, 2, 4, 8, 16, 32, 64],
            adaptive_spp: vec![4, 8, 16, 32, 64],
        }
    };
    let curve = convergence_curves(&default_scene, &plan)?;
    // Soft shadows converge only if a pixel's samples aim at different points of the
    // light: the same curve on the sphere-light example shows they do, and at what cost.
    let sphere_light_curve = match examples.iter().find(|(name, _)| name == SPHERE_LIGHT_SCENE) {
        Some((name, scene)) => {
            eprintln!("speed against error: {name} (a sphere light)");
            convergence_curves(scene, &plan)?
        }
        None => Vec::new(),
    };
    eprintln!("preview latency: default scene through the preview worker");
    let latency = crate::preview::measure_latency(
        &default_scene,
        if args.quick { 5 } else { 20 },
        std::time::Duration::from_secs(60),
    )
    .ok_or("the preview worker did not answer")?;
    eprintln!("restart latency: an edit midway through the last pass");
    let restart_latency_ms = restart_latency(&default_scene, if args.quick { 3 } else { 7 })?;
    eprintln!("edit to full frame: by kind of edit, through the preview worker");
    let edit_to_full_frame_ms = edit_latency(&default_scene, if args.quick { 5 } else { 15 })?;
    let glass_edit_to_full_frame_ms = match examples.iter().find(|(name, _)| name == GLASS_SCENE) {
        Some((name, scene)) => {
            eprintln!("edit to full frame: {name}, the glass's material first");
            Some(edit_latency(
                &glass_first(scene),
                if args.quick { 5 } else { 15 },
            )?)
        }
        None => None,
    };
    eprintln!("acceleration: flat list against BVH");
    let counts: &[usize] = if args.quick {
        &[4, 16, 64]
    } else {
        &[2, 4, 8, 12, 16, 24, 32, 64, 128, 256]
    };
    let bvh_crossover = bvh_crossover(counts, 320, 240, runs)?;
    eprintln!("precision: f32 and f64 kernels");
    let precision = precision_cost(if args.quick { 200_000 } else { 1_000_000 }, runs);
    eprintln!("diff: a 500x500 scene, 5 objects, 3 lights");
    let (diff_500_ms, _) = crate::bench::diff::diff_time(runs)?;
    eprintln!("diff: a 1280x720 course scene with mirrors, 4 samples a pixel");
    let (diff_1280x720_ms, _) = crate::bench::diff::diff_1280_time(runs.min(2))?;
    let (students, class_scenes) = if args.quick { (3, 4) } else { (6, 10) };
    eprintln!("class: {students} students x {class_scenes} scenes at 400x300, planted bugs");
    let class_pairs_per_minute =
        crate::bench::class::class_pairs_per_minute(students, class_scenes, (400, 300))?;
    eprintln!("diff accuracy: bugs planted in example and random scenes");
    let accuracy = crate::bench::diff_accuracy::report_accuracy(&examples, args.quick)?;
    // A million triangles even in a quick run: the targets are stated for that size.
    let mesh = crate::bench::mesh::mesh_bench(1_000_000, 800, 600, runs.min(3));
    eprintln!("mesh: edit to first preview frame, 1,000,000 triangles on a floor");
    let mesh_edit =
        crate::bench::mesh::mesh_edit_latency(1_000_000, if args.quick { 5 } else { 9 })?;
    Ok(BenchReport {
        quick: args.quick,
        threads: rayon::current_num_threads(),
        throughput_mrays_per_s: default.mrays_per_s,
        full_frame_1spp_ms: default.frame_ms,
        first_preview_ms: Some(latency.first_frame.as_secs_f64() * 1e3),
        first_full_preview_ms: Some(latency.full_resolution.as_secs_f64() * 1e3),
        restart_latency_ms,
        edit_to_full_frame_ms,
        glass_edit_to_full_frame_ms,
        scenes,
        curve_checks: curve_checks(&curve),
        curve,
        sphere_light_curve,
        precision,
        bvh_crossover,
        diff_500_ms,
        diff_1280x720_ms,
        class_pairs_per_minute,
        diff_top1: accuracy.top1(),
        diff_top2: accuracy.top2(),
        diff_false_verdicts: accuracy.false_verdicts(),
        mesh_triangles: mesh.triangles,
        mesh_build_ms: mesh.build_ms,
        mesh_mrays_per_s: mesh.mrays_per_s,
        mesh_bytes_per_triangle: mesh.bytes_per_triangle,
        mesh_edit_first_frame_ms: Some(mesh_edit),
    })
}

/// The example whose speed-against-error curve shows a sphere light's soft shadows.
const SPHERE_LIGHT_SCENE: &str = "soft_spot.ron";

/// The example whose edits show the cache holding trees of rays (glass).
const GLASS_SCENE: &str = "glass.ron";

/// `scene` with its first object of a transmissive material moved to the front: the
/// edit latency edits the first object's material.
fn glass_first(scene: &Scene) -> Scene {
    let mut scene = scene.clone();
    let transmits = |o: &crate::scene::Object| {
        (scene.materials.get(&o.material)).is_some_and(|m| m.transmission != glam::DVec3::ZERO)
    };
    if let Some(at) = scene.objects.iter().position(transmits) {
        let glass = scene.objects.remove(at);
        scene.objects.insert(0, glass);
    }
    scene
}

/// Sample counts whose restart latency the report gives.
const RESTART_SPP: [u32; 2] = [16, 4096];

/// The default scene at 64 x 48 (small enough to reach the last pass of 4096 samples in
/// about a second) at each of [`RESTART_SPP`]: median milliseconds from an edit midway
/// through the last pass to the edit's first frame.
fn restart_latency(
    scene: &Scene,
    runs: u32,
) -> Result<std::collections::BTreeMap<String, f64>, String> {
    let mut small = scene.clone();
    small.camera.width = 64;
    small.camera.height = 48;
    RESTART_SPP
        .iter()
        .map(|&spp| {
            small.render.samples_per_pixel = spp;
            let timeout = std::time::Duration::from_secs(120);
            crate::preview::measure_restart_latency(&small, runs, timeout)
                .map(|latency| (spp.to_string(), latency.as_secs_f64() * 1e3))
                .ok_or_else(|| format!("no restart latency measured at {spp} spp"))
        })
        .collect()
}

fn print_tables(report: &BenchReport) {
    println!(
        "threads: {}{}",
        report.threads,
        if report.quick { " (quick run)" } else { "" }
    );
    println!();
    println!(
        "| scene | size | frame (ms) | primary | shadow | reflection | transmission | Mrays/s |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for s in &report.scenes {
        println!(
            "| {} | {}x{} | {:.1} | {} | {} | {} | {} | {:.2} |",
            s.scene,
            s.width,
            s.height,
            s.frame_ms,
            s.primary_rays,
            s.shadow_rays,
            s.reflection_rays,
            s.transmission_rays,
            s.mrays_per_s
        );
    }
    println!();
    let latency = |v: Option<f64>| v.map_or("not measured".to_owned(), |ms| format!("{ms:.1} ms"));
    println!(
        "edit to first coarse preview frame: {}",
        latency(report.first_preview_ms)
    );
    println!(
        "edit to first full-resolution preview frame: {}",
        latency(report.first_full_preview_ms)
    );
    for (spp, ms) in &report.restart_latency_ms {
        println!(
            "edit midway through the last pass at {spp} spp (64x48) to its first frame: {ms:.2} ms"
        );
    }
    let e = &report.edit_to_full_frame_ms;
    let frame = report.full_frame_1spp_ms;
    println!();
    println!("| edit | to first full-resolution frame (ms) | / full_frame_1spp_ms |");
    println!("|---|---|---|");
    for (kind, ms) in [
        ("material", e.material),
        ("switch", e.switch),
        ("light colour", e.light_colour),
        ("light move", e.light_move),
        ("geometry", e.geometry),
    ] {
        println!("| {kind} | {ms:.1} | {:.2} |", ms / frame);
    }
    if let Some(g) = &report.glass_edit_to_full_frame_ms {
        println!();
        println!(
            "{GLASS_SCENE}, the glass's material edited (ms to the first full-resolution frame):"
        );
        println!(
            "material {:.1}, switch {:.1}, light colour {:.1}, light move {:.1}, geometry {:.1}",
            g.material, g.switch, g.light_colour, g.light_move, g.geometry
        );
    }
    println!();
    print_curve(&report.curve, &report.curve_checks);
    if !report.sphere_light_curve.is_empty() {
        println!();
        println!("speed against error, {SPHERE_LIGHT_SCENE} (a sphere light, soft shadows):");
        let checks = curve_checks(&report.sphere_light_curve);
        print_curve(&report.sphere_light_curve, &checks);
    }
    println!();
    println!("| objects | flat list (ms) | BVH (ms) | BVH / flat |");
    println!("|---|---|---|---|");
    for c in &report.bvh_crossover {
        println!(
            "| {} | {:.1} | {:.1} | {:.2} |",
            c.objects,
            c.flat_ms,
            c.bvh_ms,
            c.bvh_ms / c.flat_ms
        );
    }
    println!();
    let p = &report.precision;
    println!(
        "intersection kernel, {} rays x 8 spheres: f32 {:.1} ns/ray, f64 {:.1} ns/ray, f64/f32 = {:.2}",
        p.rays, p.f32_ns_per_ray, p.f64_ns_per_ray, p.f64_over_f32
    );
    println!(
        "diff of a 500x500 scene (5 objects, 3 lights): {:.1} ms",
        report.diff_500_ms
    );
    println!(
        "diff of a 1280x720 course scene with mirrors (4 spp, 11 objects): {:.1} ms",
        report.diff_1280x720_ms
    );
    println!(
        "class of generated students (400x300, planted bugs): {:.1} pairs per minute",
        report.class_pairs_per_minute
    );
    println!(
        "diff accuracy (bugs alone): named first {:.1}%, in the top two {:.1}%; a bug claimed in {:.1}% of correct pictures",
        100.0 * report.diff_top1,
        100.0 * report.diff_top2,
        100.0 * report.diff_false_verdicts
    );
    println!(
        "mesh: {} triangles, build {:.0} ms, {:.2} Mrays/s primary, {:.1} bytes per triangle",
        report.mesh_triangles,
        report.mesh_build_ms,
        report.mesh_mrays_per_s,
        report.mesh_bytes_per_triangle
    );
    if let Some(edit) = &report.mesh_edit_first_frame_ms {
        println!(
            "mesh scene (800x600, 4 spp): edit to first preview frame: material {:.1} ms, light colour {:.1} ms",
            edit.material, edit.light_colour
        );
    }
}

/// A speed-against-error curve as a table, with its checks.
fn print_curve(curve: &[crate::bench::CurvePoint], checks: &crate::bench::CurveChecks) {
    println!("| strategy | spp | time (ms) | RMSE | estimated RMSE | PSNR (dB) |");
    println!("|---|---|---|---|---|---|");
    for p in curve {
        let estimate = p
            .estimated_rmse
            .map_or(String::new(), |e| format!("{e:.5}"));
        println!(
            "| {} | {:.3} | {:.1} | {:.5} | {estimate} | {:.2} |",
            p.strategy, p.spp, p.time_ms, p.rmse, p.psnr
        );
    }
    println!(
        "progressive RMSE / uniform RMSE at equal spp: at most {:.3}; preview estimate / true RMSE from 4 spp: {:.2} to {:.2}",
        checks.progressive_over_uniform, checks.estimate_over_true[0], checks.estimate_over_true[1]
    );
}
