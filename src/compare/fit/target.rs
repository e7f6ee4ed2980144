//! The other picture as the fit sees it: per channel, the interval of linear values its
//! 8-bit value stands for, and the state of the model fitted to it (raylab's picture
//! changed by the steps accepted so far) with its error.
//!
//! The error of a pixel is the squared distance of the clamped model from the intervals
//! of its three channels: zero wherever the model would be written as the other image's
//! bytes, so rounding is never a difference.

use super::encoding::{Encoding, distance_outside};
use super::sampling::SamplingSpread;
use crate::compare::other_image::OtherImage;

/// A pixel counts as still different when some channel is this many 8-bit levels outside
/// what its byte stands for.
pub const OFF_LEVELS: f64 = 2.0;

/// The share of the error on edges ([`Target::sampling_noise`]) a step must take away
/// to be a finding: sampling's leftovers are scattered along edges with both signs, so
/// one factor takes away a small part of them, while a bug's change is coherent.
pub const NOISE_SHARE: f64 = 0.5;

/// The other picture decoded with one encoding.
#[derive(Clone, Debug)]
pub struct Target {
    /// Per pixel and channel, the interval of linear values the byte stands for.
    pub intervals: Vec<[(f64, f64); 3]>,
    /// Per pixel and channel, the value the linear fit aims at (the interval's middle).
    pub middle: Vec<[f64; 3]>,
    /// Per pixel and channel, 1 where the fit may use the channel, 0 where the other
    /// renderer clipped it (255: its true value is unknown).
    pub weight: Vec<[f64; 3]>,
    /// Per pixel, how much of an edge it is: 0 in smooth regions, towards 1 where
    /// anti-aliasing may change it by whole colours (from the sampling spread).
    pub edge: Vec<f64>,
}

impl Target {
    /// `other` decoded with `encoding`, each pixel's interval widened by what sampling
    /// may do to it (`spread`, from raylab's picture) and its weight lowered to match.
    #[must_use]
    pub fn new(other: &OtherImage, encoding: Encoding, spread: &SamplingSpread) -> Self {
        let table: Vec<(f64, f64)> = (0..=255u8).map(|k| encoding.interval(k)).collect();
        let decoded: Vec<f64> = (0..=255u8).map(|k| encoding.decode(k)).collect();
        let intervals = other
            .rgb
            .iter()
            .zip(&spread.reach)
            .map(|(p, reach)| {
                let mut interval = p.map(|k| table[usize::from(k)]);
                for (c, (lo, hi)) in interval.iter_mut().enumerate() {
                    *lo -= reach[c].0;
                    *hi += reach[c].1;
                }
                interval
            })
            .collect();
        let middle = other
            .rgb
            .iter()
            .map(|p| p.map(|k| decoded[usize::from(k)]))
            .collect();
        let weight = other
            .rgb
            .iter()
            .zip(&spread.weight)
            .map(|(p, w)| {
                let mut weight = w.to_owned();
                for (c, &k) in p.iter().enumerate() {
                    if k == 255 {
                        weight[c] = 0.0;
                    }
                }
                weight
            })
            .collect();
        let edge = spread
            .weight
            .iter()
            .map(|w| 1.0 - w.iter().copied().fold(1.0, f64::min))
            .collect();
        Self {
            intervals,
            middle,
            weight,
            edge,
        }
    }

    /// What of `error` (per pixel) sits on edges, where another renderer's sampling
    /// alone leaves differences: no single step is believed unless it takes away more
    /// than [`NOISE_SHARE`] of this.
    #[must_use]
    pub fn sampling_noise(&self, error: &[f64]) -> f64 {
        error.iter().zip(&self.edge).map(|(e, edge)| e * edge).sum()
    }

    /// This target with `pixels` out of the fit: any value is right there, and the
    /// linear fit does not see them.
    #[must_use]
    pub fn without(&self, pixels: &[u32]) -> Self {
        let mut target = self.clone();
        for &p in pixels {
            let p = p as usize;
            target.intervals[p] = [(f64::NEG_INFINITY, f64::INFINITY); 3];
            target.weight[p] = [0.0; 3];
        }
        target
    }

    /// The error of `model` at pixel `p`.
    #[inline]
    #[must_use]
    pub fn pixel_error(&self, p: usize, model: &[f64; 3]) -> f64 {
        let intervals = &self.intervals[p];
        (0..3)
            .map(|c| distance_outside(model[c], intervals[c]).powi(2))
            .sum()
    }

    /// The error of every pixel of `model`.
    #[must_use]
    pub fn errors(&self, model: &[[f64; 3]]) -> Vec<f64> {
        model
            .iter()
            .enumerate()
            .map(|(p, m)| self.pixel_error(p, m))
            .collect()
    }
}

/// The model being fitted and its error against a target.
#[derive(Clone, Debug)]
pub struct FitState {
    /// The model picture, linear and unclamped.
    pub model: Vec<[f64; 3]>,
    /// Its error per pixel.
    pub error: Vec<f64>,
    /// The sum of `error`.
    pub total: f64,
}

impl FitState {
    /// The state of `model` against `target`.
    #[must_use]
    pub fn new(model: Vec<[f64; 3]>, target: &Target) -> Self {
        let error = target.errors(&model);
        let total = error.iter().sum();
        Self {
            model,
            error,
            total,
        }
    }

    /// The linear residual `weight * (middle - model)` at pixel `p`.
    #[inline]
    #[must_use]
    pub fn residual(&self, target: &Target, p: usize) -> [f64; 3] {
        let (m, t, w) = (&self.model[p], &target.middle[p], &target.weight[p]);
        [
            w[0] * (t[0] - m[0]),
            w[1] * (t[1] - m[1]),
            w[2] * (t[2] - m[2]),
        ]
    }

    /// Adds `change` to pixel `p` and updates the error.
    pub fn add(&mut self, target: &Target, p: usize, change: [f64; 3]) {
        let m = &mut self.model[p];
        for c in 0..3 {
            m[c] += change[c];
        }
        let error = target.pixel_error(p, m);
        self.total += error - self.error[p];
        self.error[p] = error;
    }
}
