//! `raylab diff` on a picture of another version of the scene (the camera moved, two
//! objects moved): named `different-scene` first, instead of a list of weak factors;
//! and never for pictures of this scene with one bug in them.

#[path = "compare/one_sample.rs"]
mod one_sample;

use std::path::Path;

use glam::DVec3;
use one_sample::diff;
use raylab::compare::{Comparison, OtherImage};
use raylab::scene::{Scene, Transform, load_scene};
use raylab::trace::{RenderOptions, RenderProgress, Term, World, render};

fn scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron");
    let mut scene = load_scene(&path).unwrap();
    scene.camera.width = 160;
    scene.camera.height = 120;
    scene
}

/// raylab's render of `scene` (one sample), with `off` switched off, as 8-bit bytes.
fn picture(scene: &Scene, off: Option<Term>) -> OtherImage {
    let world = World::new(scene).unwrap();
    let mut options = RenderOptions {
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(scene)
    };
    if let Some(term) = off {
        options.switches.set(term, false);
    }
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    OtherImage::from_bytes(
        &image.png_bytes_as(scene.render.conventions.quantise),
        Path::new("o.png"),
    )
    .unwrap()
}

fn causes(c: &Comparison) -> Vec<&'static str> {
    c.explanations.iter().map(|e| e.cause.name()).collect()
}

fn moved(scene: &Scene, name: &str, by: DVec3) -> Scene {
    let mut moved = scene.clone();
    let object = moved.objects.iter_mut().find(|o| o.name == name).unwrap();
    if let Transform::Trs(trs) = &mut object.transform {
        trs.translate += by;
    }
    moved
}

#[test]
fn a_picture_from_a_moved_camera_or_moved_objects_is_named_a_different_scene() {
    let scene = scene();
    let mut camera_moved = scene.clone();
    camera_moved.camera.position += DVec3::new(0.6, 0.3, -0.3);
    let objects_moved = moved(
        &moved(&scene, "red ball", DVec3::new(0.5, 0.0, 0.3)),
        "blue box",
        DVec3::new(-0.4, 0.0, 0.4),
    );
    for other in [camera_moved, objects_moved] {
        let c = diff(&scene, &picture(&other, None));
        let report = c.text_lines().join("\n");
        assert_eq!(causes(&c)[0], "different-scene", "{report}");
        assert!(c.explanations[0].share > 0.5, "{report}");
    }
}

#[test]
fn pictures_of_this_scene_with_one_bug_are_not_called_another_scene() {
    let scene = scene();
    for off in [
        None,
        Some(Term::Specular),
        Some(Term::Shadows),
        Some(Term::Reflection),
    ] {
        let c = diff(&scene, &picture(&scene, off));
        assert!(
            !causes(&c).contains(&"different-scene"),
            "{off:?}:\n{}",
            c.text_lines().join("\n")
        );
    }
    // One object moved is a geometry question about that object, not another scene.
    let c = diff(
        &scene,
        &picture(&moved(&scene, "red ball", DVec3::new(0.4, 0.0, 0.0)), None),
    );
    assert!(
        !causes(&c).contains(&"different-scene"),
        "{}",
        c.text_lines().join("\n")
    );
}
