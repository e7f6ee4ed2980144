//! The example scenes of `scenes/`, embedded in the binary: the editor's default scene
//! and the scenes `raylab bench` measures, so both work from any folder.

/// The editor's default scene (`scenes/default.ron`), which uses every part of the format.
pub const DEFAULT_SCENE_RON: &str = include_str!("../../scenes/default.ron");

/// Every example scene as `(file name, RON text)`, sorted by file name.
pub const EXAMPLE_SCENES: [(&str, &str); 10] = [
    (
        "coloured_shadows.ron",
        include_str!("../../scenes/coloured_shadows.ron"),
    ),
    ("csg.ron", include_str!("../../scenes/csg.ron")),
    ("default.ron", DEFAULT_SCENE_RON),
    ("glass.ron", include_str!("../../scenes/glass.ron")),
    (
        "mirror_cap.ron",
        include_str!("../../scenes/mirror_cap.ron"),
    ),
    (
        "more_shapes.ron",
        include_str!("../../scenes/more_shapes.ron"),
    ),
    ("shapes.ron", include_str!("../../scenes/shapes.ron")),
    ("soft_spot.ron", include_str!("../../scenes/soft_spot.ron")),
    (
        "specular_exponents.ron",
        include_str!("../../scenes/specular_exponents.ron"),
    ),
    (
        "spotlights.ron",
        include_str!("../../scenes/spotlights.ron"),
    ),
];

/// The default scene, parsed.
///
/// # Panics
/// Never: the embedded file is checked by the tests.
#[must_use]
pub fn default_scene() -> super::Scene {
    super::parse_scene(DEFAULT_SCENE_RON).expect("the embedded default scene is valid")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_embedded_example_is_a_valid_scene_and_the_folder_has_no_other() {
        for (name, text) in EXAMPLE_SCENES {
            let scene = super::super::parse_scene(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            super::super::validate(&scene).unwrap();
        }
        let mut on_disk: Vec<String> =
            std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .filter(|n| n.ends_with(".ron"))
                // Scenes with meshes need their OBJ files beside them: not embedded.
                .filter(|n| {
                    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/").to_owned() + n;
                    let scene = super::super::load_scene(std::path::Path::new(&path)).unwrap();
                    super::super::mesh_objects(&scene).is_empty()
                })
                .collect();
        on_disk.sort();
        let embedded: Vec<&str> = EXAMPLE_SCENES.iter().map(|(n, _)| *n).collect();
        assert_eq!(on_disk, embedded, "embed every scene of scenes/ here");
    }
}
