//! How many rays of each kind a render cast: the figure behind every Mrays/s.

/// Rays cast, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// Camera rays.
    pub primary: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Mirror rays.
    pub reflection: u64,
    /// Transmitted rays (refracted, or internally reflected).
    pub transmission: u64,
}

impl RayCounts {
    /// All rays.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.primary + self.shadow + self.reflection + self.transmission
    }

    /// Adds another tally to this one.
    pub fn add(&mut self, other: &RayCounts) {
        self.primary += other.primary;
        self.shadow += other.shadow;
        self.reflection += other.reflection;
        self.transmission += other.transmission;
    }
}
