//! One pixel taken apart: every number the shader used for it (the pixel inspector) and
//! the tree of rays it cast (the ray-path overlay).

mod pixel;
mod ray_tree;

pub use pixel::{
    BounceReport, HitSurface, PixelOutside, PixelReport, inspect_pixel, pick, switches_text,
    try_inspect_pixel,
};
pub use ray_tree::{RayHit, RayKind, TracedRay, traced_rays};
