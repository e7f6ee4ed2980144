//! Where in a pixel each anti-aliasing sample goes.

use glam::DVec2;

/// The stratification of `count` samples per pixel: a grid of exactly `count` equal
/// cells (`rows` the largest divisor of `count` not above its square root), so every
/// stratum has the same area and no part of the pixel is left out, whatever the count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strata {
    columns: u32,
    rows: u32,
}

impl Strata {
    /// The grid for `count` samples (at least 1).
    #[must_use]
    pub fn for_count(count: u32) -> Self {
        let count = count.max(1);
        let mut rows = (f64::from(count).sqrt() as u32).max(1);
        while !count.is_multiple_of(rows) {
            rows -= 1;
        }
        Self {
            columns: count / rows,
            rows,
        }
    }

    /// The position within pixel `(px, py)` (each coordinate in [0, 1)) of sample
    /// `index`. One sample is the pixel centre. More samples take one cell each, jittered
    /// within it by a deterministic hash of the pixel and index, so renders are
    /// repeatable and samples can be added one pass at a time.
    #[must_use]
    pub fn sample(&self, px: u32, py: u32, index: u32) -> DVec2 {
        if self.columns * self.rows == 1 {
            return DVec2::splat(0.5);
        }
        let cell = DVec2::new(
            f64::from(index % self.columns),
            f64::from(index / self.columns % self.rows),
        );
        let jitter = DVec2::new(
            unit_hash(px, py, index, 0x9e37_79b9),
            unit_hash(px, py, index, 0x85eb_ca6b),
        );
        (cell + jitter) / DVec2::new(f64::from(self.columns), f64::from(self.rows))
    }
}

/// Sample `index` of `count` within pixel `(px, py)`; see [`Strata::sample`]. Callers
/// that take many samples build the [`Strata`] once.
#[must_use]
pub fn sample_in_pixel(px: u32, py: u32, index: u32, count: u32) -> DVec2 {
    Strata::for_count(count).sample(px, py, index)
}

/// Sample `index` of an open-ended low-discrepancy sequence within pixel `(px, py)`: the
/// R2 sequence (additive recurrence on the plastic number), shifted per pixel by a hash.
/// Any prefix is well spread, so it suits sample counts decided on the fly.
#[must_use]
pub fn sample_sequence(px: u32, py: u32, index: u32) -> DVec2 {
    const PLASTIC: f64 = 1.324_717_957_244_746;
    let alpha = DVec2::new(1.0 / PLASTIC, 1.0 / (PLASTIC * PLASTIC));
    let shift = DVec2::new(
        unit_hash(px, py, u32::MAX, 0x27d4_eb2f),
        unit_hash(px, py, u32::MAX, 0x1656_67b1),
    );
    (shift + alpha * f64::from(index)).fract()
}

/// A hash of the inputs mapped to [0, 1).
fn unit_hash(x: u32, y: u32, i: u32, salt: u32) -> f64 {
    let mut h = u64::from(x) | (u64::from(y) << 32);
    h ^= u64::from(i).wrapping_mul(0x2545_f491_4f6c_dd1d) ^ u64::from(salt);
    // splitmix64 finaliser
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sample_is_the_centre() {
        assert_eq!(sample_in_pixel(3, 7, 0, 1), DVec2::splat(0.5));
    }

    #[test]
    fn samples_fill_distinct_cells_of_the_pixel() {
        let count = 16;
        let mut cells = std::collections::HashSet::new();
        for i in 0..count {
            let s = sample_in_pixel(1, 2, i, count);
            assert!(s.x >= 0.0 && s.x < 1.0 && s.y >= 0.0 && s.y < 1.0);
            cells.insert(((s.x * 4.0) as u32, (s.y * 4.0) as u32));
        }
        assert_eq!(cells.len(), 16);
        assert_eq!(sample_in_pixel(1, 2, 5, 16), sample_in_pixel(1, 2, 5, 16));
    }

    #[test]
    fn any_count_covers_the_pixel_with_equal_strata() {
        for (count, columns, rows) in [(2, 2, 1), (7, 7, 1), (12, 4, 3), (32, 8, 4), (64, 8, 8)] {
            assert_eq!(Strata::for_count(count), Strata { columns, rows });
            // Every cell holds exactly one sample.
            let strata = Strata::for_count(count);
            let mut cells = std::collections::HashSet::new();
            for i in 0..count {
                let s = strata.sample(9, 4, i);
                cells.insert((
                    (s.x * f64::from(columns)) as u32,
                    (s.y * f64::from(rows)) as u32,
                ));
            }
            assert_eq!(cells.len() as u32, count);
        }
    }
}
