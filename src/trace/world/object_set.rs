//! A set of a world's objects by index, as a bit mask: what a culling step hands the
//! ray queries so they test fewer objects. Objects from index 64 on are always in the
//! set (culling covers the first 64; a world that large walks a BVH over the rest).

/// A set of object indices into [`super::World::objects`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ObjectSet {
    /// Bit `i` set: object `i` is in the set (for `i < 64`).
    bits: u64,
}

impl ObjectSet {
    /// Every object.
    pub const ALL: Self = Self { bits: u64::MAX };

    /// Objects are culled only below this index.
    pub const CULLED_BELOW: usize = 64;

    /// No object below [`Self::CULLED_BELOW`].
    #[must_use]
    pub const fn none() -> Self {
        Self { bits: 0 }
    }

    /// Adds object `index` (a no-op from [`Self::CULLED_BELOW`] on: those are always in).
    pub fn insert(&mut self, index: usize) {
        if index < Self::CULLED_BELOW {
            self.bits |= 1 << index;
        }
    }

    /// Whether object `index` is in the set.
    #[must_use]
    #[inline]
    pub fn contains(self, index: usize) -> bool {
        index >= Self::CULLED_BELOW || self.bits & (1 << index) != 0
    }

    /// The indices below `count` in the set, ascending (scene order).
    #[inline]
    pub fn members_below(self, count: usize) -> Members {
        let culled = count.min(Self::CULLED_BELOW);
        let bits = if culled == Self::CULLED_BELOW {
            self.bits
        } else {
            self.bits & ((1 << culled) - 1)
        };
        Members {
            bits,
            next_unculled: Self::CULLED_BELOW,
            count,
        }
    }

    /// The set less object `index`, if it is one culling covers (those from
    /// [`Self::CULLED_BELOW`] on stay in).
    #[must_use]
    #[inline]
    pub fn without(self, index: Option<usize>) -> Self {
        match index {
            Some(index) if index < Self::CULLED_BELOW => Self {
                bits: self.bits & !(1 << index),
            },
            _ => self,
        }
    }

    /// Whether none of the first `count` objects is in the set.
    #[must_use]
    #[inline]
    pub fn is_empty_below(self, count: usize) -> bool {
        self.members_below(count).next().is_none()
    }

    /// How many of the first `count` objects are in the set.
    #[must_use]
    pub fn count_below(self, count: usize) -> usize {
        (0..count).filter(|&i| self.contains(i)).count()
    }
}

/// The iterator of [`ObjectSet::members_below`].
#[derive(Clone, Debug)]
pub struct Members {
    /// Members below [`ObjectSet::CULLED_BELOW`] not yet visited.
    bits: u64,
    /// The next index from [`ObjectSet::CULLED_BELOW`] on (all members).
    next_unculled: usize,
    count: usize,
}

impl Iterator for Members {
    type Item = usize;

    #[inline]
    fn next(&mut self) -> Option<usize> {
        if self.bits != 0 {
            let index = self.bits.trailing_zeros() as usize;
            self.bits &= self.bits - 1;
            return Some(index);
        }
        if self.next_unculled < self.count {
            self.next_unculled += 1;
            return Some(self.next_unculled - 1);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn insert_contains_and_the_always_present_tail() {
        let mut set = ObjectSet::none();
        assert!(!set.contains(3));
        set.insert(3);
        set.insert(63);
        set.insert(200);
        assert!(set.contains(3) && set.contains(63) && !set.contains(4));
        assert!(
            set.contains(64) && set.contains(1000),
            "beyond 64 always in"
        );
        assert_eq!(set.members_below(10).collect::<Vec<_>>(), vec![3]);
        assert_eq!(
            set.members_below(66).collect::<Vec<_>>(),
            vec![3, 63, 64, 65]
        );
        assert_eq!(set.count_below(64), 2);
        assert_eq!(ObjectSet::ALL.count_below(7), 7);
        let only_three = set.without(Some(63));
        assert!(!only_three.is_empty_below(64) && only_three.without(Some(3)).is_empty_below(64));
        assert!(
            !only_three.without(Some(3)).is_empty_below(65),
            "the tail is never culled"
        );
        assert_eq!(set.without(Some(200)), set, "nor taken out");
        assert_eq!(set.without(None), set);
    }
}
