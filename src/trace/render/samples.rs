//! From a film point to a colour: the one path every pass takes, traced or re-shaded,
//! with the guard that keeps non-finite colours out of the pixels.

use glam::{DVec2, DVec3};

use crate::trace::film::{PinholeCamera, sample_in_pixel};
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{LiveRays, NoRecorder, RaySource, Tracer};

/// One camera sample at `offset` (in [0, 1)^2) within pixel `(px, py)`. `None` when the
/// colour came out non-finite: the guard that keeps NaN and infinity out of every pixel
/// (the caller counts these; they should never happen).
#[inline]
pub fn trace_sample(
    tracer: &Tracer,
    camera: &PinholeCamera,
    px: u32,
    py: u32,
    offset: DVec2,
    rays: &mut RayCounts,
) -> Option<DVec3> {
    let colour = trace_colour(tracer, camera, film_point(px, py, offset), rays);
    colour.is_finite().then_some(colour)
}

/// The film point of the sample at `offset` within pixel `(px, py)`.
#[inline]
fn film_point(px: u32, py: u32, offset: DVec2) -> DVec2 {
    DVec2::new(f64::from(px), f64::from(py)) + offset
}

/// The unguarded colour of the camera ray through film point `point` (may be non-finite).
#[inline]
fn trace_colour(
    tracer: &Tracer,
    camera: &PinholeCamera,
    point: DVec2,
    rays: &mut RayCounts,
) -> DVec3 {
    camera_sample(tracer, camera, point, &mut LiveRays::all(), rays)
}

/// The unguarded colour of the camera ray through film point `point`, its rays answered
/// by `source`: the one path from a film point to a colour, traced or re-shaded.
#[inline]
pub(crate) fn camera_sample(
    tracer: &Tracer,
    camera: &PinholeCamera,
    point: DVec2,
    source: &mut impl RaySource,
    rays: &mut RayCounts,
) -> DVec3 {
    tracer.trace_primary_from(&camera.ray(point), source, rays, &mut NoRecorder)
}

/// The film point of sample `index` of `count` within pixel `(px, py)`.
#[inline]
pub(crate) fn sample_point(px: u32, py: u32, index: u32, count: u32) -> DVec2 {
    film_point(px, py, sample_in_pixel(px, py, index, count))
}
