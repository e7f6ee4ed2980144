//! raylab's own render of a scene, written as raylab writes it: the other picture of
//! tests whose student renders a changed scene with a correct tracer.
#![allow(dead_code)]

use raylab::compare::OtherImage;
use raylab::scene::Scene;
use raylab::trace::{RenderOptions, RenderProgress, TermSwitches, World, render};

/// raylab's render of `scene` at one sample per pixel, as 8-bit bytes.
pub fn own_render(scene: &Scene) -> OtherImage {
    own_render_with(scene, TermSwitches::ALL_ON)
}

/// As [`own_render`], with the terms `switches` leaves on.
pub fn own_render_with(scene: &Scene, switches: TermSwitches) -> OtherImage {
    let world = World::new(scene).unwrap();
    let options = RenderOptions {
        samples_per_pixel: 1,
        switches,
        ..RenderOptions::from_scene(scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let rgb = image
        .to_rgba8()
        .chunks(4)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    OtherImage::new(scene.camera.width, scene.camera.height, rgb)
}
