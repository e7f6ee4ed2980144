//! From a placement matrix back to translate / rotate / scale: for resetting a general
//! matrix in the inspector and for placing new objects.

use glam::DVec3;

use crate::scene::Trs;

/// The nearest translate / rotate / scale to an affine matrix (exact without shear).
#[must_use]
pub fn trs_from_matrix(affine: &glam::DAffine3) -> Trs {
    let (scale, rotation, translate) = affine.to_scale_rotation_translation();
    // Trs applies Rz * Ry * Rx: glam's ZYX order returns (z, y, x).
    let (z, y, x) = rotation.to_euler(glam::EulerRot::ZYX);
    let trs = Trs {
        translate,
        rotate_deg: DVec3::new(x.to_degrees(), y.to_degrees(), z.to_degrees()),
        scale,
    };
    if trs.scale.is_finite() && trs.rotate_deg.is_finite() && trs.scale.min_element().abs() > 0.0 {
        trs
    } else {
        Trs {
            translate,
            ..Trs::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_reset_keeps_a_shear_free_placement() {
        let trs = Trs {
            translate: DVec3::new(1.0, -2.0, 0.5),
            rotate_deg: DVec3::new(20.0, -35.0, 70.0),
            scale: DVec3::new(2.0, 0.5, 1.5),
        };
        let back = trs_from_matrix(&trs.world_from_object());
        let a = trs.world_from_object();
        let b = back.world_from_object();
        assert!(a.abs_diff_eq(b, 1e-9), "{a:?} vs {b:?}");
    }
}
