//! File > Compare with Image: raylab's picture of the scene beside another renderer's,
//! with the explanations `crate::compare` finds. [`CompareSession`] holds the state
//! (the running comparison, its result, the view); [`compare_window`] picks the file and
//! shows progress and errors; [`compare_view_ui`] replaces the live preview with the two
//! pictures (swipe, side by side, difference, flip) and the list of explanations.

mod bar;
mod explanations;
mod mode;
mod picture;
mod session;
mod textures;
mod view;
mod window;

pub use explanations::{explanation_label, explanation_selection, explanations_ui};
pub use mode::{CompareMode, Side};
pub use picture::{COMPARE_PICTURE_LABEL, compare_view_ui, picture_frames};
pub use session::{CompareSession, OtherSource, PictureToCompare};
pub use view::{MAX_ZOOM, ZoomView, split_at};
pub use window::{COMPARE_PATH_LABEL, compare_window, is_compare_image};
