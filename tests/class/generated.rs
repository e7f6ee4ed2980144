//! A small generated class for the `raylab class` tests: three example scenes at 80x60
//! and four students whose renders are raylab's own with planted bugs, plus the things
//! a real class hands in (a missing render, a picture of the wrong size, an unreadable
//! one, a stray file, a `_render` suffix, a file outside any student's folder).
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use raylab::bench::class::{PlantedBug, class_scenes, render_with_bug};
use raylab::scene::{Light, Scene, save_scene};
use raylab::trace::Term;

/// The class's folders.
pub struct Class {
    /// The root (removed and made anew by [`generate`]).
    pub root: PathBuf,
    /// The scenes by name.
    pub scenes: Vec<(String, Scene)>,
}

impl Class {
    pub fn scenes_dir(&self) -> PathBuf {
        self.root.join("scenes")
    }
    pub fn submissions_dir(&self) -> PathBuf {
        self.root.join("submissions")
    }
    pub fn scene(&self, name: &str) -> &Scene {
        &self.scenes.iter().find(|(n, _)| n == name).unwrap().1
    }
}

/// The index of the first light that is not ambient.
pub fn first_lit(scene: &Scene) -> usize {
    scene
        .lights
        .iter()
        .position(|l| !matches!(l, Light::Ambient { .. }))
        .unwrap()
}

/// The object hidden in bob's `shapes`.
pub const HIDDEN_IN_SHAPES: usize = 1;

fn write(path: &Path, bytes: &[u8]) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, bytes).unwrap();
}

/// Writes the class under the temp folder as `raylab-class-NAME-PID`:
/// - ann: every scene right (`spotlights_render.png` by a suffix);
/// - bob: no `default`, `shapes` with object 1 hidden, `spotlights` with its first lit
///   light muted, and `notes.txt` (a light muted in `default`, with its mirror ball,
///   reads as another mirror convention at this size: see the report of issue 49);
/// - cat: `default` with specular off, `shapes` at half size, `spotlights` not an image;
/// - dan: `DEFAULT_final.PNG` (case and suffix) with shadows off, nothing else;
/// - `README.txt` loose in the submissions folder.
pub fn generate(name: &str) -> Class {
    let root = std::env::temp_dir().join(format!("raylab-class-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let mut scenes: Vec<(String, Scene)> = class_scenes(10, 80, 60)
        .unwrap()
        .into_iter()
        .filter(|(n, _)| ["default", "shapes", "spotlights"].contains(&n.as_str()))
        .collect();
    for (_, scene) in &mut scenes {
        scene.render.samples_per_pixel = 1;
    }
    let class = Class { root, scenes };
    std::fs::create_dir_all(class.scenes_dir()).unwrap();
    for (name, scene) in &class.scenes {
        save_scene(scene, &class.scenes_dir().join(format!("{name}.ron"))).unwrap();
    }
    let submissions = class.submissions_dir();
    let render = |scene: &str, bug: PlantedBug| render_with_bug(class.scene(scene), &bug).unwrap();
    let spotlights = class.scene("spotlights");
    write(
        &submissions.join("ann/default.png"),
        &render("default", PlantedBug::None),
    );
    write(
        &submissions.join("ann/shapes.png"),
        &render("shapes", PlantedBug::None),
    );
    write(
        &submissions.join("ann/spotlights_render.png"),
        &render("spotlights", PlantedBug::None),
    );
    write(
        &submissions.join("bob/spotlights.png"),
        &render("spotlights", PlantedBug::MutedLight(first_lit(spotlights))),
    );
    write(
        &submissions.join("bob/shapes.png"),
        &render("shapes", PlantedBug::HiddenObject(HIDDEN_IN_SHAPES)),
    );
    write(&submissions.join("bob/notes.txt"), b"my tracer is great\n");
    write(
        &submissions.join("cat/default.png"),
        &render("default", PlantedBug::TermOff(Term::Specular)),
    );
    let mut small = class.scene("shapes").clone();
    small.camera.width = 40;
    small.camera.height = 30;
    write(
        &submissions.join("cat/shapes.png"),
        &render_with_bug(&small, &PlantedBug::None).unwrap(),
    );
    write(&submissions.join("cat/spotlights.png"), b"not a picture");
    write(
        &submissions.join("dan/DEFAULT_final.PNG"),
        &render("default", PlantedBug::TermOff(Term::Shadows)),
    );
    write(&submissions.join("README.txt"), b"hand-in instructions\n");
    class
}

/// Every file under `folder` with its bytes and modification time, sorted.
pub fn snapshot(folder: &Path) -> Vec<(PathBuf, Vec<u8>, std::time::SystemTime)> {
    let mut files = Vec::new();
    let mut work = vec![folder.to_path_buf()];
    while let Some(dir) = work.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                work.push(path);
            } else {
                let modified = std::fs::metadata(&path).unwrap().modified().unwrap();
                files.push((path.clone(), std::fs::read(&path).unwrap(), modified));
            }
        }
    }
    files.sort();
    files
}
