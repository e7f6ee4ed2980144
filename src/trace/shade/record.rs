//! What the shader tells a [`Recorder`]: the hits, terms and lights of each ray
//! ([`LightRecord`]), the shadow rays it cast (origin, direction, how far they looked,
//! what was in the way) and the lights it skipped, with the reason, so the inspector,
//! the ray-path overlay and `raylab inspect` can account for every light.

use glam::DVec3;

use super::branch::Branch;
use crate::trace::ray::Ray;
use crate::trace::world::{SurfacePoint, WorldLight};

/// One light's part in shading a point, as the inspector shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightRecord {
    /// Index of the light in the scene's light list.
    pub scene_index: usize,
    /// L_l(p): the light's strength arriving at the point, before visibility.
    pub strength: DVec3,
    /// n.l (may be negative: the light is behind the surface).
    pub n_dot_l: f64,
    /// The scene index of the object that blocked the shadow ray, if one did (for a
    /// sphere light: the first ray's blocker, where none of its rays reached it).
    pub blocked_by: Option<usize>,
    /// Whether a shadow ray was cast at all.
    pub shadow_ray_cast: bool,
    /// The shadow ray, when one was cast to a point light (a sphere light's rays go to
    /// [`Recorder::sphere_shadow_ray`]).
    pub shadow_ray: Option<ShadowRay>,
    /// The fraction of the shadow rays that reached the light (1 where none was cast),
    /// and how many were cast: vis_l of the lighting model.
    pub visibility: (f64, u32),
    /// The diffuse contribution added.
    pub diffuse: DVec3,
    /// The specular contribution added.
    pub specular: DVec3,
}

/// Receives the numbers behind one traced ray. Every method has an empty default, so the
/// renderer's [`NoRecorder`] costs nothing.
///
/// A camera ray starts a tree of rays (mirror and transmitted); `node` names a ray of it
/// by the order it was shaded: 0 for the camera ray, and on a plain mirror chain the
/// depth. [`Recorder::started`] says where each ray sits before anything else about it.
pub trait Recorder {
    /// Whether the recorder wants the calls at all: the shader does the extra work of
    /// accounting for skipped lights only when it does.
    const ACTIVE: bool = true;
    /// Ray `node`, at `depth` (0 = primary), starts: from ray `from.0` as its
    /// `from.1`, or from the camera (`None`).
    fn started(&mut self, _node: u32, _depth: u32, _from: Option<(u32, Branch)>) {}
    /// Ray `node` hit `hit`.
    fn hit(&mut self, _node: u32, _ray: &Ray, _hit: &SurfacePoint) {}
    /// Ray `node` hit nothing and returns `background`.
    fn miss(&mut self, _node: u32, _ray: &Ray, _background: DVec3) {}
    /// The ambient term of ray `node`.
    fn ambient(&mut self, _node: u32, _colour: DVec3) {}
    /// A light at the hit of ray `node` that can reach it (in front of the surface or not).
    fn light(&mut self, _node: u32, _record: &LightRecord) {}
    /// One of a sphere light's shadow rays from the hit of ray `node`, as cast, to the
    /// light with scene index `light`.
    fn sphere_shadow_ray(&mut self, _node: u32, _light: usize, _ray: &ShadowRay) {}
    /// A light passed over at the hit of ray `node`, and why.
    fn skipped_light(&mut self, _node: u32, _skipped: &SkippedLight) {}
    /// The mirror term of ray `node`: `km * reflected` was added.
    fn reflection(&mut self, _node: u32, _km: DVec3, _reflected: DVec3) {}
    /// The transmission term of ray `node`: `kt * transmitted` was added, brought by a
    /// ray that was refracted or internally reflected (`branch`).
    fn transmission(&mut self, _node: u32, _kt: DVec3, _transmitted: DVec3, _branch: Branch) {}
    /// The colour returned for ray `node`.
    fn result(&mut self, _node: u32, _colour: DVec3) {}
    /// The ray's colour before the `EachRay` convention clamped it (only where the clamp
    /// changed it), before its `result`.
    fn clamped(&mut self, _node: u32, _unclamped: DVec3) {}
}

/// A recorder that records nothing.
pub struct NoRecorder;

impl Recorder for NoRecorder {
    const ACTIVE: bool = false;
}

/// A shadow ray as the shader cast it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowRay {
    /// The ray, from the hit point's offset origin. Towards a light with a position its
    /// `dir` is the whole way there: the light is at `t = 1`.
    pub ray: Ray,
    /// How far the ray looked: just short of the light, or infinity for a light at
    /// infinity.
    pub t_max: f64,
    /// The object found in the way, if any (the first one the search met, which need not
    /// be the nearest): the world's index inside the shader, the scene's in the records
    /// recorders are handed.
    pub blocked_by: Option<usize>,
}

/// Why a light was not even sampled at a point: no shadow ray, nothing added.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightSkip {
    /// The point lies outside the spotlight's cone.
    OutsideSpotCone,
    /// The point is exactly at the light: no direction to it.
    AtTheLight,
    /// The material has neither diffuse nor specular colour.
    NoDiffuseOrSpecular,
    /// Both the diffuse and the specular terms are switched off.
    TermsOff,
}

impl LightSkip {
    /// The reason in words: "outside the spot cone".
    #[must_use]
    pub fn text(self) -> &'static str {
        match self {
            LightSkip::OutsideSpotCone => "outside the spot cone",
            LightSkip::AtTheLight => "the point is at the light",
            LightSkip::NoDiffuseOrSpecular => "the material has no diffuse or specular",
            LightSkip::TermsOff => "diffuse and specular are switched off",
        }
    }
}

/// A light the shader passed over at a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SkippedLight {
    /// Index of the light in the scene's light list.
    pub scene_index: usize,
    /// Why.
    pub why: LightSkip,
}

/// What one light did for a point, in the inspector's words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightOutcome {
    /// It reached the point and added diffuse or specular light.
    Lit,
    /// It reached the point, but both its diffuse and specular parts are zero here
    /// (a switched-off term, a zero colour, or a highlight that points elsewhere).
    AddsNothing,
    /// It is behind the surface (n.l <= 0): no shadow ray, nothing added.
    BehindSurface,
    /// Its shadow ray met this object.
    Shadowed(usize),
    /// The shader passed it over.
    Skipped(LightSkip),
}

impl LightOutcome {
    /// The outcome of a light the shader sampled.
    #[must_use]
    pub fn of(record: &super::record::LightRecord) -> Self {
        if record.n_dot_l <= 0.0 {
            LightOutcome::BehindSurface
        } else if let Some(blocker) = record.blocked_by {
            LightOutcome::Shadowed(blocker)
        } else if record.diffuse + record.specular == DVec3::ZERO {
            LightOutcome::AddsNothing
        } else {
            LightOutcome::Lit
        }
    }

    /// Whether the light added anything.
    #[must_use]
    pub fn adds_light(self) -> bool {
        self == LightOutcome::Lit
    }

    /// The outcome in words, naming a blocker with `object_name`: "shadowed by red ball".
    #[must_use]
    pub fn text(self, object_name: &dyn Fn(usize) -> String) -> String {
        match self {
            LightOutcome::Lit => "lit".to_owned(),
            LightOutcome::AddsNothing => "reaches the point but adds nothing here".to_owned(),
            LightOutcome::BehindSurface => "behind the surface".to_owned(),
            LightOutcome::Shadowed(blocker) => format!("shadowed by {}", object_name(blocker)),
            LightOutcome::Skipped(why) => why.text().to_owned(),
        }
    }
}

/// Why `light` gave no sample at `p` (it returned `None` from `sample`): outside a spot
/// cone, or `p` at the light itself.
#[must_use]
pub fn unsampled_reason(light: &WorldLight, p: DVec3) -> LightSkip {
    let at = |position: DVec3| {
        let d2 = (position - p).length_squared();
        d2 == 0.0 || !d2.is_finite()
    };
    match *light {
        WorldLight::Spot { position, .. } if !at(position) => LightSkip::OutsideSpotCone,
        _ => LightSkip::AtTheLight,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unsampled_spot_is_outside_its_cone_unless_the_point_is_at_it() {
        let spot = WorldLight::Spot {
            position: DVec3::Y,
            axis: -DVec3::Y,
            cos_angle: 0.9,
            strength: DVec3::ONE,
        };
        let outside = DVec3::new(5.0, 0.0, 0.0);
        assert!(spot.sample(outside).is_none());
        assert_eq!(unsampled_reason(&spot, outside), LightSkip::OutsideSpotCone);
        assert!(spot.sample(DVec3::Y).is_none());
        assert_eq!(unsampled_reason(&spot, DVec3::Y), LightSkip::AtTheLight);
    }
}
