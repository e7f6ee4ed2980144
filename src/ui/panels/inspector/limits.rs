//! What each inspector field accepts: the validator's rules, in one place. A field never
//! rewrites the value it shows; a user's drag or typed value is held to these limits,
//! and a value the validator refuses inside them (an open end, a zero scale) is not
//! taken.

use std::ops::RangeInclusive;

pub(super) use crate::scene::{
    MAX_DEPTH, MAX_IOR, MAX_LIGHT_SAMPLES, MAX_SAMPLES_PER_PIXEL, MAX_SPOT_ANGLE_DEG,
};

/// The numbers a field takes: `min..=max`, minus the open ends and (for scales) zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Limits {
    /// The smallest value (taken unless `min_open`).
    pub min: f64,
    /// The largest value (taken unless `max_open`).
    pub max: f64,
    /// `min` itself is refused.
    pub min_open: bool,
    /// `max` itself is refused.
    pub max_open: bool,
    /// Zero is refused (a scale component: the transform would be singular).
    pub nonzero: bool,
}

impl Limits {
    /// Any finite number.
    pub const ANY: Limits = Limits::closed(f64::NEG_INFINITY, f64::INFINITY);
    /// Any number >= 0 (colours, intensities).
    pub const NON_NEGATIVE: Limits = Limits::closed(0.0, f64::INFINITY);
    /// Any number but zero, either sign (scale: negative mirrors).
    pub const NONZERO: Limits = Limits {
        nonzero: true,
        ..Limits::ANY
    };

    /// `min..=max`.
    #[must_use]
    pub const fn closed(min: f64, max: f64) -> Self {
        Self {
            min,
            max,
            min_open: false,
            max_open: false,
            nonzero: false,
        }
    }

    /// The range a drag or a typed value is held to.
    #[must_use]
    pub fn range(self) -> RangeInclusive<f64> {
        self.min..=self.max
    }

    /// The numbers taken, in words: "above 0, at most 1", "any number but 0".
    #[must_use]
    pub fn describe(self) -> String {
        let mut parts = Vec::new();
        if self.min.is_finite() {
            parts.push(if self.min_open {
                format!("above {}", self.min)
            } else {
                format!("at least {}", self.min)
            });
        }
        if self.max.is_finite() {
            parts.push(if self.max_open {
                format!("below {}", self.max)
            } else {
                format!("at most {}", self.max)
            });
        }
        if self.nonzero {
            parts.push("not 0".to_owned());
        }
        if parts.is_empty() {
            "any finite number".to_owned()
        } else {
            parts.join(", ")
        }
    }

    /// What a user's gesture that produced `value` sets: held to the range, `None` when
    /// the validator would refuse it (the field then keeps its value).
    #[must_use]
    pub fn take(self, value: f64) -> Option<f64> {
        if !value.is_finite() {
            return None;
        }
        let value = value.clamp(self.min, self.max);
        let refused = (self.min_open && value == self.min)
            || (self.max_open && value == self.max)
            || (self.nonzero && value == 0.0);
        (!refused).then_some(value)
    }
}

/// Vertical field of view, strictly between 0 and 180 degrees.
pub(super) const FOV_DEG: Limits = Limits {
    min_open: true,
    max_open: true,
    ..Limits::closed(0.0, 180.0)
};

/// A spot light's half-angle: (0, [`MAX_SPOT_ANGLE_DEG`]], as the validator takes it.
pub(super) const SPOT_ANGLE_DEG: Limits = Limits {
    min_open: true,
    ..Limits::closed(0.0, MAX_SPOT_ANGLE_DEG)
};

/// The Phong exponent: any value >= 0, however large (0 lights where r.v > 0).
pub(super) const SHININESS: Limits = Limits::NON_NEGATIVE;

/// A torus's tube radius: any finite number above 0 (from 1 on, a horn or spindle torus).
pub(super) const TORUS_MINOR: Limits = Limits {
    min_open: true,
    ..Limits::closed(0.0, f64::INFINITY)
};

/// A tube's hole radius: strictly between 0 and the outer radius 1.
pub(super) const TUBE_INNER: Limits = Limits {
    min_open: true,
    max_open: true,
    ..Limits::closed(0.0, 1.0)
};

/// An index of refraction: (0, [`MAX_IOR`]], as the validator takes it (1: air, no
/// bending; below 1 is allowed, as for a bubble of air in glass).
pub(super) const IOR: Limits = Limits {
    min_open: true,
    ..Limits::closed(0.0, MAX_IOR)
};

/// A sphere light's radius: 0 (a point) or more.
pub(super) const LIGHT_RADIUS: Limits = Limits::NON_NEGATIVE;

/// A sphere light's shadow rays per shading point.
pub(super) const LIGHT_SAMPLES: RangeInclusive<u32> = 1..=MAX_LIGHT_SAMPLES;

/// Output width and height in pixels.
pub(super) const IMAGE_SIDE: RangeInclusive<u32> = 1..=crate::scene::MAX_IMAGE_SIDE;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn open_ends_and_zero_scales_are_refused_and_the_rest_held_to_range() {
        assert_eq!(FOV_DEG.take(0.0), None);
        assert_eq!(FOV_DEG.take(180.0), None);
        assert_eq!(FOV_DEG.take(250.0), None, "held to 180, which is refused");
        assert_eq!(FOV_DEG.take(0.001), Some(0.001));
        assert_eq!(Limits::NONZERO.take(0.0), None);
        assert_eq!(Limits::NONZERO.take(-3.0), Some(-3.0));
        assert_eq!(Limits::NON_NEGATIVE.take(-1.0), Some(0.0));
        assert_eq!(
            SPOT_ANGLE_DEG.take(MAX_SPOT_ANGLE_DEG),
            Some(MAX_SPOT_ANGLE_DEG)
        );
        assert_eq!(Limits::ANY.take(f64::NAN), None);
        assert_eq!(SHININESS.take(1e9), Some(1e9));
        assert_eq!(
            SHININESS.take(0.0),
            Some(0.0),
            "shininess 0 is in the contract"
        );
        assert_eq!(SPOT_ANGLE_DEG.take(180.0), Some(180.0));
        assert_eq!(SPOT_ANGLE_DEG.take(0.0), None);
        assert_eq!(IOR.take(0.0), None, "an index of 0 is refused");
        assert_eq!(IOR.take(1e9), Some(MAX_IOR));
        assert_eq!(LIGHT_RADIUS.take(-0.5), Some(0.0));
    }
}
