//! Stage 3, the fit: the other picture read as intervals under its 8-bit encoding, the
//! course's other conventions tried, and a greedy least-squares search over groups of
//! channels, each accepted group a step with its share of the squared difference.

mod conventions;
mod encoding;
mod groups;
mod rivals;
mod sampling;
mod search;
mod target;

pub use conventions::{
    BetterConventions, ConventionTrials, NO_LIMIT_DEPTH, better_conventions, convention_names,
    convention_trials,
};
pub use encoding::{Encoding, detect as detect_encoding};
pub use groups::{Group, Groups};
pub use sampling::{SamplingSpread, samples_otherwise};
pub use search::{Floor, MIN_ERROR, MIN_STEP_SHARE, Step, search};
pub use target::{FitState, NOISE_SHARE, OFF_LEVELS, Target};
