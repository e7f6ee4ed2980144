//! A pixel's rays as one flat list, read off its [`PixelReport`]: the camera ray, each
//! mirror and transmitted ray and every shadow ray, each with where it started, which way it went,
//! how far it got and what it met. `raylab inspect --json` prints this list and the
//! editor's ray-path overlay draws it, so both show exactly what the shader computed.

use glam::DVec3;

use super::pixel::PixelReport;
use crate::trace::shade::Branch;
use crate::trace::world::SurfacePoint;

/// Which kind of ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    /// The camera ray through the pixel.
    Primary,
    /// A ray from a hit point towards a light.
    Shadow,
    /// A mirror bounce.
    Reflection,
    /// A transmitted ray bent by Snell's law.
    Refraction,
    /// A transmitted share sent along the mirror direction: total internal reflection.
    InternalReflection,
}

impl RayKind {
    /// "primary", "shadow", "reflection", "refraction" or "internal-reflection", as in
    /// `raylab inspect --json`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Primary => "primary",
            RayKind::Shadow => "shadow",
            RayKind::Reflection => "reflection",
            RayKind::Refraction => "refraction",
            RayKind::InternalReflection => "internal-reflection",
        }
    }
}

/// Where a ray met a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// The scene index of the object.
    pub object: usize,
    /// The point.
    pub point: DVec3,
    /// The unit normal there, facing the ray.
    pub normal: DVec3,
}

impl RayHit {
    fn of(hit: &SurfacePoint) -> Self {
        Self {
            object: hit.object,
            point: hit.p,
            normal: hit.n,
        }
    }
}

/// One ray of a pixel's tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TracedRay {
    /// Which kind.
    pub kind: RayKind,
    /// 0 for the camera ray and its shadow rays, 1 for the rays it started and their
    /// shadow rays, and so on.
    pub depth: u32,
    /// Where it starts (a secondary ray's origin is offset off the surface).
    pub origin: DVec3,
    /// Unit direction.
    pub direction: DVec3,
    /// Distance along `direction` to the surface it met, `None` when it met none.
    pub t: Option<f64>,
    /// Distance the ray looked to, `None` for no limit: a shadow ray stops just short of
    /// its light.
    pub t_max: Option<f64>,
    /// What it met: the closest surface for a camera or mirror ray, the blocker for a
    /// shadow ray.
    pub hit: Option<RayHit>,
    /// For a shadow ray, the index of its light in the scene's light list.
    pub light: Option<usize>,
    /// For a shadow ray, the scene index of the object that blocked it.
    pub blocked_by: Option<usize>,
}

impl TracedRay {
    /// The point at distance `distance` along the ray.
    #[must_use]
    pub fn at(&self, distance: f64) -> DVec3 {
        self.origin + self.direction * distance
    }
}

/// Every ray behind the pixel of `report`, bounce by bounce: each bounce's own ray, then
/// its shadow rays in light order.
#[must_use]
pub fn traced_rays(report: &PixelReport) -> Vec<TracedRay> {
    let mut rays = Vec::new();
    for bounce in &report.bounces {
        let length = bounce.ray.dir.length();
        rays.push(TracedRay {
            kind: match bounce.from {
                None => RayKind::Primary,
                Some((_, Branch::Mirror)) => RayKind::Reflection,
                Some((_, Branch::Refracted)) => RayKind::Refraction,
                Some((_, Branch::InternallyReflected)) => RayKind::InternalReflection,
            },
            depth: bounce.depth,
            origin: bounce.ray.origin,
            direction: bounce.ray.dir / length,
            t: bounce.hit.map(|hit| hit.t * length),
            t_max: None,
            hit: bounce.hit.as_ref().map(RayHit::of),
            light: None,
            blocked_by: None,
        });
        // A sphere light's rays, each with its own end (the blocker is found again
        // where the overlay needs its point: not here).
        for (light, shadow) in &bounce.sphere_shadow_rays {
            let length = shadow.ray.dir.length();
            rays.push(TracedRay {
                kind: RayKind::Shadow,
                depth: bounce.depth,
                origin: shadow.ray.origin,
                direction: shadow.ray.dir / length,
                t: None,
                t_max: shadow.t_max.is_finite().then_some(shadow.t_max * length),
                hit: None,
                light: Some(*light),
                blocked_by: shadow.blocked_by,
            });
        }
        for light in &bounce.lights {
            let Some(shadow) = light.shadow_ray else {
                continue;
            };
            let length = shadow.ray.dir.length();
            let blocker = bounce.blocker_hit(light.scene_index);
            rays.push(TracedRay {
                kind: RayKind::Shadow,
                depth: bounce.depth,
                origin: shadow.ray.origin,
                direction: shadow.ray.dir / length,
                t: blocker.map(|hit| hit.t * length),
                t_max: shadow.t_max.is_finite().then_some(shadow.t_max * length),
                hit: blocker.map(RayHit::of),
                light: Some(light.scene_index),
                blocked_by: shadow.blocked_by,
            });
        }
    }
    rays
}
