//! Axis-aligned bounding boxes, used to skip exact intersection tests.

use glam::{DAffine3, DMat3, DVec3};

use crate::trace::ray::Ray;

/// An axis-aligned box `[min, max]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: DVec3,
    /// Largest corner.
    pub max: DVec3,
}

impl Aabb {
    /// The box with these corners.
    #[must_use]
    pub fn new(min: DVec3, max: DVec3) -> Self {
        Self { min, max }
    }

    /// The smallest box holding both boxes.
    #[must_use]
    pub fn union(&self, other: &Aabb) -> Self {
        Self::new(self.min.min(other.min), self.max.max(other.max))
    }

    /// The box around this box's eight corners after `world_from_object`, grown by a
    /// relative margin so that rounding in the transform can never cull a real hit.
    #[must_use]
    pub fn transformed(&self, world_from_object: &DAffine3) -> Self {
        let mut min = DVec3::INFINITY;
        let mut max = DVec3::NEG_INFINITY;
        for corner in 0..8 {
            let pick = |bit: usize, axis: usize| {
                if corner & bit == 0 {
                    self.min[axis]
                } else {
                    self.max[axis]
                }
            };
            let p =
                world_from_object.transform_point3(DVec3::new(pick(1, 0), pick(2, 1), pick(4, 2)));
            min = min.min(p);
            max = max.max(p);
        }
        let margin = (max - min)
            .max_element()
            .max(max.abs().max(min.abs()).max_element())
            * 1e-9;
        Self::new(min - margin, max + margin)
    }

    /// Whether the ray passes through the box for some t in [0, t_max]. Conservative:
    /// a NaN from 0 * inf (origin on a slab plane, ray parallel to it) keeps the box.
    #[must_use]
    pub fn hit_by(&self, ray: &Ray, inv_dir: DVec3, t_max: f64) -> bool {
        let t0 = (self.min - ray.origin) * inv_dir;
        let t1 = (self.max - ray.origin) * inv_dir;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element().min(t_max);
        near <= far || near.is_nan() || far.is_nan()
    }
}

/// At least how far `m` moves a unit vector at most: the square root of Gershgorin's
/// bound on the largest eigenvalue of `m^T m`, the largest row sum of its absolute
/// values. That is the longest axis when the axes are perpendicular (a rotation of a
/// scale), and still a bound when a group's scale shears its rotated children, where the
/// longest axis is not.
#[must_use]
pub fn largest_stretch(m: &DMat3) -> f64 {
    // Symmetric: its columns are its rows.
    let gram = m.transpose() * *m;
    [gram.x_axis, gram.y_axis, gram.z_axis]
        .iter()
        .map(|row| row.abs().element_sum())
        .fold(0.0, f64::max)
        .sqrt()
}

/// A bounding sphere, for objects whose box is loose (spheres of any orientation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingSphere {
    /// Centre.
    pub centre: DVec3,
    /// Radius squared, slightly padded.
    pub radius_sq: f64,
}

impl BoundingSphere {
    /// The sphere around the unit sphere placed by `world_from_object`, padded by a
    /// relative 1e-9.
    #[must_use]
    pub fn around_unit_sphere(world_from_object: &DAffine3) -> Self {
        let radius = largest_stretch(&world_from_object.matrix3) * (1.0 + 1e-9);
        Self {
            centre: world_from_object.translation,
            radius_sq: radius * radius,
        }
    }

    /// Whether the ray can meet the sphere at some t in [0, t_max]. Conservative.
    #[must_use]
    pub fn hit_by(&self, ray: &Ray, t_max: f64) -> bool {
        let to_centre = self.centre - ray.origin;
        let d2 = ray.dir.length_squared();
        let along = to_centre.dot(ray.dir); // t of the closest approach, times |d|^2
        let distance_sq = to_centre.length_squared();
        if along < 0.0 {
            // Moving away: only a ray starting inside can meet it.
            return distance_sq <= self.radius_sq;
        }
        let miss_sq = distance_sq - along * along / d2;
        if miss_sq > self.radius_sq {
            return false;
        }
        // The nearest crossing must not be beyond t_max: t_near = (along - chord) / d2.
        let chord = ((self.radius_sq - miss_sq).max(0.0) * d2).sqrt();
        distance_sq <= self.radius_sq || along - chord <= t_max * d2 * (1.0 + 1e-9)
    }
}
