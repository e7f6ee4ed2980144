//! Stage 5, the verdicts: the search's steps and the extra objects become explanations
//! with a sentence each, what nothing explains is localised as geometry or shading, and
//! a picture of another version of the scene is named as such.

mod different_scene;
mod explain;
mod explanation;
mod localise;
mod summary;
mod verdicts;

pub use explain::{Explained, explain};
pub use explanation::{Cause, ExplainedTerm, Explanation, HIGH_CONFIDENCE};
pub use summary::{looped_lights, summary};
