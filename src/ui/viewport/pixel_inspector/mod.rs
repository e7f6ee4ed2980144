//! The pixel inspector: every number behind one pixel, for the ray through its centre,
//! as the tracer's own shading code recorded it ([`try_inspect_pixel`]). The numbers are
//! the tracer's [`PixelReport`] itself; this model only adds the names of the objects,
//! materials and lights its indices point at, and of the lights and objects the
//! isolation switches leave out (shown as such, not as missing), so the window lays out
//! text. The tracing runs off the UI thread ([`link`]).

mod compared;
mod inspection;
pub mod link;
mod placement;
mod report_view;
mod window;

pub use compared::{OTHER_VALUE_LABEL, RAYLAB_VALUE_LABEL, compared_rows};
pub use inspection::{
    InspectedBounce, InspectedHit, InspectedLight, InspectedPixel, LIGHT_OFF_OUTCOME,
    PixelInspection, inspected_pixel,
};
pub use placement::PixelAnchor;
pub use report_view::{FINAL_COLOUR_LABEL, isolation_lines};
pub use window::{
    InspectorView, MAX_WIDTH, inspector_window_id, pixel_inspector_ui, switches_text,
};
