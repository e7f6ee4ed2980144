//! The course framework's habits that change a picture without being bugs: how mirrors
//! combine with the local colour, when colour is clamped, how it becomes 8 bits
//! (`render.conventions` in SCENE_FORMAT.md).

use serde::{Deserialize, Serialize};

/// How a render combines, clamps and quantises colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Conventions {
    /// How the mirror term joins the local colour.
    #[serde(default)]
    pub mirror: MirrorConvention,
    /// When colour is clamped to [0, 1].
    #[serde(default)]
    pub clamp: ClampConvention,
    /// How a pixel's value becomes a byte.
    #[serde(default)]
    pub quantise: Quantise,
}

impl Conventions {
    /// The course skeletons' habits: each ray clamped, bytes truncated, mirrors added
    /// (as the 2020 reference renderer does; `raylab diff` also tries `Blend`).
    pub const COURSE: Conventions = Conventions {
        mirror: MirrorConvention::Add,
        clamp: ClampConvention::EachRay,
        quantise: Quantise::Truncate,
    };

    /// Whether every choice is the default (the contract's own lighting model).
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Conventions::default()
    }
}

/// How the mirror term joins the local colour.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum MirrorConvention {
    /// local + km * reflected.
    #[default]
    Add,
    /// (1 - km) * local + km * reflected, per channel: the skeleton's weighted sum.
    Blend,
}

/// When colour is clamped to [0, 1].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ClampConvention {
    /// Only the final pixel.
    #[default]
    Pixel,
    /// Each ray's colour (its local part plus what its mirror and transmitted rays
    /// bring), before it is used: the skeleton's `clip()`.
    EachRay,
}

/// How a pixel's value in [0, 1] becomes a byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Quantise {
    /// round(255 c).
    #[default]
    Round,
    /// floor(255 c), as `int(255 c)` in the course's code.
    Truncate,
}

impl Quantise {
    /// The byte for a value already clamped to [0, 1].
    #[must_use]
    pub fn byte(self, clamped: f64) -> u8 {
        let scaled = clamped * 255.0;
        // Both forms stay in 0..=255 for clamped input; the cast saturates anyway.
        match self {
            Quantise::Round => scaled.round() as u8,
            Quantise::Truncate => scaled.floor() as u8,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truncate_and_round_differ_at_half_steps() {
        let c = 100.6 / 255.0;
        assert_eq!(Quantise::Round.byte(c), 101);
        assert_eq!(Quantise::Truncate.byte(c), 100);
        assert_eq!(Quantise::Truncate.byte(1.0), 255);
        assert_eq!(Quantise::Round.byte(0.0), 0);
    }

    #[test]
    fn course_conventions_parse_and_default_is_empty() {
        let c: Conventions =
            ron::from_str("(mirror: Blend, clamp: EachRay, quantise: Truncate)").unwrap();
        assert_eq!(c.mirror, MirrorConvention::Blend);
        assert_eq!(c.clamp, ClampConvention::EachRay);
        assert_eq!(c.quantise, Quantise::Truncate);
        let d: Conventions = ron::from_str("()").unwrap();
        assert!(d.is_default());
    }
}
