//! The editor state that commands, panels and the viewport share: preview settings, the
//! view camera, isolation toggles, pick requests, ray-path settings and labels. Plain
//! data and egui-free logic, so `commands` depends on it and not on the viewport.

mod isolation;
mod labels;
mod pick;
mod preview_settings;
mod ray_paths;
mod view_camera;

pub use isolation::{IsolationAnchors, IsolationToggle, isolation_note, keep_in_range};
pub use labels::{light_label, view_label};
pub use pick::{PickPurpose, PickRequest};
pub use preview_settings::PreviewSettings;
pub use ray_paths::{MAX_SPAN_PIXELS, RayPathSettings, RaySpan};
pub use view_camera::{MAX_VIEW_LONG_SIDE, ViewCamera, free_render_size, shown_scene};
