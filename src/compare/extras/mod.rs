//! Stage 4, the extras: what the fit's factors cannot say. Objects the other picture
//! draws and raylab does not (with their shadows), found from the pixels the search
//! leaves off, their shape guessed from their outline, and the test that a pixel is
//! only a lighting of raylab's own surfaces (not an object of its own).

mod extra_object;
mod regions;
mod relit;
mod shape_guess;

pub use extra_object::{ExtraObject, confirm_shadows, find as find_extra_objects};
pub use regions::PixelBox;
pub use relit::Palette;
pub use shape_guess::ShapeGuess;
