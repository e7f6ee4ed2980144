//! A generated class: the example scenes at a chosen size, and students whose renders
//! are raylab's own with planted bugs (a light muted, an object hidden, a term off), as
//! a student's tracer with that bug would draw them. `raylab bench` times `raylab class`
//! on one ([`class_pairs_per_minute`]); the tests and scripts/class_bench.sh build
//! classes with it too.

use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

use glam::DVec3;

use crate::class::{ClassOptions, run_class};
use crate::scene::examples::EXAMPLE_SCENES;
use crate::scene::{Light, Scene, parse_scene, save_scene};
use crate::trace::{Isolation, RenderOptions, RenderProgress, Term, TermSwitches, World, render};

/// A bug planted in a student's render.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlantedBug {
    /// No bug: raylab's own render.
    None,
    /// The light at this index of the scene's list is left out.
    MutedLight(usize),
    /// The object at this index of the scene's list is left out.
    HiddenObject(usize),
    /// The term is switched off.
    TermOff(Term),
}

/// raylab's render of `scene` with `bug` planted, at the scene's size and samples per
/// pixel, as PNG bytes written as raylab writes them.
///
/// # Errors
/// The scene does not render (or the bug names a light or object it does not have).
pub fn render_with_bug(scene: &Scene, bug: &PlantedBug) -> Result<Vec<u8>, String> {
    let mut isolation = Isolation::NONE;
    let mut switches = TermSwitches::ALL_ON;
    match bug {
        PlantedBug::None => {}
        PlantedBug::MutedLight(light) => {
            isolation.muted_lights.insert(*light);
        }
        PlantedBug::HiddenObject(object) => {
            isolation.hidden_objects.insert(*object);
        }
        PlantedBug::TermOff(term) => switches.set(*term, false),
    }
    let world = World::isolated(scene, &isolation).map_err(|e| e.to_string())?;
    let options = RenderOptions {
        switches,
        isolation,
        ..RenderOptions::from_scene(scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).ok_or("cancelled")?;
    Ok(image.png_bytes_as(scene.render.conventions.quantise))
}

/// The example scenes without meshes, each at `width` x `height`, named by file stem;
/// `count` of them, the examples first and then each again seen from a camera turned
/// 40 degrees about its target (`default_turned`).
///
/// # Errors
/// Never for the embedded examples; a message if one did not parse.
pub fn class_scenes(count: usize, width: u32, height: u32) -> Result<Vec<(String, Scene)>, String> {
    let mut examples = Vec::new();
    for (name, text) in EXAMPLE_SCENES {
        let mut scene = parse_scene(text).map_err(|e| format!("{name}: {e}"))?;
        scene.camera.width = width;
        scene.camera.height = height;
        examples.push((name.trim_end_matches(".ron").to_owned(), scene));
    }
    let mut scenes: Vec<(String, Scene)> = Vec::new();
    for i in 0..count {
        let (name, scene) = &examples[i % examples.len()];
        let mut scene = scene.clone();
        let turns = i / examples.len();
        let mut name = name.clone();
        if turns > 0 {
            let offset = scene.camera.position - scene.camera.look_at;
            let angle = (40.0 * turns as f64).to_radians();
            let turned = glam::DQuat::from_axis_angle(DVec3::Y, angle) * offset;
            scene.camera.position = scene.camera.look_at + turned;
            name = format!(
                "{name}_turned{}",
                if turns > 1 {
                    turns.to_string()
                } else {
                    String::new()
                }
            );
        }
        scenes.push((name, scene));
    }
    Ok(scenes)
}

/// The bug student `student` plants in scene `scene`: each student leaves one scene in
/// four right and plants a muted light, a hidden object or a term switched off in the
/// others, in turn.
#[must_use]
pub fn planted_bug(student: usize, scene: &Scene, index: usize) -> PlantedBug {
    let lit: Vec<usize> = (0..scene.lights.len())
        .filter(|&l| !matches!(scene.lights[l], Light::Ambient { .. }))
        .collect();
    match (student + index) % 4 {
        1 if !lit.is_empty() => PlantedBug::MutedLight(lit[student % lit.len()]),
        2 if !scene.objects.is_empty() => PlantedBug::HiddenObject(student % scene.objects.len()),
        3 => PlantedBug::TermOff([Term::Specular, Term::Shadows, Term::Diffuse][student % 3]),
        _ => PlantedBug::None,
    }
}

/// Writes a class into `folder`: `scenes/NAME.ron` for `scene_count` scenes and
/// `submissions/student_NN/NAME.png` for `students` students, bugs planted by
/// [`planted_bug`]. Returns the number of pairs.
///
/// # Errors
/// A scene does not render, or a file cannot be written.
pub fn generate_class(
    folder: &Path,
    students: usize,
    scene_count: usize,
    (width, height): (u32, u32),
) -> Result<usize, String> {
    let scenes = class_scenes(scene_count, width, height)?;
    let scene_folder = folder.join("scenes");
    std::fs::create_dir_all(&scene_folder).map_err(|e| e.to_string())?;
    for (name, scene) in &scenes {
        save_scene(scene, &scene_folder.join(format!("{name}.ron"))).map_err(|e| e.to_string())?;
    }
    for student in 0..students {
        let student_folder = folder
            .join("submissions")
            .join(format!("student_{student:02}"));
        std::fs::create_dir_all(&student_folder).map_err(|e| e.to_string())?;
        for (index, (name, scene)) in scenes.iter().enumerate() {
            let rendered = render_with_bug(scene, &planted_bug(student, scene, index))?;
            let bytes = signed(&rendered, student)?;
            let path = student_folder.join(format!("{name}.png"));
            std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        }
    }
    Ok(students * scenes.len())
}

/// `png` with student `student`'s mark: one channel of one pixel (the student's index,
/// counted row by row) a level off. Students with the same planted bug would otherwise
/// hand in the same bytes, which the class's cache compares once: a real class's
/// renders all differ, and the timing must compare every pair. One level at one pixel
/// is below what the comparison explains.
///
/// # Errors
/// `png` is not a PNG.
pub fn signed(png: &[u8], student: usize) -> Result<Vec<u8>, String> {
    let mut image = image::load_from_memory(png)
        .map_err(|e| format!("generated render: {e}"))?
        .to_rgb8();
    let (width, height) = image.dimensions();
    let at = student % (width as usize * height as usize);
    let pixel = image.get_pixel_mut((at % width as usize) as u32, (at / width as usize) as u32);
    pixel.0[0] = if pixel.0[0] < 255 {
        pixel.0[0] + 1
    } else {
        254
    };
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .map_err(|e| format!("generated render: {e}"))?;
    Ok(bytes)
}

/// Pairs per minute of `raylab class` on a generated class of `students` students and
/// `scene_count` scenes at `size`, every pair compared (a fresh report, no cache), with
/// the class written to a temporary folder and removed after.
///
/// # Errors
/// The class cannot be written or the run fails.
pub fn class_pairs_per_minute(
    students: usize,
    scene_count: usize,
    size: (u32, u32),
) -> Result<f64, String> {
    let folder = std::env::temp_dir().join(format!("raylab-bench-class-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    let result = (|| {
        let pairs = generate_class(&folder, students, scene_count, size)?;
        let started = Instant::now();
        let run = run_class(
            &folder.join("scenes"),
            &folder.join("submissions"),
            &folder.join("report"),
            &ClassOptions::default(),
            &AtomicBool::new(false),
            &|_, _| {},
        )?;
        crate::class::write_report(&run, &folder.join("report"))?;
        let minutes = started.elapsed().as_secs_f64() / 60.0;
        if run.computed != pairs {
            return Err(format!("{} of {pairs} pairs compared", run.computed));
        }
        Ok(pairs as f64 / minutes)
    })();
    let _ = std::fs::remove_dir_all(&folder);
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_students_render_differs_even_with_the_same_bug() {
        let folder =
            std::env::temp_dir().join(format!("raylab-generated-class-{}", std::process::id()));
        let pairs = generate_class(&folder, 5, 2, (24, 18)).unwrap();
        assert_eq!(pairs, 10);
        let mut seen = std::collections::HashSet::new();
        for student in 0..5 {
            let renders = folder
                .join("submissions")
                .join(format!("student_{student:02}"));
            for entry in std::fs::read_dir(&renders).unwrap() {
                let bytes = std::fs::read(entry.unwrap().path()).unwrap();
                assert!(
                    seen.insert(bytes),
                    "student {student}: a render another handed in"
                );
            }
        }
        // Students 0 and 4 plant the same bug in each scene: only their marks differ.
        let scenes = class_scenes(2, 24, 18).unwrap();
        assert_eq!(
            planted_bug(0, &scenes[0].1, 0),
            planted_bug(4, &scenes[0].1, 0)
        );
        std::fs::remove_dir_all(&folder).unwrap();
    }
}
