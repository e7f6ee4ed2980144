//! Scene transforms as the course's transform keywords, in file order.
//!
//! The course applies `Scale3`, `Rotate X|Y|Z` and `Translate` each after those before
//! it, so a [`Trs`] (`T * Rz * Ry * Rx * S`) is written as `Scale3` (or `Scale`), then
//! `Rotate X`, `Rotate Y`, `Rotate Z`, then `Translate`, leaving out the steps that do
//! nothing; the importer composes them and gets the same translate / rotate / scale
//! back. A general `Matrix` is written the same way when it is a translate / rotate /
//! scale (found as the importer finds it); any other matrix (a shear, or a non-uniform
//! scale after a rotation) has no such form here and is refused.

use std::fmt;

use glam::DVec3;

use super::super::convert::as_trs;
use super::numbers::{number, triple};
use crate::scene::{Transform, Trs, affine_from_rows};

/// One transform keyword.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// `Scale s`.
    Scale(f64),
    /// `Scale3 sx sy sz`.
    Scale3(DVec3),
    /// `Rotate X|Y|Z deg`, the axis as its letter.
    Rotate(char, f64),
    /// `Translate x y z`.
    Translate(DVec3),
}

impl fmt::Display for Step {
    /// The keyword and its numbers, as in a file.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Step::Scale(s) => write!(f, "Scale {}", number(s)),
            Step::Scale3(s) => write!(f, "Scale3 {}", triple(s)),
            Step::Rotate(axis, deg) => write!(f, "Rotate {axis} {}", number(deg)),
            Step::Translate(t) => write!(f, "Translate {}", triple(t)),
        }
    }
}

/// Why a transform has no course form.
pub const SHEAR_REFUSAL: &str = "its transform is a general matrix that is not a \
    translate / rotate / scale (a shear, or a non-uniform scale after a rotation); the \
    course's Translate, Rotate and Scale3 keywords cannot say it";

/// The steps of `transform`, or `None` for a matrix with no translate / rotate / scale
/// form.
#[must_use]
pub fn steps(transform: &Transform) -> Option<Vec<Step>> {
    let trs = match transform {
        Transform::Trs(trs) => *trs,
        Transform::Matrix(rows) => as_trs(&affine_from_rows(rows))?,
    };
    Some(trs_steps(&trs))
}

/// The steps of a translate / rotate / scale, without those that do nothing.
#[must_use]
pub fn trs_steps(trs: &Trs) -> Vec<Step> {
    let mut steps = Vec::new();
    let s = trs.scale;
    if s != DVec3::ONE {
        steps.push(if s.x == s.y && s.y == s.z {
            Step::Scale(s.x)
        } else {
            Step::Scale3(s)
        });
    }
    for (axis, angle) in ['X', 'Y', 'Z'].into_iter().zip(trs.rotate_deg.to_array()) {
        if angle != 0.0 {
            steps.push(Step::Rotate(axis, angle));
        }
    }
    if trs.translate != DVec3::ZERO {
        steps.push(Step::Translate(trs.translate));
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trs_is_written_scale_first_and_translate_last() {
        let trs = Trs {
            translate: DVec3::new(1.0, 0.0, -2.0),
            rotate_deg: DVec3::new(0.0, 30.0, 0.0),
            scale: DVec3::new(2.0, 1.0, 1.0),
        };
        let text: Vec<String> = trs_steps(&trs).iter().map(ToString::to_string).collect();
        assert_eq!(text, ["Scale3 2 1 1", "Rotate Y 30", "Translate 1 0 -2"]);
        assert!(trs_steps(&Trs::default()).is_empty());
    }

    #[test]
    fn a_sheared_matrix_has_no_steps_and_a_rotation_matrix_has() {
        let shear = [
            [1.0, 0.5, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
        ];
        assert_eq!(steps(&Transform::Matrix(shear)), None);
        // Rotate Z 90 then Translate 0 0 3, as a matrix.
        let turn = [
            [0.0, -1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 3.0],
        ];
        let text: Vec<String> = steps(&Transform::Matrix(turn))
            .unwrap()
            .iter()
            .map(ToString::to_string)
            .collect();
        assert_eq!(text, ["Rotate Z 90", "Translate 0 0 3"]);
    }
}
