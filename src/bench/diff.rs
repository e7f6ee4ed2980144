//! The speed of `raylab diff`: a 500x500 scene with 5 objects and 3 lights (the
//! comparison tests' scene, enlarged) against raylab's own render of it with one light
//! at half strength, timed from the scene and the 8-bit image to the finished report;
//! and a course scene like the slowest pair of the public corpus (1280x720, 4 samples a
//! pixel, 11 objects, mirrors: `scripts/bench/diff/mirrors_1280.txt`) against its
//! picture by a tracer that blends mirrors.

use std::time::Instant;

use crate::compare::plant::{parse_bugs, plant};
use crate::compare::{CompareOptions, OtherImage, compare};
use crate::scene::legacy::import_legacy;
use crate::scene::{Light, LightSource, Scene, parse_scene};
use crate::trace::{MeshStore, RenderOptions, RenderProgress, World, render};

/// The course scene like the corpus's slowest pair (issue 50).
const MIRRORS_1280: &str = include_str!("../../scripts/bench/diff/mirrors_1280.txt");

/// The benchmark scene: five objects (two planes, two spheres, a cone), three lights.
const SCENE: &str = r#"Scene(
    camera: (position: (0.0, 2.0, 8.0), look_at: (0.0, 0.9, 0.0), fov_deg: 40.0, width: 500, height: 500),
    render: (max_depth: 4, background: (0.05, 0.06, 0.09), samples_per_pixel: 1),
    materials: {
        "floor": (ambient: (0.2, 0.2, 0.2), diffuse: (0.5, 0.5, 0.5), specular: (0.3, 0.3, 0.3), shininess: 10.0),
        "wall": (ambient: (0.15, 0.2, 0.25), diffuse: (0.3, 0.4, 0.5), specular: (0.2, 0.2, 0.2), shininess: 5.0),
        "red": (ambient: (0.1, 0.02, 0.02), diffuse: (0.7, 0.1, 0.1), specular: (0.8, 0.8, 0.8), shininess: 2.0),
        "mirror": (ambient: (0.02, 0.02, 0.02), diffuse: (0.05, 0.05, 0.05), specular: (0.6, 0.6, 0.6), shininess: 60.0, mirror: (0.85, 0.85, 0.85)),
        "gold": (ambient: (0.15, 0.1, 0.02), diffuse: (0.6, 0.45, 0.1), specular: (0.6, 0.5, 0.3), shininess: 20.0),
    },
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (6.0, 6.0, 1.0)), material: "floor"),
        (name: "wall", shape: Plane, transform: (translate: (0.0, 2.5, -3.0), rotate_deg: (0.0, 180.0, 0.0), scale: (6.0, 2.5, 1.0)), material: "wall"),
        (name: "red ball", shape: Sphere, transform: (translate: (-1.5, 0.8, 0.6), scale: (0.8, 0.8, 0.8)), material: "red"),
        (name: "mirror ball", shape: Sphere, transform: (translate: (0.6, 1.0, -0.8)), material: "mirror"),
        (name: "gold cone", shape: Cone, transform: (translate: (2.2, 1.3, 1.0), rotate_deg: (90.0, 0.0, 0.0), scale: (0.6, 0.6, 1.3)), material: "gold"),
    ],
    lights: [
        Ambient(colour: (0.15, 0.15, 0.15)),
        Point(position: (-3.0, 5.0, 4.0), colour: (1.0, 0.95, 0.9), intensity: 40.0),
        Directional(direction: (0.5, -1.0, -0.3), colour: (0.5, 0.5, 0.6), intensity: 1.0),
    ],
)"#;

/// The benchmark scene.
///
/// # Panics
/// Never: the scene text is fixed and valid (a test loads it).
#[must_use]
pub fn diff_scene() -> Scene {
    parse_scene(SCENE).expect("the benchmark scene is valid")
}

/// The best time of `runs` comparisons, in milliseconds, and the top explanation's
/// summary of the last.
///
/// # Errors
/// A message if the comparison fails.
pub fn diff_time(runs: u32) -> Result<(f64, String), String> {
    let scene = diff_scene();
    let mut dimmed = scene.clone();
    if let Some(Light::Point {
        source: LightSource { intensity, .. },
        ..
    }) = dimmed.lights.get_mut(1)
    {
        *intensity *= 0.5;
    }
    let world = World::new(&dimmed).map_err(|e| e.to_string())?;
    let options = RenderOptions::from_scene(&dimmed);
    let (image, _) = render(&world, &options, &RenderProgress::default()).ok_or("cancelled")?;
    let rgb = image
        .to_rgba8()
        .chunks(4)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    let other = OtherImage::new(image.width, image.height, rgb);
    best_compare(&scene, &other, runs)
}

/// The best time of `runs` comparisons of `scene` with `other`, in milliseconds, and the
/// top explanation's summary of the last.
fn best_compare(scene: &Scene, other: &OtherImage, runs: u32) -> Result<(f64, String), String> {
    let mut best = f64::INFINITY;
    let mut top = String::new();
    for _ in 0..runs.max(1) {
        let started = Instant::now();
        let comparison = compare(
            scene,
            other,
            &CompareOptions::default(),
            &RenderProgress::default(),
        )
        .map_err(|e| e.to_string())?;
        best = best.min(started.elapsed().as_secs_f64() * 1e3);
        top = comparison
            .explanations
            .first()
            .map_or_else(String::new, |e| e.summary.clone());
    }
    Ok((best, top))
}

/// The course scene like the corpus's slowest pair, imported.
///
/// # Panics
/// Never: the scene text is fixed and valid (a test loads it).
#[must_use]
pub fn mirrors_1280_scene() -> Scene {
    import_legacy(MIRRORS_1280)
        .expect("the benchmark course scene is valid")
        .scene
}

/// The best time of `runs` comparisons of the 1280x720 course scene with mirrors with
/// its picture by a tracer that blends mirrors, in milliseconds, and the top
/// explanation's summary of the last.
///
/// # Errors
/// A message if the picture or the comparison fails.
pub fn diff_1280_time(runs: u32) -> Result<(f64, String), String> {
    let scene = mirrors_1280_scene();
    let meshes = MeshStore::default();
    let bugs = parse_bugs("mirror-blend", &scene)?;
    let spp = scene.render.samples_per_pixel;
    let other = plant(&scene, &meshes, &bugs, spp, &RenderProgress::default())
        .map_err(|e| e.to_string())?;
    best_compare(&scene, &other, runs)
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_benchmark_scene_has_five_objects_and_three_lights() {
        let scene = super::diff_scene();
        assert_eq!((scene.objects.len(), scene.lights.len()), (5, 3));
        assert_eq!((scene.camera.width, scene.camera.height), (500, 500));
    }

    #[test]
    fn the_course_benchmark_scene_is_1280x720_supersampled_with_11_objects_and_mirrors() {
        let scene = super::mirrors_1280_scene();
        assert_eq!(scene.objects.len(), 11);
        assert_eq!((scene.camera.width, scene.camera.height), (1280, 720));
        assert_eq!(scene.render.samples_per_pixel, 4);
        let mirrors = scene
            .objects
            .iter()
            .filter(|o| scene.materials[&o.material].mirror != glam::DVec3::ZERO);
        assert!(mirrors.count() >= 3);
    }
}
