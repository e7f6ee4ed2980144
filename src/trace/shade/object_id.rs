//! The object-id debug view's colours: one distinct hue per object.

use glam::DVec3;

/// A distinct, saturated colour for an object index (golden-ratio hue steps).
#[must_use]
pub fn object_id_colour(index: usize) -> DVec3 {
    let hue = (index as f64 * 0.618_033_988_749_895 + 0.1).fract() * 6.0;
    let x = 1.0 - (hue % 2.0 - 1.0).abs();
    let (r, g, b) = match hue as u32 {
        0 => (1.0, x, 0.0),
        1 => (x, 1.0, 0.0),
        2 => (0.0, 1.0, x),
        3 => (0.0, x, 1.0),
        4 => (x, 0.0, 1.0),
        _ => (1.0, 0.0, x),
    };
    DVec3::new(r, g, b) * 0.85 + 0.15
}
