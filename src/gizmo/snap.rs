//! Snapping while Shift is held: 1 unit, 15 degrees, 0.1 of scale.

/// Translation snaps to whole units.
pub const TRANSLATE_STEP: f64 = 1.0;
/// Rotation snaps to 15 degrees.
pub const ROTATE_STEP_DEG: f64 = 15.0;
/// Scale snaps to tenths.
pub const SCALE_STEP: f64 = 0.1;

/// `value` rounded to the nearest multiple of `step`.
#[must_use]
pub fn snap(value: f64, step: f64) -> f64 {
    (value / step).round() * step
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snaps_to_the_nearest_step() {
        assert_eq!(snap(1.4, TRANSLATE_STEP), 1.0);
        assert_eq!(snap(-1.6, TRANSLATE_STEP), -2.0);
        assert_eq!(snap(22.0, ROTATE_STEP_DEG), 15.0);
        assert_eq!(snap(23.0, ROTATE_STEP_DEG), 30.0);
        assert!((snap(0.74, SCALE_STEP) - 0.7).abs() < 1e-12);
    }
}
