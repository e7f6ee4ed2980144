//! Scale and place invariance: the default scene (every shape and light kind, mirrors,
//! shadows, objects resting on the floor) and the eight-shape scene (tori, tubes and
//! octahedra too, on a mirror floor) scaled by 1e-3, 1e3 and 1e5, or moved 1e6 units
//! away with their camera, render the same picture.

use std::path::Path;

use glam::DVec3;
use raylab::scene::{
    Light, LightSource, Scene, Transform, affine_from_rows, load_scene, rows_from_affine,
};
use raylab::trace::{RenderOptions, RenderProgress, World, render};

/// The scene with every length multiplied by `scale` and then moved by `offset`; point
/// and spot intensities grow with the square of the scale so the picture is unchanged.
fn scaled_and_moved(scene: &Scene, scale: f64, offset: DVec3) -> Scene {
    let place = |p: DVec3| p * scale + offset;
    let mut out = scene.clone();
    out.camera.position = place(scene.camera.position);
    out.camera.look_at = place(scene.camera.look_at);
    for object in &mut out.objects {
        object.transform = match object.transform {
            Transform::Trs(mut trs) => {
                trs.translate = place(trs.translate);
                trs.scale *= scale;
                Transform::Trs(trs)
            }
            Transform::Matrix(rows) => {
                let mut m = affine_from_rows(&rows);
                m.matrix3 *= scale;
                m.translation = place(m.translation);
                Transform::Matrix(rows_from_affine(&m))
            }
        };
    }
    for light in &mut out.lights {
        match light {
            Light::Point {
                position,
                source: LightSource { intensity, .. },
            }
            | Light::Spot {
                position,
                source: LightSource { intensity, .. },
                ..
            } => {
                *position = place(*position);
                *intensity *= scale * scale;
            }
            Light::Ambient { .. } | Light::Directional { .. } => {}
        }
    }
    out
}

fn render_rgb(scene: &Scene) -> Vec<u8> {
    let world = World::new(scene).unwrap();
    let mut options = RenderOptions::from_scene(scene);
    options.width = 200;
    options.height = 150;
    options.samples_per_pixel = 1;
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
        .to_rgba8()
}

fn assert_same_picture(label: &str, scale: f64, offset: DVec3) {
    for scene in ["default.ron", "more_shapes.ron", "glass.ron"] {
        assert_same_picture_of(scene, label, scale, offset);
    }
}

fn assert_same_picture_of(scene: &str, label: &str, scale: f64, offset: DVec3) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(scene);
    let original = load_scene(&path).unwrap();
    let reference = render_rgb(&original);
    let changed = render_rgb(&scaled_and_moved(&original, scale, offset));
    let pixels = reference.len() / 4;
    let within = reference
        .chunks(4)
        .zip(changed.chunks(4))
        .filter(|(a, b)| a.iter().zip(b.iter()).all(|(x, y)| x.abs_diff(*y) <= 2))
        .count();
    let fraction = within as f64 / pixels as f64;
    assert!(
        fraction >= 0.995,
        "{scene} {label}: only {:.3}% of pixels within 2/255",
        fraction * 100.0
    );
}

#[test]
fn scaled_down_a_thousand_times() {
    assert_same_picture("x1e-3", 1e-3, DVec3::ZERO);
}

#[test]
fn scaled_up_a_thousand_times() {
    assert_same_picture("x1e3", 1e3, DVec3::ZERO);
}

#[test]
fn scaled_up_a_hundred_thousand_times() {
    assert_same_picture("x1e5", 1e5, DVec3::ZERO);
}

#[test]
fn moved_a_million_units_away_with_its_camera() {
    assert_same_picture("+1e6", 1.0, DVec3::new(1e6, -1e6, 1e6));
}

#[test]
fn scaled_down_and_moved_far_away() {
    assert_same_picture("x1e-3 +1e6", 1e-3, DVec3::new(0.0, 0.0, 1e6));
}
