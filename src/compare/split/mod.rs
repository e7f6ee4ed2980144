//! Stage 2, the split: raylab's picture traced once, every sample split into the
//! catalogue's channels by a recorder listening to the tracer's own shading code.

mod components;
mod context;
mod fold_watch;
mod folded_only;
mod recorder;

pub use components::{Components, render_components};
