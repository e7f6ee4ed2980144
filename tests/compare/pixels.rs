//! Where an object shows in raylab's picture, for the comparison tests that check a
//! verdict's bounding box: the pixels whose camera ray (one sample, at the pixel's
//! centre as raylab's first sample) meets the object first.
#![allow(dead_code)]

use glam::DVec2;
use raylab::compare::PixelBox;
use raylab::scene::Scene;
use raylab::trace::{PinholeCamera, World, sample_in_pixel};

/// The bounding box of the pixels where `scene`'s object `index` (a top-level object
/// of a scene without groups) is hit first.
pub fn object_box(scene: &Scene, index: usize) -> PixelBox {
    let world = World::new(scene).unwrap();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let camera = PinholeCamera::new(&scene.camera, w, h);
    let pixels: Vec<u32> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let point = DVec2::new(f64::from(x), f64::from(y)) + sample_in_pixel(x, y, 0, 1);
            let hit = world.intersect(&camera.ray(point), f64::INFINITY);
            hit.is_some_and(|hit| world.scene_object(hit.object) == index)
        })
        .map(|(x, y)| y * w + x)
        .collect();
    PixelBox::of(&pixels, w).expect("the object is in the picture")
}

/// Whether two boxes agree within `slack` pixels on every side.
pub fn boxes_agree(a: PixelBox, b: PixelBox, slack: u32) -> bool {
    a.x0.abs_diff(b.x0) <= slack
        && a.y0.abs_diff(b.y0) <= slack
        && a.x1.abs_diff(b.x1) <= slack
        && a.y1.abs_diff(b.y1) <= slack
}
