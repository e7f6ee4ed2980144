//! Culling for the shadow rays cast from a tile's camera hits. Those hits lie on the
//! tile's candidate objects inside the tile's pyramid, so within a box `H` found before
//! tracing: the union over the candidates of each one's world box clipped to the part of
//! the pyramid at the box's depths. A shadow ray from a point of `H` runs to a point
//! light inside the hull of `H` and the light, and to a directional light inside `H`
//! swept towards it. An object whose box misses that region (tested on the three axes,
//! and against the capsule of `H`'s bounding sphere moved to the light) cannot block the
//! ray, so the tile's shadow queries skip it.
//!
//! As for camera rays, the margins are far above rounding (the spawned origin moves
//! off the surface by a few error bounds, ~1e-15 relative) and the queries keep scene
//! order, so every shadow answer is the one the full list gives.

use glam::DVec3;

use crate::trace::shapes::Aabb;
use crate::trace::world::{ObjectSet, WorldLight};

/// Margin, relative to the lengths involved, by which a region must miss a box.
const RELATIVE_MARGIN: f64 = 1e-8;

/// A box by centre and half extent, with the margin its tests add.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CullBox {
    /// Centre, world space.
    pub centre: DVec3,
    /// Half extent.
    pub half: DVec3,
}

impl CullBox {
    /// The box of `bounds`.
    pub fn of(bounds: &Aabb) -> Self {
        Self {
            centre: (bounds.min + bounds.max) * 0.5,
            half: (bounds.max - bounds.min) * 0.5,
        }
    }

    fn min(&self) -> DVec3 {
        self.centre - self.half
    }

    fn max(&self) -> DVec3 {
        self.centre + self.half
    }
}

/// The box around every camera hit of a tile: `quad` holds the film directions of the
/// tile's corners (forward component 1, so depth `s` along the view is the point
/// `eye + s * quad[k]`), `forward` the unit view direction, and `candidates` the boxes
/// of the objects the tile's camera rays may hit. `None` when no candidate is in view.
pub(crate) fn tile_hit_box(
    eye: DVec3,
    forward: DVec3,
    quad: &[DVec3; 4],
    candidates: impl Iterator<Item = CullBox>,
) -> Option<CullBox> {
    let (quad_lo, quad_hi) = quad
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), u| {
            (lo.min(*u), hi.max(*u))
        });
    let mut lo = DVec3::INFINITY;
    let mut hi = DVec3::NEG_INFINITY;
    for object in candidates {
        let depth_centre = (object.centre - eye).dot(forward);
        let depth_half = object.half.dot(forward.abs());
        let (mut near, mut far) = (
            (depth_centre - depth_half).max(0.0),
            depth_centre + depth_half,
        );
        // Tighter: the multiples s of the film directions at which some ray of the tile
        // is inside the box's slab on each axis (the directions' components span
        // [quad_lo, quad_hi]).
        for axis in 0..3 {
            let (s0, s1) = slab_span(
                eye[axis],
                quad_lo[axis],
                quad_hi[axis],
                object.min()[axis],
                object.max()[axis],
            );
            near = near.max(s0);
            far = far.min(s1);
        }
        if near > far {
            continue; // no ray of the tile meets this box
        }
        let (mut clipped_lo, mut clipped_hi) = (object.min(), object.max());
        // (A NaN depth keeps the whole box.)
        if near <= far {
            // The pyramid between those depths is the hull of its eight corners.
            let (near, far) = (
                near * (1.0 - RELATIVE_MARGIN),
                far * (1.0 + RELATIVE_MARGIN),
            );
            let mut frustum_lo = DVec3::INFINITY;
            let mut frustum_hi = DVec3::NEG_INFINITY;
            for s in [near, far] {
                for corner in quad {
                    let p = eye + s * *corner;
                    frustum_lo = frustum_lo.min(p);
                    frustum_hi = frustum_hi.max(p);
                }
            }
            let reach = (frustum_hi - frustum_lo).max_element()
                + frustum_hi.abs().max(frustum_lo.abs()).max_element();
            let margin = DVec3::splat(RELATIVE_MARGIN * reach);
            clipped_lo = clipped_lo.max(frustum_lo - margin);
            clipped_hi = clipped_hi.min(frustum_hi + margin);
        }
        if clipped_lo.cmple(clipped_hi).all() {
            lo = lo.min(clipped_lo);
            hi = hi.max(clipped_hi);
        }
    }
    if !lo.cmple(hi).all() {
        return None;
    }
    let reach = (hi - lo).max_element() + hi.abs().max(lo.abs()).max_element();
    let margin = DVec3::splat(RELATIVE_MARGIN * reach);
    Some(CullBox::of(&Aabb::new(lo - margin, hi + margin)))
}

/// The multiples `s >= 0` for which `origin + s u` lies in `[min, max]` for some `u` in
/// `[u_lo, u_hi]` (one axis), widened by a relative margin: `(near, far)`, empty when
/// `near > far`.
fn slab_span(origin: f64, u_lo: f64, u_hi: f64, min: f64, max: f64) -> (f64, f64) {
    let (mut near, mut far) = (0.0f64, f64::INFINITY);
    // origin + s u_lo <= max: the lowest reach must not pass the top.
    let to_max = max - origin;
    if u_lo > 0.0 {
        far = far.min(to_max / u_lo);
    } else if u_lo < 0.0 {
        near = near.max(to_max / u_lo);
    } else if to_max < 0.0 {
        return (1.0, 0.0);
    }
    // origin + s u_hi >= min: the highest reach must get past the bottom.
    let to_min = min - origin;
    if u_hi > 0.0 {
        near = near.max(to_min / u_hi);
    } else if u_hi < 0.0 {
        far = far.min(to_min / u_hi);
    } else if to_min > 0.0 {
        return (1.0, 0.0);
    }
    if near.is_nan() || far.is_nan() {
        return (0.0, f64::INFINITY);
    }
    (
        near * (1.0 - RELATIVE_MARGIN),
        far * (1.0 + RELATIVE_MARGIN),
    )
}

/// The objects (of `boxes`, by index) that may block a shadow ray from a point of
/// `hits` to `light`.
pub(crate) fn shadow_set(hits: &CullBox, light: &WorldLight, boxes: &[CullBox]) -> ObjectSet {
    let mut set = ObjectSet::none();
    for (index, object) in boxes.iter().enumerate() {
        if may_block(hits, light, object) {
            set.insert(index);
        }
    }
    set
}

/// Whether a shadow ray from `hits` to `light` may meet `object`'s box.
fn may_block(hits: &CullBox, light: &WorldLight, object: &CullBox) -> bool {
    let (hits_lo, hits_hi) = (hits.min(), hits.max());
    let (target, toward) = match *light {
        WorldLight::Point { position, .. } | WorldLight::Spot { position, .. } => (position, None),
        WorldLight::Directional { to_light, .. } => (hits.centre, Some(to_light)),
    };
    let reach = (object.centre - hits.centre).length()
        + (target - hits.centre).length()
        + object.half.length()
        + hits.half.length()
        + object.centre.abs().max_element()
        + target.abs().max_element();
    let margin = RELATIVE_MARGIN * reach;
    // The region's box on each axis: to the light's position, or unbounded the way the
    // light's direction goes.
    let (mut lo, mut hi) = (hits_lo.min(target), hits_hi.max(target));
    if let Some(w) = toward {
        for axis in 0..3 {
            if w[axis] > 0.0 {
                hi[axis] = f64::INFINITY;
            } else if w[axis] < 0.0 {
                lo[axis] = f64::NEG_INFINITY;
            }
        }
    }
    let apart = (object.min() - hi).max(lo - object.max());
    if apart.max_element() > margin {
        return false;
    }
    // The capsule round the segment (or half-line) from H's centre to the light, of H's
    // bounding radius, holds the whole region.
    let axis_point = match toward {
        None => closest_on_segment(hits.centre, target, object.centre),
        Some(w) => hits.centre + w * (object.centre - hits.centre).dot(w).max(0.0),
    };
    let distance = (object.centre - axis_point).length();
    distance <= hits.half.length() + object.half.length() + margin || distance.is_nan()
}

/// The point of the segment from `a` to `b` closest to `p`.
fn closest_on_segment(a: DVec3, b: DVec3, p: DVec3) -> DVec3 {
    let ab = b - a;
    let length_sq = ab.length_squared();
    if length_sq == 0.0 {
        return a;
    }
    a + ab * ((p - a).dot(ab) / length_sq).clamp(0.0, 1.0)
}
