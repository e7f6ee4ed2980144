//! Stage 6, the report: the comparison as a value (both pictures, the difference, the
//! explanations), as JSON and text, and as a PNG of panels.

mod comparison;
mod panel_grid;
mod png;

pub use comparison::{Comparison, PSNR_IDENTICAL_DB, PixelValues, difference, psnr_db, rgb_of};
pub use panel_grid::{Panel, panel_grid_png};
pub use png::{difference_heatmap, report_png, write_report_png};
