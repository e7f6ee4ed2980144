//! Where in a pixel each anti-aliasing sample goes.

use glam::DVec2;

/// The position within pixel `(px, py)` (each coordinate in [0, 1)) of sample `index` out
/// of `count`. One sample is the pixel centre. More samples are stratified: the pixel is
/// cut into a grid of about `count` cells, sample `index` takes cell `index`, and a
/// deterministic hash of the pixel and index jitters it within its cell, so renders are
/// repeatable and samples can be added one pass at a time.
#[must_use]
pub fn sample_in_pixel(px: u32, py: u32, index: u32, count: u32) -> DVec2 {
    if count <= 1 {
        return DVec2::splat(0.5);
    }
    let columns = (f64::from(count).sqrt().ceil() as u32).max(1);
    let rows = count.div_ceil(columns);
    let cell = DVec2::new(f64::from(index % columns), f64::from(index / columns));
    let jitter = DVec2::new(
        unit_hash(px, py, index, 0x9e37_79b9),
        unit_hash(px, py, index, 0x85eb_ca6b),
    );
    (cell + jitter) / DVec2::new(f64::from(columns), f64::from(rows))
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
}
