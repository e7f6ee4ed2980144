//! The watertight ray-triangle test of Woop, Benthin and Wald ("Watertight ray/triangle
//! intersection", JCGT 2(1), 2013), in f64 on the mesh's f32 vertices (exact in f64).
//!
//! The ray is turned once into a shear ([`RayShear`]) that takes it to the +z axis; every
//! vertex is then translated and sheared the same way whichever triangle it belongs to,
//! and the three edge functions are computed from those shared values. Two triangles
//! sharing an edge therefore compute that edge's function from the same two products,
//! with opposite signs and no fused multiply-add, so a ray can never pass between them;
//! an edge function of exactly 0 counts as inside for both.

use glam::DVec3;

use super::gamma;
use crate::trace::ray::Ray;

/// Per-ray constants of the test: the axis permutation and the shear.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RayShear {
    origin: DVec3,
    kx: usize,
    ky: usize,
    kz: usize,
    sx: f64,
    sy: f64,
    sz: f64,
}

impl RayShear {
    /// The shear for `ray`: z is the direction's largest axis, x and y swapped where
    /// that keeps the winding (and so the sign of the edge functions).
    #[inline]
    pub(crate) fn new(ray: &Ray) -> Self {
        let d = ray.dir;
        let a = d.abs();
        let kz = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let mut kx = (kz + 1) % 3;
        let mut ky = (kx + 1) % 3;
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        Self {
            origin: ray.origin,
            kx,
            ky,
            kz,
            sx: d[kx] / d[kz],
            sy: d[ky] / d[kz],
            sz: 1.0 / d[kz],
        }
    }
}

/// Where a ray meets a triangle: its parameter and barycentric weights of the corners.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TriangleCrossing {
    /// Ray parameter.
    pub t: f64,
    /// Weights of corners a, b, c; they sum to 1.
    pub weights: [f64; 3],
}

/// The crossing of the sheared ray with triangle (a, b, c) at t in (0, t_max), if any.
/// Both windings are hit (the mesh is two-sided; the normal tells the sides apart).
#[inline(always)]
pub(crate) fn cross(
    shear: &RayShear,
    a: DVec3,
    b: DVec3,
    c: DVec3,
    t_max: f64,
) -> Option<TriangleCrossing> {
    let (a, b, c) = (a - shear.origin, b - shear.origin, c - shear.origin);
    let (kx, ky, kz) = (shear.kx, shear.ky, shear.kz);
    let ax = a[kx] - shear.sx * a[kz];
    let ay = a[ky] - shear.sy * a[kz];
    let bx = b[kx] - shear.sx * b[kz];
    let by = b[ky] - shear.sy * b[kz];
    let cx = c[kx] - shear.sx * c[kz];
    let cy = c[ky] - shear.sy * c[kz];
    // Edge functions: u for edge bc (the weight of a), v for ca, w for ab.
    let u = cx * by - cy * bx;
    let v = ax * cy - ay * cx;
    let w = bx * ay - by * ax;
    if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
        return None;
    }
    let det = u + v + w;
    if det == 0.0 {
        return None;
    }
    let az = shear.sz * a[kz];
    let bz = shear.sz * b[kz];
    let cz = shear.sz * c[kz];
    let t_scaled = u * az + v * bz + w * cz;
    // t = t_scaled / det must lie in (0, t_max): compare without dividing where the
    // sign of det decides.
    if det > 0.0 {
        if t_scaled <= 0.0 || t_scaled >= t_max * det {
            return None;
        }
    } else if t_scaled >= 0.0 || t_scaled <= t_max * det {
        return None;
    }
    let inv_det = 1.0 / det;
    Some(TriangleCrossing {
        t: t_scaled * inv_det,
        weights: [u * inv_det, v * inv_det, w * inv_det],
    })
}

/// The hit point from the weights and its error bound (pbrt's bound for the
/// barycentric sum: gamma(7) times the sum of the terms' magnitudes).
#[inline]
pub(crate) fn point_and_error(weights: [f64; 3], a: DVec3, b: DVec3, c: DVec3) -> (DVec3, DVec3) {
    let [wa, wb, wc] = weights;
    let p = wa * a + wb * b + wc * c;
    let error = gamma(7) * ((wa * a).abs() + (wb * b).abs() + (wc * c).abs());
    (p, error)
}

/// The shading normal to use for a ray along `dir` hitting a triangle with unit
/// geometric normal `ng` and unit interpolated normal `ns` (both outward): `ns` where it
/// is safe, else `ng`. Safe means the ray meets the shading normal's surface from the
/// same side as the geometric one, and its mirror reflection about `ns` leaves on the
/// side of the geometric surface it came from (never into the solid).
#[inline]
pub(crate) fn safe_shading_normal(dir: DVec3, ng: DVec3, ns: DVec3) -> DVec3 {
    /// Below this cosine between the two normals the interpolated one is not trusted.
    const MIN_AGREEMENT: f64 = 0.1;
    if !ns.is_finite() || ns.dot(ng) < MIN_AGREEMENT {
        return ng;
    }
    let side = if dir.dot(ng) < 0.0 { 1.0 } else { -1.0 };
    let (ng_facing, ns_facing) = (ng * side, ns * side);
    let d = dir.normalize();
    let reflected = d - 2.0 * d.dot(ns_facing) * ns_facing;
    if d.dot(ns_facing) >= 0.0 || reflected.dot(ng_facing) <= 0.0 {
        return ng;
    }
    ns
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri() -> [DVec3; 3] {
        [DVec3::ZERO, DVec3::X, DVec3::Y]
    }

    #[test]
    fn a_ray_through_the_inside_gets_t_and_weights() {
        let [a, b, c] = tri();
        let ray = Ray::new(DVec3::new(0.25, 0.5, 2.0), DVec3::new(0.0, 0.0, -1.0));
        let hit = cross(&RayShear::new(&ray), a, b, c, f64::INFINITY).expect("hit");
        assert_eq!(hit.t, 2.0);
        let [wa, wb, wc] = hit.weights;
        assert!((wa - 0.25).abs() < 1e-15 && (wb - 0.25).abs() < 1e-15);
        assert!((wc - 0.5).abs() < 1e-15);
        let (p, error) = point_and_error(hit.weights, a, b, c);
        assert!((p - DVec3::new(0.25, 0.5, 0.0)).length() < 1e-15);
        assert!(error.max_element() < 1e-14);
    }

    #[test]
    fn misses_outside_behind_and_beyond_t_max() {
        let [a, b, c] = tri();
        let down = DVec3::new(0.0, 0.0, -1.0);
        let outside = Ray::new(DVec3::new(0.75, 0.75, 2.0), down);
        assert!(cross(&RayShear::new(&outside), a, b, c, f64::INFINITY).is_none());
        let behind = Ray::new(DVec3::new(0.2, 0.2, -1.0), down);
        assert!(cross(&RayShear::new(&behind), a, b, c, f64::INFINITY).is_none());
        let short = Ray::new(DVec3::new(0.2, 0.2, 2.0), down);
        assert!(cross(&RayShear::new(&short), a, b, c, 1.5).is_none());
        // From below, the other winding: still hit (two-sided).
        let up = Ray::new(DVec3::new(0.2, 0.2, -1.0), -down);
        assert_eq!(
            cross(&RayShear::new(&up), a, b, c, 9.0).map(|h| h.t),
            Some(1.0)
        );
    }

    #[test]
    fn a_shading_normal_that_would_reflect_into_the_solid_falls_back_to_the_flat_one() {
        let ng = DVec3::Z;
        // A grazing ray and a shading normal tilted along it: the reflection about the
        // tilted normal would head below z = 0.
        let dir = DVec3::new(1.0, 0.0, -0.3).normalize();
        let along = DVec3::new(0.2, 0.0, 0.98).normalize();
        let reflected = dir - 2.0 * dir.dot(along) * along;
        assert!(reflected.z < 0.0, "the case is the hard one");
        assert_eq!(safe_shading_normal(dir, ng, along), ng);
        // Tilted against the ray it is safe and kept.
        let against = DVec3::new(-0.6, 0.0, 0.8);
        assert_eq!(safe_shading_normal(dir, ng, against), against);
        // A steep ray with the first tilt is fine.
        let steep = DVec3::new(0.1, 0.0, -1.0).normalize();
        assert_eq!(safe_shading_normal(steep, ng, along), along);
        // From below, the same holds with the sides swapped.
        assert_eq!(safe_shading_normal(-steep, ng, along), along);
        // Opposite normals are not trusted.
        assert_eq!(safe_shading_normal(steep, ng, -against), ng);
    }
}
