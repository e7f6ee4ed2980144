//! The viewport: the preview picture and its toolbar, the link to the preview worker and
//! its settings, the view camera and camera navigation, the isolation switches, picking
//! and the pixel inspector off the UI thread, the ray-path overlay and the convergence
//! plot.

pub mod camera_navigation;
mod clicks;
pub mod convergence_plot;
pub mod exchange;
pub mod full_picture_marker;
pub mod isolation_memory;
mod legend;
mod marks;
pub mod pick_link;
pub mod picture;
pub mod pixel_inspector;
pub mod preview_link;
pub mod ray_paths;
pub mod toolbar;
pub mod view_memory;
