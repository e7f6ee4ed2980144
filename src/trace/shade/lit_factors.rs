//! What the shader hands the re-shade cache for each light at each hit: the numbers from
//! which the diffuse and specular terms follow for any material and light strength.

use crate::trace::world::LightSample;

/// What one light gave one cached hit, encoded in three floats (the cache holds one per
/// hit and light): unknown (`n.l` NaN), unreachable (`n.l` minus infinity, no term as
/// for a light behind the surface), or the light's sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LitFactors {
    distance_squared: f64,
    /// NaN: unknown (the shader did not look at this light here); minus infinity: the
    /// light cannot reach the point (outside its cone, or at the light itself).
    n_dot_l: f64,
    /// The lobe; -1 where there is none (`r.v <= 0`).
    lobe: f64,
}

impl LitFactors {
    /// Nothing known.
    pub const UNKNOWN: Self = Self {
        distance_squared: f64::NAN,
        n_dot_l: f64::NAN,
        lobe: f64::NAN,
    };

    /// The light cannot reach the point.
    pub const UNREACHABLE: Self = Self {
        distance_squared: f64::NAN,
        n_dot_l: f64::NEG_INFINITY,
        lobe: f64::NAN,
    };

    /// A light sampled at the point.
    #[must_use]
    pub fn reached(sample: &LightSample, n_dot_l: f64, lobe: Option<f64>) -> Self {
        Self {
            distance_squared: sample.distance_squared,
            n_dot_l,
            lobe: lobe.unwrap_or(-1.0),
        }
    }

    /// `n.l` where the light was sampled; NaN where nothing is known, minus infinity
    /// where the light cannot reach the point.
    #[inline]
    #[must_use]
    pub fn n_dot_l(&self) -> f64 {
        self.n_dot_l
    }

    /// The distance the strength falls off with (for a reached light).
    #[inline]
    #[must_use]
    pub fn distance_squared(&self) -> f64 {
        self.distance_squared
    }

    /// The Phong lobe (for a reached light in front of the surface).
    #[inline]
    #[must_use]
    pub fn lobe(&self) -> Option<f64> {
        (self.lobe >= 0.0).then_some(self.lobe)
    }

    /// Whether nothing is known: the pixel must be shaded in full.
    #[inline]
    #[must_use]
    pub fn is_unknown(&self) -> bool {
        self.n_dot_l.is_nan()
    }
}
