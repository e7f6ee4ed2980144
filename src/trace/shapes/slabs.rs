//! The slab test the cube and the octahedron share: a convex solid as the overlap of
//! slabs -1 <= s.p <= 1, the ray entering where it has entered them all and leaving
//! where it first leaves one. A ray parallel to a slab is inside it or misses the solid,
//! and never divides by zero (an origin on a face plane gives no 0 * inf = NaN).

use glam::DVec3;

use crate::trace::ray::Ray;

/// Entry and exit of a ray through the slabs, with the slab of each.
pub(crate) struct SlabSpan {
    pub t_near: f64,
    pub near_slab: usize,
    pub t_far: f64,
    pub far_slab: usize,
}

/// The span of `ray` through `N` slabs, `project(v, k)` being slab `k`'s coordinate of
/// the vector `v` (for the cube an axis, for the octahedron a dot product).
#[inline(always)]
pub(crate) fn slab_span<const N: usize>(
    ray: &Ray,
    project: impl Fn(DVec3, usize) -> f64,
) -> Option<SlabSpan> {
    let mut s = SlabSpan {
        t_near: f64::NEG_INFINITY,
        near_slab: 0,
        t_far: f64::INFINITY,
        far_slab: 0,
    };
    for slab in 0..N {
        let (o, d) = (project(ray.origin, slab), project(ray.dir, slab));
        if d == 0.0 {
            if o.abs() > 1.0 {
                return None;
            }
            continue;
        }
        let (mut t0, mut t1) = ((-1.0 - o) / d, (1.0 - o) / d);
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        if t0 > s.t_near {
            s.t_near = t0;
            s.near_slab = slab;
        }
        if t1 < s.t_far {
            s.t_far = t1;
            s.far_slab = slab;
        }
    }
    (s.t_near <= s.t_far).then_some(s)
}
