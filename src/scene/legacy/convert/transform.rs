//! Legacy transform sequences: composition in file order, and the scene transform that
//! holds the result without loss.
//!
//! Each step is applied after those before it, so the object-to-world matrix of steps
//! `S1, S2, ..., Sn` is `Sn * ... * S2 * S1`. The result becomes a translate / rotate /
//! scale ([`Trs`], applied as `T * Rz * Ry * Rx * S`) when it is one: the linear part
//! must be a rotation times a diagonal scale. That is checked by decomposing and then
//! recomposing, which must give back the same matrix to a relative 1e-12. Anything else
//! (a non-uniform scale after a rotation is a shear) stays a general `Matrix`.

use glam::{DAffine3, DMat3, DVec3};

use super::super::syntax::{Axis, TransformStep};
use crate::scene::transform::sin_cos_deg;
use crate::scene::{MatrixRows, Transform, Trs, rows_from_affine};

/// Relative agreement a recomposed translate / rotate / scale must reach.
const RECOMPOSE_TOLERANCE: f64 = 1e-12;
/// How far (relative) a decomposed number may move to become a short decimal: a few
/// units in the last place.
const SNAP_TOLERANCE: f64 = 1e-15;
/// The size angles (in degrees) are measured against when snapping.
const FULL_TURN_DEG: f64 = 360.0;

/// The object-to-world matrix of one step.
#[must_use]
pub fn step_affine(step: &TransformStep) -> DAffine3 {
    match *step {
        TransformStep::Translate(offset) => DAffine3::from_translation(offset),
        TransformStep::Rotate { axis, angle_deg } => DAffine3::from_mat3(rotation(axis, angle_deg)),
        TransformStep::Scale(s) => DAffine3::from_scale(DVec3::splat(s)),
        TransformStep::Scale3(s) => DAffine3::from_scale(s),
    }
}

/// A right-handed rotation about a coordinate axis (as glam's `from_rotation_*`).
fn rotation(axis: Axis, angle_deg: f64) -> DMat3 {
    let (s, c) = sin_cos_deg(angle_deg);
    match axis {
        Axis::X => DMat3::from_cols(DVec3::X, DVec3::new(0.0, c, s), DVec3::new(0.0, -s, c)),
        Axis::Y => DMat3::from_cols(DVec3::new(c, 0.0, -s), DVec3::Y, DVec3::new(s, 0.0, c)),
        Axis::Z => DMat3::from_cols(DVec3::new(c, s, 0.0), DVec3::new(-s, c, 0.0), DVec3::Z),
    }
}

/// The object-to-world matrix of steps applied in order (each after those before).
#[must_use]
pub fn compose<'a>(steps: impl IntoIterator<Item = &'a TransformStep>) -> DAffine3 {
    steps
        .into_iter()
        .fold(DAffine3::IDENTITY, |world_from_object, step| {
            step_affine(step) * world_from_object
        })
}

/// The scene transform for `world_from_object`: a [`Trs`] when one reproduces it,
/// else the general matrix.
#[must_use]
pub fn scene_transform(world_from_object: &DAffine3) -> Transform {
    match as_trs(world_from_object) {
        Some(trs) => Transform::Trs(trs),
        None => Transform::Matrix(snapped_rows(world_from_object)),
    }
}

/// The matrix rows, each number moved to a short decimal where that changes it by at
/// most a relative 1e-15 (of the linear part's or the translation's size), so that
/// 0.49999999999999994 is written as 0.5.
fn snapped_rows(m: &DAffine3) -> MatrixRows {
    let linear_size = max_abs(&m.matrix3);
    let translation_size = m.translation.abs().max_element();
    rows_from_affine(m).map(|row| {
        [
            snap(row[0], linear_size),
            snap(row[1], linear_size),
            snap(row[2], linear_size),
            snap(row[3], translation_size),
        ]
    })
}

fn max_abs(m: &DMat3) -> f64 {
    m.abs().to_cols_array().into_iter().fold(0.0, f64::max)
}

/// The translate / rotate / scale equal to `m`, if there is one.
#[must_use]
pub fn as_trs(m: &DAffine3) -> Option<Trs> {
    let raw = decompose(m)?;
    let snapped = Trs {
        translate: snap_vector(raw.translate),
        rotate_deg: raw.rotate_deg.map(|a| snap(a, FULL_TURN_DEG)),
        scale: snap_vector(raw.scale),
    };
    [snapped, raw]
        .into_iter()
        .find(|trs| agrees(&trs.world_from_object(), m))
}

/// Scale from the column lengths, the rotation from what is left, then XYZ Euler angles.
/// With a mirror (negative determinant) one scale is negated: the axis that leaves the
/// smallest rotation, so `Scale3 1 -1 1` comes back as that and not as a turn.
fn decompose(m: &DAffine3) -> Option<Trs> {
    let a = m.matrix3;
    let lengths = DVec3::new(a.x_axis.length(), a.y_axis.length(), a.z_axis.length());
    if lengths.min_element() <= 0.0 || !lengths.is_finite() {
        return None;
    }
    let candidates: Vec<DVec3> = if a.determinant() >= 0.0 {
        vec![lengths]
    } else {
        (0..3)
            .map(|axis| {
                let mut scale = lengths;
                scale[axis] = -scale[axis];
                scale
            })
            .collect()
    };
    candidates
        .into_iter()
        .map(|scale| {
            let rotation = a * DMat3::from_diagonal(scale.recip());
            Trs {
                translate: m.translation,
                rotate_deg: euler_xyz_deg(&rotation),
                scale,
            }
        })
        .min_by(|p, q| {
            let size = |t: &Trs| t.rotate_deg.abs().element_sum();
            size(p).total_cmp(&size(q))
        })
}

/// Angles (a, b, c) in degrees with `rotation = Rz(c) * Ry(b) * Rx(a)`.
fn euler_xyz_deg(rotation: &DMat3) -> DVec3 {
    // Row r, column c of the matrix is rotation.col(c)[r].
    let at = |row: usize, col: usize| rotation.col(col)[row];
    let cos_b = at(0, 0).hypot(at(1, 0));
    let b = (-at(2, 0)).atan2(cos_b);
    let (a, c) = if cos_b > 1e-9 {
        (at(2, 1).atan2(at(2, 2)), at(1, 0).atan2(at(0, 0)))
    } else {
        // Gimbal lock: only a - c (or a + c) is defined; put it all in a.
        ((-at(1, 2)).atan2(at(1, 1)), 0.0)
    };
    DVec3::new(a, b, c).map(f64::to_degrees)
}

/// Whether two transforms agree to a relative 1e-12, linear part and translation apart.
fn agrees(p: &DAffine3, q: &DAffine3) -> bool {
    let linear_size = max_abs(&q.matrix3);
    let linear_error = max_abs(&(p.matrix3 - q.matrix3));
    let translation_error = (p.translation - q.translation).abs().max_element();
    linear_error <= RECOMPOSE_TOLERANCE * linear_size
        && translation_error <= RECOMPOSE_TOLERANCE * q.translation.abs().max_element()
}

fn snap_vector(v: DVec3) -> DVec3 {
    let size = v.abs().max_element();
    v.map(|x| snap(x, size))
}

/// The shortest decimal (up to 12 places) within a relative 1e-15 of `x` or of `size`,
/// so that 29.999999999999996 reads as 30 and rounding noise next to 1 reads as 0.
fn snap(x: f64, size: f64) -> f64 {
    let tolerance = SNAP_TOLERANCE * x.abs().max(size);
    (0..=12)
        .map(|places| {
            let scale = 10f64.powi(places);
            (x * scale).round() / scale
        })
        .find(|candidate| (candidate - x).abs() <= tolerance)
        .unwrap_or(x)
        + 0.0 // no negative zero in files
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trs(steps: &[TransformStep]) -> Trs {
        match scene_transform(&compose(steps)) {
            Transform::Trs(trs) => trs,
            other => panic!("expected a Trs, got {other:?}"),
        }
    }

    fn rotate(axis: Axis, angle_deg: f64) -> TransformStep {
        TransformStep::Rotate { axis, angle_deg }
    }

    #[test]
    fn steps_apply_in_file_order() {
        // Scale 2 then Translate 0 -2 0: the unit point (0, 1, 0) goes to (0, 0, 0).
        let m = compose(&[
            TransformStep::Scale(2.0),
            TransformStep::Translate(DVec3::new(0.0, -2.0, 0.0)),
        ]);
        assert_eq!(m.transform_point3(DVec3::Y), DVec3::ZERO);
    }

    #[test]
    fn simple_sequences_become_exact_short_trs() {
        let t = trs(&[
            TransformStep::Scale3(DVec3::new(2.0, 3.0, 4.0)),
            rotate(Axis::X, 30.0),
            rotate(Axis::Y, -45.0),
            rotate(Axis::Z, 90.0),
            TransformStep::Translate(DVec3::new(0.1, 0.2, 0.3)),
            TransformStep::Translate(DVec3::new(0.2, 0.0, 0.0)),
        ]);
        assert_eq!(t.scale, DVec3::new(2.0, 3.0, 4.0));
        assert_eq!(t.rotate_deg, DVec3::new(30.0, -45.0, 90.0));
        assert_eq!(t.translate, DVec3::new(0.3, 0.2, 0.3));
    }

    #[test]
    fn a_mirror_keeps_its_axis() {
        let t = trs(&[TransformStep::Scale3(DVec3::new(1.0, -1.0, 1.0))]);
        assert_eq!(t.scale, DVec3::new(1.0, -1.0, 1.0));
        assert_eq!(t.rotate_deg, DVec3::ZERO);
    }

    #[test]
    fn gimbal_lock_still_reproduces_the_matrix() {
        let steps = [
            rotate(Axis::Z, 20.0),
            rotate(Axis::Y, 90.0),
            rotate(Axis::X, 10.0),
        ];
        let t = trs(&steps);
        assert!(agrees(&t.world_from_object(), &compose(&steps)));
    }

    #[test]
    fn scale_after_rotation_is_a_shear_and_stays_a_matrix() {
        let steps = [
            rotate(Axis::Z, 30.0),
            TransformStep::Scale3(DVec3::new(1.0, 2.0, 1.0)),
        ];
        let m = compose(&steps);
        let Transform::Matrix(rows) = scene_transform(&m) else {
            panic!("expected a matrix");
        };
        assert!(agrees(&crate::scene::affine_from_rows(&rows), &m));
        // sin 30 degrees comes out of the float maths as 0.49999999999999994.
        assert_eq!(rows[0][1], -0.5);
    }

    #[test]
    fn every_sequence_survives_conversion() {
        // A fixed pseudo-random walk over all step kinds: whatever form the result takes,
        // it reproduces the composed matrix.
        let mut cases = crate::test_cases::Xorshift(0x2545_f491_4f6c_dd1d);
        let mut next = move || cases.unit();
        let axes = [Axis::X, Axis::Y, Axis::Z];
        for _ in 0..500 {
            let steps: Vec<TransformStep> = (0..1 + (next() * 5.0) as usize)
                .map(|_| {
                    let kind = (next() * 4.0) as usize;
                    let v = DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * 8.0;
                    match kind {
                        0 => TransformStep::Translate(v),
                        1 => rotate(axes[(next() * 3.0) as usize % 3], (next() - 0.5) * 720.0),
                        2 => TransformStep::Scale(v.x + 4.5),
                        _ => TransformStep::Scale3(v + DVec3::splat(4.5)),
                    }
                })
                .collect();
            let m = compose(&steps);
            let back = scene_transform(&m).world_from_object();
            assert!(agrees(&back, &m), "{steps:?}");
        }
    }

    #[test]
    fn quarter_turns_are_exact() {
        let m = compose(&[rotate(Axis::X, 180.0), rotate(Axis::Y, -270.0)]);
        assert_eq!(m.transform_vector3(DVec3::Y), DVec3::NEG_Y);
        assert_eq!(m.transform_vector3(DVec3::Z), DVec3::NEG_X);
    }

    #[test]
    fn uniform_scale_after_rotation_is_still_a_trs() {
        let t = trs(&[rotate(Axis::Z, 30.0), TransformStep::Scale(-2.0)]);
        assert!(agrees(
            &t.world_from_object(),
            &compose(&[rotate(Axis::Z, 30.0), TransformStep::Scale(-2.0)])
        ));
    }
}
