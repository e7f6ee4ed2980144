//! Which of its parent's rays a secondary ray is: the recorders and the ray tree both
//! name rays by it.

/// Which of its parent's rays a secondary ray is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Branch {
    /// The mirror ray (weight km).
    Mirror,
    /// The transmitted ray, bent by Snell's law (weight kt).
    Refracted,
    /// The transmitted share where Snell's law has no solution: along the mirror
    /// direction (weight kt).
    InternallyReflected,
}

impl Branch {
    /// Whether the ray carries the transmitted share (refracted or internally reflected).
    #[must_use]
    pub fn is_transmitted(self) -> bool {
        self != Branch::Mirror
    }
}
