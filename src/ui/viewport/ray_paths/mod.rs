//! The ray-path overlay: a pixel's ray tree drawn in 3D over the viewport (the camera
//! ray from the scene camera through the pixel, each hit with its normal, a shadow ray to
//! every light or a stub saying why there is none, each mirror bounce, misses running
//! off), for the inspected pixel, its row or column, and pinned pixels. Hovering a
//! segment shows its numbers. Everything drawn is read off the tracer's own record.

mod controls;
mod overlay;

pub use controls::{RAY_PATHS_LABEL, ray_path_controls_ui};
pub use overlay::{HoveredRay, ScreenSegment, ray_paths_ui, screen_segments};
