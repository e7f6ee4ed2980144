//! The viewport: the preview picture and its toolbar, the link to the preview worker and
//! its settings, the isolation switches, the pixel inspector, the convergence plot and
//! camera navigation.

pub mod camera_navigation;
pub mod convergence_plot;
pub mod full_picture_marker;
pub mod isolation;
pub mod isolation_memory;
pub mod picture;
pub mod pixel_inspector;
pub mod preview_link;
pub mod preview_settings;
pub mod toolbar;
