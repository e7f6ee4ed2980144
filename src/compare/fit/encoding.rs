//! How an 8-bit value stands for a linear colour. raylab writes `round(255 c)`; other
//! renderers truncate, or encode sRGB. Each 8-bit value `k` stands for an interval of
//! linear values, and a model value inside that interval is not a difference at all:
//! that is what makes the comparison blind to rounding.

use serde::Serialize;

use crate::scene::Quantise;

/// Slack added to each interval, in linear units, for the rounding of float sums.
const SLACK: f64 = 1e-6;

/// An 8-bit encoding of linear colour in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Encoding {
    /// `round(255 c)`: raylab's and the legacy renderer's.
    LinearRound,
    /// `floor(255 c)` (with 1.0 written as 255): a common shortcut.
    LinearTruncate,
    /// The sRGB transfer curve, then `round(255 x)`.
    Srgb,
}

impl Encoding {
    /// Every encoding, raylab's first.
    pub const ALL: [Encoding; 3] = [
        Encoding::LinearRound,
        Encoding::LinearTruncate,
        Encoding::Srgb,
    ];

    /// The name used in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Encoding::LinearRound => "linear-round",
            Encoding::LinearTruncate => "linear-truncate",
            Encoding::Srgb => "srgb",
        }
    }

    /// The interval `[lo, hi]` of linear values that this encoding writes as `k`. The ends
    /// of the range are open: 0 stands for anything up to its top, 255 for anything from
    /// its bottom (a renderer clamps).
    #[must_use]
    pub fn interval(self, k: u8) -> (f64, f64) {
        let k = f64::from(k);
        let (lo, hi) = match self {
            Encoding::LinearRound => ((k - 0.5) / 255.0, (k + 0.5) / 255.0),
            Encoding::LinearTruncate => (k / 255.0, (k + 1.0) / 255.0),
            Encoding::Srgb => (
                srgb_to_linear((k - 0.5) / 255.0),
                srgb_to_linear((k + 0.5) / 255.0),
            ),
        };
        let lo = if k == 0.0 { f64::NEG_INFINITY } else { lo };
        let hi = if k == 255.0 { f64::INFINITY } else { hi };
        (lo - SLACK, hi + SLACK)
    }

    /// The byte this encoding writes for the linear value `c` (clamped to [0, 1]; a
    /// non-finite value is written as 0): the value each [`Encoding::interval`] holds.
    #[must_use]
    pub fn encode(self, c: f64) -> u8 {
        if !c.is_finite() {
            return 0;
        }
        // The linear encodings are the renderer's own, on its f32 pixels, so a picture
        // written here has raylab's bytes wherever its values are raylab's.
        match self {
            Encoding::LinearRound => crate::trace::encode(c as f32, Quantise::Round),
            Encoding::LinearTruncate => crate::trace::encode(c as f32, Quantise::Truncate),
            Encoding::Srgb => {
                let c = c.clamp(0.0, 1.0);
                let x = if c <= 0.003_130_8 {
                    12.92 * c
                } else {
                    1.055 * c.powf(1.0 / 2.4) - 0.055
                };
                (x * 255.0 + 0.5) as u8
            }
        }
    }

    /// The linear value that best stands for `k`: the middle of its interval (the ends of
    /// the range stand for 0 and 1).
    #[must_use]
    pub fn decode(self, k: u8) -> f64 {
        match k {
            0 => 0.0,
            255 => 1.0,
            _ => {
                let (lo, hi) = self.interval(k);
                0.5 * (lo + hi)
            }
        }
    }
}

/// The sRGB decoding curve for `x` in [0, 1] (values outside are clamped).
#[must_use]
pub fn srgb_to_linear(x: f64) -> f64 {
    let x = x.clamp(0.0, 1.0);
    if x <= 0.04045 {
        x / 12.92
    } else {
        ((x + 0.055) / 1.055).powf(2.4)
    }
}

/// How far `value` (clamped to [0, 1]) lies outside the interval of `k`: 0 inside.
#[inline]
#[must_use]
pub fn distance_outside(value: f64, (lo, hi): (f64, f64)) -> f64 {
    let value = value.clamp(0.0, 1.0);
    if value < lo {
        lo - value
    } else if value > hi {
        value - hi
    } else {
        0.0
    }
}

/// The encoding under which most channels of `model` (linear, unclamped) fall inside
/// the interval of the other image's value; raylab's own wins ties. Channels the other
/// renderer got wrong for another reason fall outside under every encoding, so they do
/// not sway the choice.
#[must_use]
pub fn detect(model: &[[f64; 3]], other: &[[u8; 3]]) -> Encoding {
    let mut best = (Encoding::LinearRound, 0usize);
    for encoding in Encoding::ALL {
        let table: Vec<(f64, f64)> = (0..=255u8).map(|k| encoding.interval(k)).collect();
        let inside = model
            .iter()
            .zip(other)
            .map(|(m, o)| {
                (0..3)
                    .filter(|&c| distance_outside(m[c], table[usize::from(o[c])]) == 0.0)
                    .count()
            })
            .sum::<usize>();
        if inside > best.1 {
            best = (encoding, inside);
        }
    }
    best.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn intervals_hold_what_each_encoding_writes() {
        for c in [0.0_f64, 0.1, 0.2001, 0.5, 0.73, 0.999, 1.0, 1.7] {
            let round = (c.clamp(0.0, 1.0) * 255.0).round() as u8;
            let truncate = (c.clamp(0.0, 1.0) * 255.0).floor() as u8;
            assert_eq!(
                distance_outside(c, Encoding::LinearRound.interval(round)),
                0.0
            );
            assert_eq!(
                distance_outside(c, Encoding::LinearTruncate.interval(truncate)),
                0.0
            );
        }
        assert!(distance_outside(0.5, Encoding::LinearRound.interval(120)) > 0.0);
    }

    #[test]
    fn each_encoding_writes_a_byte_whose_interval_holds_the_value() {
        for encoding in Encoding::ALL {
            for i in 0..=1000 {
                let c = f64::from(i) / 1000.0;
                let k = encoding.encode(c);
                assert_eq!(
                    distance_outside(c, encoding.interval(k)),
                    0.0,
                    "{encoding:?} {c}"
                );
            }
        }
        assert_eq!(Encoding::Srgb.encode(0.5), 188);
        assert_eq!(Encoding::LinearTruncate.encode(0.999), 254);
    }

    #[test]
    fn detection_tells_truncation_from_rounding() {
        let model: Vec<[f64; 3]> = (0..300)
            .map(|i| [i as f64 / 300.0, (i as f64 * 0.37).fract(), 0.25])
            .collect();
        let encode = |f: fn(f64) -> f64| -> Vec<[u8; 3]> {
            model
                .iter()
                .map(|m| m.map(|c| f(c * 255.0) as u8))
                .collect()
        };
        assert_eq!(detect(&model, &encode(f64::round)), Encoding::LinearRound);
        assert_eq!(
            detect(&model, &encode(f64::floor)),
            Encoding::LinearTruncate
        );
    }
}
