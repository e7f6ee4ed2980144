//! A pixel's ray tree as world-space segments, for the viewport's ray-path overlay: each
//! traced ray from its origin to where it stopped (a hit, its blocker, its light) or
//! running off when it met nothing; a stub towards every light that added nothing
//! without a shadow ray (behind the surface, outside the spot cone...); the normal at
//! each hit. Read off the tracer's own record, so what is drawn is what was computed.

use glam::DVec3;

use crate::scene::Light;
use crate::trace::{LightOutcome, PixelReport, RayKind, TracedRay, traced_rays};

/// What a segment shows (each kind can be switched off in the overlay).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentKind {
    /// A traced ray.
    Ray(RayKind),
    /// A light the point was shaded without a shadow ray: towards it, and why.
    Unreached(LightOutcome),
    /// The shading normal at a hit.
    Normal,
}

/// How a segment ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentEnd {
    /// On a surface the ray hit.
    Hit,
    /// On the object that blocked a shadow ray.
    Blocked,
    /// At the light a shadow ray reached.
    ReachesLight,
    /// Nowhere: the ray met nothing (drawn running off).
    RunsOff,
}

/// One segment of the tree, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathSegment {
    /// What it shows.
    pub kind: SegmentKind,
    /// The bounce it belongs to (0: the camera ray's hit).
    pub depth: u32,
    /// Index into [`traced_rays`] of the report, for a traced ray.
    pub ray: Option<usize>,
    /// For a shadow ray or an unreached light, the light's index in the scene.
    pub light: Option<usize>,
    /// The object at the end: the surface hit, the blocker, or the normal's surface.
    pub object: Option<usize>,
    /// Start.
    pub from: DVec3,
    /// End.
    pub to: DVec3,
    /// How it ends.
    pub end: SegmentEnd,
}

/// Lengths for what has no end of its own, in world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentLengths {
    /// A ray that met nothing, or a shadow ray to a light at infinity.
    pub run_off: f64,
    /// A normal; a stub towards an unreached light is twice as long.
    pub normal: f64,
}

/// The segments of `report` (traced in a scene with `lights`), in drawing order.
#[must_use]
pub fn path_segments(
    report: &PixelReport,
    lights: &[Light],
    lengths: SegmentLengths,
) -> Vec<PathSegment> {
    let rays = traced_rays(report);
    let mut out: Vec<PathSegment> = rays
        .iter()
        .enumerate()
        .map(|(index, ray)| ray_segment(index, ray, lengths.run_off))
        .collect();
    for bounce in &report.bounces {
        let Some(hit) = &bounce.hit else {
            continue;
        };
        out.push(PathSegment {
            kind: SegmentKind::Normal,
            depth: bounce.depth,
            ray: None,
            light: None,
            object: Some(hit.object),
            from: hit.p,
            to: hit.p + hit.n * lengths.normal,
            end: SegmentEnd::RunsOff,
        });
        for (light, outcome, record) in bounce.light_outcomes() {
            let cast = record.is_some_and(|r| r.shadow_ray.is_some());
            let Some(towards) = lights.get(light).and_then(|l| direction_to(l, hit.p)) else {
                continue;
            };
            if !cast {
                out.push(PathSegment {
                    kind: SegmentKind::Unreached(outcome),
                    depth: bounce.depth,
                    ray: None,
                    light: Some(light),
                    object: None,
                    from: hit.p,
                    to: hit.p + towards * lengths.normal * 2.0,
                    end: SegmentEnd::RunsOff,
                });
            }
        }
    }
    out
}

fn ray_segment(index: usize, ray: &TracedRay, run_off: f64) -> PathSegment {
    let (to, end) = match (ray.t, ray.kind) {
        (Some(t), RayKind::Shadow) => (ray.at(t), SegmentEnd::Blocked),
        (Some(t), _) => (ray.at(t), SegmentEnd::Hit),
        (None, RayKind::Shadow) => match ray.t_max {
            Some(t_max) => (ray.at(t_max), SegmentEnd::ReachesLight),
            None => (ray.at(run_off), SegmentEnd::RunsOff),
        },
        (None, _) => (ray.at(run_off), SegmentEnd::RunsOff),
    };
    PathSegment {
        kind: SegmentKind::Ray(ray.kind),
        depth: ray.depth,
        ray: Some(index),
        light: ray.light,
        object: ray.hit.map(|hit| hit.object),
        from: ray.origin,
        to,
        end,
    }
}

/// The unit direction from `p` towards a light; `None` for ambient light (everywhere)
/// or a light at `p`.
fn direction_to(light: &Light, p: DVec3) -> Option<DVec3> {
    let d = match *light {
        Light::Point { position, .. } | Light::Spot { position, .. } => position - p,
        Light::Directional { direction, .. } => -direction,
        Light::Ambient { .. } => return None,
    };
    let d = d.normalize_or_zero();
    (d != DVec3::ZERO).then_some(d)
}

/// The part of the segment `a`-`b` at least `near` in front of `eye` along the unit
/// `forward`, or `None` when all of it is nearer (so it projects without wrapping round).
#[must_use]
pub fn clip_in_front(
    a: DVec3,
    b: DVec3,
    eye: DVec3,
    forward: DVec3,
    near: f64,
) -> Option<(DVec3, DVec3)> {
    let (da, db) = ((a - eye).dot(forward) - near, (b - eye).dot(forward) - near);
    match (da >= 0.0, db >= 0.0) {
        (true, true) => Some((a, b)),
        (false, false) => None,
        (true, false) => Some((a, a + (b - a) * (da / (da - db)))),
        (false, true) => Some((a + (b - a) * (da / (da - db)), b)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_the_part_in_front() {
        let eye = DVec3::ZERO;
        let f = -DVec3::Z;
        let (a, b) = (DVec3::new(0.0, 0.0, 1.0), DVec3::new(0.0, 0.0, -3.0));
        let (p, q) = clip_in_front(a, b, eye, f, 1.0).unwrap();
        assert!((p - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
        assert_eq!(q, b);
        assert_eq!(clip_in_front(a, DVec3::Z * 2.0, eye, f, 0.1), None);
        assert_eq!(clip_in_front(b, b * 2.0, eye, f, 0.1), Some((b, b * 2.0)));
    }
}
