//! Rays: an origin and a direction, parameterised by t.

use glam::{DAffine3, DVec3};

/// A ray `origin + t * dir`. `dir` need not be unit length (object-space rays are not),
/// so `t` keeps its meaning across the world-to-object transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: DVec3,
    /// Which way it goes; not necessarily unit length.
    pub dir: DVec3,
}

impl Ray {
    /// A ray from `origin` along `dir`.
    #[must_use]
    pub fn new(origin: DVec3, dir: DVec3) -> Self {
        Self { origin, dir }
    }

    /// The point at parameter `t`.
    #[must_use]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.dir
    }

    /// The same ray in another space; `t` is unchanged because `dir` is not renormalised.
    #[must_use]
    pub fn transformed(&self, b_from_a: &DAffine3) -> Self {
        Self {
            origin: b_from_a.transform_point3(self.origin),
            dir: b_from_a.transform_vector3(self.dir),
        }
    }
}
