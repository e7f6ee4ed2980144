//! Where the shader's rays get their answers. The shader ([`super::tracer::Tracer`]) asks
//! a [`RaySource`] for the closest hit of each ray of a camera ray's tree (each named by
//! its [`RayAt`]) and for the object blocking each shadow ray; [`LiveRays`] asks the world (the only place the shader's rays
//! meet [`World::intersect`] and [`World::occluder_except`]), and the hit cache of
//! [`crate::trace::render::cached`] answers from rays it traced before. Both feed the one lighting model,
//! so a re-shaded pixel is the same arithmetic as a traced one.

use super::bounce_tree::RayAt;
use super::lit_factors::LitFactors;
use crate::trace::cull::Candidates;
use crate::trace::ray::Ray;
use crate::trace::world::{ObjectSet, SurfacePoint, World};

/// A shadow ray the shader needs the answer to.
#[derive(Clone, Copy, Debug)]
pub struct ShadowQuery {
    /// The shadow ray, from the hit's offset origin.
    pub ray: Ray,
    /// How far it looks.
    pub t_max: f64,
}

/// Which shadow ray the shader asks about: from the hit of ray `node` (at `depth`) of the
/// tree to light `light` (an index into [`World::lights`]); the ray cannot meet object
/// `except` (the one it leaves on its outer side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShadowRequest {
    /// Depth in the tree of the hit the ray leaves.
    pub depth: u32,
    /// Index in the tree ([`RayAt::node`]) of the ray whose hit it leaves.
    pub node: u32,
    /// The light it goes to.
    pub light: usize,
    /// The object it cannot meet.
    pub except: Option<usize>,
    /// The object whose surface it leaves.
    pub from: usize,
    /// It aims at a point of a sphere light other than the light's position (the tile's
    /// shadow culling, made for the position, does not hold for it).
    pub off_centre: bool,
    /// The only objects that may block it, as the shader found (a sphere light's cone
    /// from the point: [`crate::trace::world::LightCone`]); [`ObjectSet::ALL`] otherwise.
    pub within: ObjectSet,
}

/// Makes the shadow ray, for a source that has to cast it (a cache that knows the answer
/// never does).
pub trait MakeRay: FnOnce() -> ShadowQuery {}

impl<F: FnOnce() -> ShadowQuery> MakeRay for F {}

/// Answers the shader's ray queries for one pixel sample, in the order the shader asks:
/// the camera ray, then each ray of its tree in the order of [`RayAt::node`], a hit's
/// shadow rays before the next ray.
pub trait RaySource {
    /// The closest hit of `ray`, the ray `at` of the tree.
    fn closest_hit(&mut self, world: &World, at: RayAt, ray: &Ray) -> Option<SurfacePoint>;

    /// The world index of an object blocking the shadow ray `to`, if any; `ray` makes
    /// the ray, for a source that has to cast it.
    fn occluder(&mut self, world: &World, to: ShadowRequest, ray: impl MakeRay) -> Option<usize>;

    /// How many of the `samples` shadow rays from the hit of ray `node` to sphere light
    /// `light` reach it, and the first blocker met: `cast` casts them through this source
    /// (each an `off_centre` request; none where the point's cone shows them all clear)
    /// and counts them. A source that keeps the count may give it without casting, and
    /// then names no blocker.
    #[inline]
    fn sphere_rays_clear(
        &mut self,
        _node: u32,
        _light: usize,
        _samples: u32,
        cast: impl FnOnce(&mut Self) -> (u32, Option<usize>),
    ) -> (u32, Option<usize>)
    where
        Self: Sized,
    {
        cast(self)
    }

    /// Offers what light `light` (an index into [`World::lights`]) gave the hit of ray
    /// `node`, for a source that keeps it: the one call through which the
    /// re-shade cache learns from the shader. `factors` is worked out only if the source
    /// wants it (it does not have it yet), whatever the switches.
    #[inline]
    fn keep_light_factors(
        &mut self,
        _node: u32,
        _light: usize,
        _factors: impl FnOnce() -> LitFactors,
    ) {
    }
}

/// Traces every ray in the world. The camera ray and the shadow rays from its hit test
/// only the objects its tile's culling left (see [`crate::trace::cull::tiles`]: exact, so the
/// answers are those of the full list); mirror rays test every object.
#[derive(Clone, Copy, Debug)]
pub struct LiveRays<'c> {
    among: Candidates<'c>,
}

impl LiveRays<'static> {
    /// Every object for every ray.
    #[must_use]
    pub fn all() -> Self {
        Self {
            among: Candidates::ALL,
        }
    }
}

impl<'c> LiveRays<'c> {
    /// The camera ray may meet only what `among` names.
    #[must_use]
    pub fn among(among: Candidates<'c>) -> Self {
        Self { among }
    }
}

impl RaySource for LiveRays<'_> {
    #[inline]
    fn closest_hit(&mut self, world: &World, at: RayAt, ray: &Ray) -> Option<SurfacePoint> {
        if at.depth == 0 {
            world.intersect_among(ray, f64::INFINITY, self.among.camera)
        } else {
            world.intersect(ray, f64::INFINITY)
        }
    }

    #[inline]
    fn occluder(&mut self, world: &World, to: ShadowRequest, ray: impl MakeRay) -> Option<usize> {
        let except = to.except;
        if to.depth == 0 && !to.off_centre {
            let among = self.among.shadow(to.light);
            // Culling left nothing that could block: no ray to spawn (about a quarter
            // of the default scene's camera hits' shadow rays).
            if among.without(except).is_empty_below(world.objects.len()) {
                return None;
            }
            let query = ray();
            world.occluder_except_among(&query.ray, query.t_max, except, among)
        } else {
            let query = ray();
            world.occluder_except_among(&query.ray, query.t_max, except, to.within)
        }
    }
}
