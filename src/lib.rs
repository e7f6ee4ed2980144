//! raylab: a Whitted-style CPU ray tracer and the scene editor built around it.
//!
//! The layers depend one way: `ui -> preview -> trace -> scene`. `scene` and `trace` know
//! nothing of egui; everything the editor shows can be produced headless.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bench;
pub mod class;
pub mod cli;
pub mod compare;
pub mod gizmo;
pub mod preview;
pub mod recovery;
pub mod scene;
#[cfg(test)]
mod test_cases;
pub mod trace;
#[cfg(feature = "editor")]
pub mod ui;
