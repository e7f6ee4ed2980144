//! Hit-testing handles on screen: which handle the pointer is over, in pixels.

use glam::DVec2;

/// How close (in pixels) the pointer must be to grab a handle.
pub const GRAB_RADIUS_PX: f64 = 8.0;

/// Distance from `p` to the segment `a`-`b`.
#[must_use]
pub fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let length_sq = ab.length_squared();
    let s = if length_sq > 0.0 {
        ((p - a).dot(ab) / length_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * s - p).length()
}

/// A handle's shape on screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HandleShape {
    /// A point handle (a dot).
    Point(DVec2),
    /// A line handle (an arrow shaft).
    Segment(DVec2, DVec2),
}

impl HandleShape {
    /// Distance from the pointer to the handle, in pixels.
    #[must_use]
    pub fn distance(&self, pointer: DVec2) -> f64 {
        match *self {
            HandleShape::Point(c) => (pointer - c).length(),
            HandleShape::Segment(a, b) => distance_to_segment(pointer, a, b),
        }
    }
}

/// The index of the nearest handle within [`GRAB_RADIUS_PX`] of the pointer. Point
/// handles win ties over segments (they are drawn on top).
#[must_use]
pub fn pick_handle(pointer: DVec2, handles: &[HandleShape]) -> Option<usize> {
    handles
        .iter()
        .enumerate()
        .map(|(i, h)| {
            let bias = if matches!(h, HandleShape::Point(_)) {
                -0.5
            } else {
                0.0
            };
            (i, h.distance(pointer) + bias)
        })
        .filter(|&(_, d)| d <= GRAB_RADIUS_PX)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn picks_the_nearest_handle_within_reach() {
        let handles = [
            HandleShape::Segment(DVec2::new(0.0, 0.0), DVec2::new(100.0, 0.0)),
            HandleShape::Point(DVec2::new(100.0, 0.0)),
            HandleShape::Segment(DVec2::new(0.0, 0.0), DVec2::new(0.0, 100.0)),
        ];
        assert_eq!(pick_handle(DVec2::new(50.0, 3.0), &handles), Some(0));
        assert_eq!(pick_handle(DVec2::new(99.0, 1.0), &handles), Some(1));
        assert_eq!(pick_handle(DVec2::new(-2.0, 60.0), &handles), Some(2));
        assert_eq!(pick_handle(DVec2::new(50.0, 50.0), &handles), None);
    }

    #[test]
    fn segment_distance_clamps_to_the_ends() {
        let (a, b) = (DVec2::ZERO, DVec2::new(10.0, 0.0));
        assert_eq!(distance_to_segment(DVec2::new(-3.0, 4.0), a, b), 5.0);
        assert_eq!(distance_to_segment(DVec2::new(5.0, -2.0), a, b), 2.0);
    }
}
