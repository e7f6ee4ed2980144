//! Snell's law at a surface: the direction a transmitted ray takes, or total internal
//! reflection where there is none. Objects do not nest media (SCENE_FORMAT.md,
//! "Transmission"): a ray is inside an object of index `ior` or outside in air (1).

use glam::DVec3;

/// Which way a transmitted share goes on from a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transmitted {
    /// Bent by Snell's law through the surface.
    Refracted(DVec3),
    /// Snell's law has no solution (the ray is inside the denser medium, beyond the
    /// critical angle): the share follows the mirror direction instead.
    InternallyReflected(DVec3),
}

impl Transmitted {
    /// The direction of the ray that carries the share.
    #[must_use]
    pub fn dir(self) -> DVec3 {
        match self {
            Transmitted::Refracted(dir) | Transmitted::InternallyReflected(dir) => dir,
        }
    }
}

/// The mirror direction of `d` about `n`: `d - 2 (d.n) n` (keeps `d`'s length).
#[inline]
#[must_use]
pub fn mirror_dir(d: DVec3, n: DVec3) -> DVec3 {
    d - 2.0 * d.dot(n) * n
}

/// Where a ray of unit direction `d` goes on through a surface with unit normal `n`
/// facing the ray (`d.n <= 0`), from a medium of index `from` into one of index `to`.
///
/// `t = eta d + (eta cos_i - cos_t) n`, with `eta = from / to`, `cos_i = -d.n` and
/// `cos_t = sqrt(1 - eta^2 (1 - cos_i^2))`: a unit vector on the far side of the surface,
/// in the plane of `d` and `n`. Where the root's argument is negative the ray is
/// internally reflected. A grazing ray (`cos_i` = 0) into a denser medium leaves along the
/// critical angle; every value here stays finite for finite unit inputs.
#[must_use]
pub fn refract(d: DVec3, n: DVec3, from: f64, to: f64) -> Transmitted {
    let eta = from / to;
    // Rounding can put a unit d a hair past the tangent plane: no negative cosine.
    let cos_i = (-d.dot(n)).max(0.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t > 1.0 {
        return Transmitted::InternallyReflected(mirror_dir(d, n));
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Transmitted::Refracted(eta * d + (eta * cos_i - cos_t) * n)
}

/// The indices a ray goes from and into at a surface of index `ior`: into the object
/// where the ray meets its outer side (`d` against the outward normal), out of it where
/// it meets the inner side.
#[inline]
#[must_use]
pub fn media(d: DVec3, n_outward: DVec3, ior: f64) -> (f64, f64) {
    if d.dot(n_outward) < 0.0 {
        (1.0, ior)
    } else {
        (ior, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_at(degrees: f64) -> DVec3 {
        // In the xz plane, heading down onto the surface z = 0 with normal +z.
        let (s, c) = degrees.to_radians().sin_cos();
        DVec3::new(s, 0.0, -c)
    }

    #[test]
    fn snell_holds_for_the_sines_and_the_ray_stays_unit() {
        for degrees in [0.0, 10.0, 30.0, 45.0, 60.0, 89.0] {
            let d = unit_at(degrees);
            let Transmitted::Refracted(t) = refract(d, DVec3::Z, 1.0, 1.5) else {
                panic!("air to glass always refracts");
            };
            let sin_i = d.x;
            let sin_t = t.x;
            assert!((sin_i - 1.5 * sin_t).abs() < 1e-15, "{degrees} degrees");
            assert!((t.length() - 1.0).abs() < 1e-15);
            assert!(t.z < 0.0, "the ray goes on through the surface");
        }
    }

    #[test]
    fn total_internal_reflection_starts_at_the_critical_angle() {
        // Glass (1.5) to air: the critical angle is asin(1 / 1.5) = 41.81 degrees.
        let critical = (1.0f64 / 1.5).asin().to_degrees();
        let just_below = refract(unit_at(critical - 0.01), DVec3::Z, 1.5, 1.0);
        let just_above = refract(unit_at(critical + 0.01), DVec3::Z, 1.5, 1.0);
        let Transmitted::Refracted(t) = just_below else {
            panic!("below the critical angle the ray leaves");
        };
        assert!(t.z.abs() < 0.02, "it leaves almost along the surface: {t}");
        let d = unit_at(critical + 0.01);
        assert_eq!(
            just_above,
            Transmitted::InternallyReflected(DVec3::new(d.x, d.y, -d.z))
        );
    }

    #[test]
    fn an_index_of_one_leaves_the_ray_unbent_and_grazing_rays_stay_finite() {
        let d = unit_at(37.0);
        assert_eq!(refract(d, DVec3::Z, 1.0, 1.0), Transmitted::Refracted(d));
        let grazing = refract(DVec3::X, DVec3::Z, 1.0, 1.5);
        assert!(grazing.dir().is_finite() && grazing.dir().z < 0.0);
        // A unit d a rounding past the tangent plane (d.n > 0) is treated as grazing.
        let past = DVec3::new(1.0, 0.0, 1e-17);
        assert!(refract(past, DVec3::Z, 1.0, 1.5).dir().is_finite());
    }

    #[test]
    fn the_media_swap_when_the_ray_is_inside() {
        assert_eq!(media(-DVec3::Z, DVec3::Z, 1.5), (1.0, 1.5));
        assert_eq!(media(DVec3::Z, DVec3::Z, 1.5), (1.5, 1.0));
    }

    use proptest::prelude::*;

    /// A unit vector from two angles.
    fn unit(theta: f64, phi: f64) -> DVec3 {
        let (st, ct) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        DVec3::new(st * cp, st * sp, ct)
    }

    proptest! {
        /// Any unit direction against any normal and any pair of indices in (0, 10]:
        /// a finite unit direction; a refracted one on the far side of the surface,
        /// keeping Snell's sines; internal reflection only where the sine would pass 1;
        /// and the refracted ray refracted back leaves along the reverse of the first.
        #[test]
        fn snell_holds_and_reverses_for_any_ray_and_indices(
            theta in 0.0..std::f64::consts::FRAC_PI_2,
            phi in 0.0..std::f64::consts::TAU,
            normal in (0.0..std::f64::consts::PI, 0.0..std::f64::consts::TAU),
            from in 0.05f64..10.0,
            to in 0.05f64..10.0,
        ) {
            let n = unit(normal.0, normal.1);
            let (u, v) = n.any_orthonormal_pair();
            // theta from the normal, heading into the surface.
            let (st, ct) = theta.sin_cos();
            let d = -(ct * n) + st * (phi.cos() * u + phi.sin() * v);
            let out = refract(d, n, from, to);
            let t = out.dir();
            prop_assert!(t.is_finite());
            prop_assert!((t.length() - 1.0).abs() < 1e-12, "{}", t.length());
            let sin_i = d.cross(n).length();
            match out {
                Transmitted::Refracted(t) => {
                    prop_assert!(t.dot(n) <= 1e-12, "on the far side");
                    prop_assert!((from * sin_i - to * t.cross(n).length()).abs() < 1e-9);
                    // Back through the surface from the other side.
                    if let Transmitted::Refracted(back) = refract(-t, -n, to, from) {
                        prop_assert!((back + d).length() < 1e-6, "{back} vs {d}");
                    }
                }
                Transmitted::InternallyReflected(r) => {
                    prop_assert!(from * sin_i > to * (1.0 - 1e-12));
                    prop_assert!((r.dot(n) + d.dot(n)).abs() < 1e-12, "mirrored");
                }
            }
        }
    }
}
