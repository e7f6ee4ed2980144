//! Shadow rays: which object a shadow ray cannot meet, the ray itself (spawned once, in
//! `world::spawn`), the object blocking it as the ray source answers, a light's
//! visibility (one ray to a point light; for a sphere light the fraction of its
//! stratified rays that reach it) and the shadow-mask view (the mean visibility of the
//! lights that reach a point).

use super::phong::visible_fraction;
use super::ray_source::{RaySource, ShadowQuery, ShadowRequest};
use super::record::{NoRecorder, Recorder, ShadowRay};
use super::tracer::Tracer;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shapes::Primitive;
use glam::DVec3;

use crate::trace::world::{
    LightCone, LightSample, ObjectSet, SobolScramble, SphereLight, SurfacePoint, shading_seed,
    spawn_ray, spawn_ray_to,
};

/// Which light a shadow ray goes to, from the hit of which ray of the tree (its depth,
/// and its index for recorders).
#[derive(Clone, Copy, Debug)]
pub(super) struct LightAt {
    pub depth: u32,
    pub node: u32,
    pub index: usize,
}

/// What a light's shadow rays from a point found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Visibility {
    /// The fraction of the rays that reach the light.
    pub fraction: f64,
    /// The object met, where no ray reaches the light (the first ray's blocker).
    pub blocker: Option<usize>,
    /// How many rays were cast.
    pub rays: u32,
}

impl Tracer<'_> {
    /// The object blocking the shadow ray from `hit` (at `to.depth`) to light
    /// `to.index`, if any; `off_centre`: the ray aims at a point of a sphere light other
    /// than the light's position, and only the objects of that set may block it. The
    /// ray itself is made only if `rays` has to cast it.
    #[inline]
    fn shadow_blocker(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        to: LightAt,
        off_centre: Option<ObjectSet>,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> Option<usize> {
        counts.shadow += 1;
        let except = self.shadow_except(hit, sample);
        let target = ShadowRequest {
            depth: to.depth,
            node: to.node,
            light: to.index,
            except,
            from: hit.object,
            off_centre: off_centre.is_some(),
            within: off_centre.unwrap_or(ObjectSet::ALL),
        };
        rays.occluder(self.world, target, || self.shadow_query(hit, sample))
    }

    /// How much of light `to.index` (whose centre `sample` describes) `hit` sees: one
    /// shadow ray to a point light, `samples` stratified ones to a sphere light, each
    /// shown to `recorder` as it is cast (with the scene's index of the light).
    #[inline]
    pub(super) fn visibility<R: Recorder>(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        to: LightAt,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> Visibility {
        let (Some(sphere), Some(centre)) =
            (self.world.light_spheres[to.index], sample.light_position)
        else {
            let blocker = self.shadow_blocker(hit, sample, to, None, rays, counts);
            let fraction = if blocker.is_some() { 0.0 } else { 1.0 };
            return Visibility {
                fraction,
                blocker,
                rays: 1,
            };
        };
        self.sphere_visibility(hit, sample, (sphere, centre), to, rays, counts, recorder)
    }

    /// [`Self::visibility`] of a sphere light, out of line so that a point light's stays
    /// small enough to inline.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn sphere_visibility<R: Recorder>(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        (sphere, centre): (SphereLight, DVec3),
        to: LightAt,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> Visibility {
        let mut cast = false;
        let (clear, first_blocker) =
            rays.sphere_rays_clear(to.node, to.index, sphere.samples, |rays| {
                cast = true;
                // The rays' origins lie off the point by their offset (`spawn::offset_origin`).
                let apex_error = 4.0 * hit.p_error.length();
                let cone = LightCone::new(hit.p, centre, sphere.radius, apex_error);
                let within = cone.map_or(ObjectSet::ALL, |cone| {
                    self.disc_blockers(hit, &cone, centre, sphere.radius)
                });
                // Nothing can block any of the rays: the point sees the whole light; or a
                // ball blocks every one: it sees none. Then the rays are not cast (but
                // counted as cast; the inspector's recorder is shown each ray, and named
                // the blocker).
                if !R::ACTIVE {
                    let seen = if within.is_empty_below(self.world.objects.len()) {
                        Some(sphere.samples)
                    } else {
                        cone.filter(|cone| self.world.ball_hides_light(cone, within, hit.object))
                            .map(|_| 0)
                    };
                    if let Some(clear) = seen {
                        counts.shadow += u64::from(sphere.samples);
                        return (clear, None);
                    }
                }
                let scramble = SobolScramble::new(shading_seed(hit.p, to.index));
                let disc = sphere.disc_seen_from(centre, hit.p);
                let mut clear = 0u32;
                let mut first_blocker = None;
                for i in 0..sphere.samples {
                    let target = disc.point(i, &scramble);
                    let toward = LightSample {
                        light_position: Some(target),
                        to_light: (target - hit.p).normalize_or_zero(),
                        ..*sample
                    };
                    let blocker = self.shadow_blocker(hit, &toward, to, Some(within), rays, counts);
                    match blocker {
                        None => clear += 1,
                        Some(_) => first_blocker = first_blocker.or(blocker),
                    }
                    if R::ACTIVE {
                        let query = self.shadow_query(hit, &toward);
                        let light = self.world.light_scene_index[to.index];
                        let shadow = ShadowRay {
                            ray: query.ray,
                            t_max: query.t_max,
                            blocked_by: blocker.map(|b| self.world.scene_object(b)),
                        };
                        recorder.sphere_shadow_ray(to.node, light, &shadow);
                    }
                }
                (clear, first_blocker)
            });
        // Counted as cast, as a point light's answer from the cache is.
        if !cast {
            counts.shadow += u64::from(sphere.samples);
        }
        Visibility {
            fraction: visible_fraction(clear, sphere.samples),
            blocker: first_blocker.filter(|_| clear == 0),
            rays: sphere.samples,
        }
    }

    /// The objects that may block a shadow ray from `hit` to a point of the sphere light
    /// of `radius` about `centre`: those whose bounds meet `cone`, from the point round
    /// the light, less the object the point lies on where every such ray leaves it on
    /// its outer side ([`Self::shadow_except`] for each of them).
    fn disc_blockers(
        &self,
        hit: &SurfacePoint,
        cone: &LightCone,
        centre: DVec3,
        radius: f64,
    ) -> ObjectSet {
        let object = &self.world.objects[hit.object];
        // Every ray's direction is within `radius` of the centre's, so leaves on the
        // outer side where the centre is more than `radius` above the tangent plane
        // (less a relative margin for the rounding of each ray's own test).
        let above = hit.n_outward.dot(centre - hit.p);
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || above > radius + 1e-9 * above.abs());
        let within = self.world.blockers_in_cone(cone);
        if leaves_outward {
            within.without(Some(hit.object))
        } else {
            within
        }
    }

    /// The object a shadow ray from `hit` to the light of `sample` cannot meet: a shadow
    /// ray leaving a convex solid on its outer side, or leaving a plane, cannot meet the
    /// surface it starts on (a torus, a tube, a mesh or a concave CSG node can).
    #[inline]
    fn shadow_except(&self, hit: &SurfacePoint, sample: &LightSample) -> Option<usize> {
        let object = &self.world.objects[hit.object];
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || hit.n_outward.dot(sample.to_light) > 0.0);
        leaves_outward.then_some(hit.object)
    }

    /// The shadow ray from `hit` to the light of `sample`.
    #[inline]
    pub(super) fn shadow_query(&self, hit: &SurfacePoint, sample: &LightSample) -> ShadowQuery {
        let (ray, t_max) = match sample.light_position {
            Some(position) => spawn_ray_to(hit, position),
            None => (spawn_ray(hit, sample.to_light), f64::INFINITY),
        };
        ShadowQuery { ray, t_max }
    }

    /// Mean visibility of the lights that reach `hit` (in front, inside any spot cone):
    /// the fraction whose shadow ray is clear, sphere lights counting in part; 0 where no
    /// light reaches.
    pub(super) fn shadow_mask(
        &self,
        hit: &SurfacePoint,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> f64 {
        let mut reaching = 0u32;
        let mut visible = 0.0;
        for (index, light) in self.world.lights.iter().enumerate() {
            let Some(sample) = light.sample(hit.p) else {
                continue;
            };
            if hit.n.dot(sample.to_light) <= 0.0 {
                continue;
            }
            reaching += 1;
            let to = LightAt {
                depth: 0,
                node: 0,
                index,
            };
            visible += if self.primary.shadows {
                let seen = self.visibility(hit, &sample, to, rays, counts, &mut NoRecorder);
                seen.fraction
            } else {
                1.0
            };
        }
        if reaching == 0 {
            0.0
        } else {
            visible / f64::from(reaching)
        }
    }
}
