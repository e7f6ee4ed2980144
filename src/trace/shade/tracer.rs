//! The lighting model of the contract, one ray at a time:
//!
//! ```text
//! colour = sum over ambient lights of ka * L
//!        + sum over other lights l of vis_l * L_l(p) * (kd * max(0, n.l) + ks * max(0, r.v)^s)
//!        + km * colour(reflected ray)          while depth < max_depth
//! ```
//!
//! The mirror chain is followed in a loop, so the stack stays the same size at any depth.
//!
//! Work is only done where a term can contribute: no shadow ray for a light behind the
//! surface, outside its spot cone, or for a material with no diffuse and no specular; no
//! mirror ray where km is zero. An optional [`Recorder`] sees every number the shader
//! uses, so the pixel inspector reports this very code path.

use glam::DVec3;

use super::depth_view::DepthRange;
use super::lit_factors::LitFactors;
use super::mirror_chain::Bounce;
use super::mirror_chain::Chain;
use super::mirror_chain::fold_back;
use super::object_id::object_id_colour;
use super::phong::LocalLight;
use super::ray_source::LiveRays;
use super::ray_source::RaySource;
use super::ray_source::ShadowQuery;
use super::record::LightRecord;
use super::record::LightSkip;
use super::record::Recorder;
use super::record::ShadowRay;
use super::record::SkippedLight;
use super::record::unsampled_reason;
use crate::scene::Material;
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::terms::ActiveTerms;
use crate::trace::terms::TermSwitches;
use crate::trace::terms::View;
use crate::trace::world::LightSample;
use crate::trace::world::SurfacePoint;
use crate::trace::world::World;
use crate::trace::world::spawn_ray;
use crate::trace::world::spawn_ray_to;

/// Which light a shadow ray goes to, from the hit at which depth of the mirror chain.
#[derive(Clone, Copy, Debug)]
struct LightAt {
    depth: u32,
    index: usize,
}

/// Traces rays through a world with a fixed set of switches and view.
#[derive(Clone, Copy, Debug)]
pub struct Tracer<'w> {
    world: &'w World,
    primary: ActiveTerms,
    secondary: ActiveTerms,
    view: View,
    /// The depth view's grey scale, found once per render.
    depth_range: Option<DepthRange>,
}

impl<'w> Tracer<'w> {
    /// A tracer for `world`. Solo `shadows` shows the shadow mask.
    #[must_use]
    pub fn new(world: &'w World, switches: TermSwitches, view: View) -> Self {
        let view = switches.shown_view(view);
        Self {
            world,
            primary: switches.primary(),
            secondary: switches.secondary(),
            view,
            depth_range: (view == View::Depth)
                .then(|| DepthRange::visible(world))
                .flatten(),
        }
    }

    /// The world traced.
    #[must_use]
    pub fn world(&self) -> &'w World {
        self.world
    }

    /// The terms of camera rays and of mirror rays, when the view is the lit picture.
    pub(crate) fn beauty_terms(&self) -> Option<(ActiveTerms, ActiveTerms)> {
        (self.view == View::Beauty).then_some((self.primary, self.secondary))
    }

    /// The colour of a camera ray, unclamped, as the view asks for it.
    pub fn trace_primary<R: Recorder>(
        &self,
        ray: &Ray,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        self.trace_primary_from(ray, &mut LiveRays::all(), counts, recorder)
    }

    /// As [`Self::trace_primary`], each ray answered by `rays` (the world itself, or a
    /// cache of rays traced before: the shading arithmetic is the same).
    pub fn trace_primary_from<S: RaySource, R: Recorder>(
        &self,
        ray: &Ray,
        rays: &mut S,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        counts.primary += 1;
        if self.view == View::Beauty {
            return self.radiance(ray, rays, counts, recorder);
        }
        let Some(hit) = rays.closest_hit(self.world, 0, ray) else {
            return DVec3::ZERO;
        };
        match self.view {
            View::Normal => hit.n * 0.5 + 0.5,
            View::Depth => DVec3::splat(self.depth_range.map_or(1.0, |range| range.grey(hit.t))),
            View::ObjectId => object_id_colour(self.world.scene_object(hit.object)),
            View::ShadowMask => DVec3::splat(self.shadow_mask(&hit, rays, counts)),
            View::Beauty => unreachable!("handled above"),
        }
    }

    /// The lit colour of a camera ray and its chain of mirror bounces.
    ///
    /// A loop, not a recursion, so any `max_depth` runs in constant stack: the chain is
    /// walked forward, keeping each ray's local colour and mirror weight, then folded back
    /// from the deepest ray as `colour(d) = local(d) + km(d) * colour(d + 1)`. That is the
    /// same arithmetic, and the same recorder calls in the same order, as the recursive
    /// form (a ray's `reflection` and `result` after everything deeper).
    fn radiance(
        &self,
        ray: &Ray,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) -> DVec3 {
        let (camera_bounce, mirror_ray) = self.shade(ray, 0, &self.primary, rays, counts, recorder);
        // Most camera rays meet no mirror: no chain to keep.
        let Some(mut ray) = mirror_ray else {
            recorder.result(0, camera_bounce.local);
            return camera_bounce.local;
        };
        let mut chain = Chain::new();
        chain.push(camera_bounce);
        loop {
            let depth = chain.len() as u32;
            let (bounce, mirror_ray) =
                self.shade(&ray, depth, &self.secondary, rays, counts, recorder);
            chain.push(bounce);
            match mirror_ray {
                Some(next) => ray = next,
                None => break,
            }
        }
        fold_back(&chain, recorder)
    }

    /// One ray of the mirror chain at `depth`: what it adds itself, and the mirror ray to
    /// follow, if one is cast. Inlined into both calls in [`Self::radiance`], so the pair
    /// it returns is not passed through memory (callgrind: about 2% more instructions per
    /// camera ray when it is not).
    #[inline(always)]
    pub(crate) fn shade<R: Recorder>(
        &self,
        ray: &Ray,
        depth: u32,
        terms: &ActiveTerms,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> (Bounce, Option<Ray>) {
        let Some(hit) = rays.closest_hit(self.world, depth, ray) else {
            let background = if terms.background {
                self.world.background
            } else {
                DVec3::ZERO
            };
            recorder.miss(depth, ray, background);
            return (Bounce::local(background), None);
        };
        // Recorders see the scene's object index, whatever the world left out.
        recorder.hit(
            depth,
            ray,
            &SurfacePoint {
                object: self.world.scene_object(hit.object),
                ..hit
            },
        );
        let world = self.world;
        let material = &world.materials[world.objects[hit.object].material];
        let mut colour = DVec3::ZERO;

        // ambient: ka * (sum of ambient lights)
        if terms.ambient {
            let ambient = material.ambient * world.ambient;
            recorder.ambient(depth, ambient);
            colour += ambient;
        }

        // diffuse and specular, light by light
        let has_local = material.diffuse != DVec3::ZERO || material.specular != DVec3::ZERO;
        if (terms.diffuse || terms.specular) && has_local {
            // Camera rays are unit length and mirror reflection keeps the length.
            let view_dir = -ray.dir;
            for (index, light) in world.lights.iter().enumerate() {
                let Some(sample) = light.sample(hit.p) else {
                    // A light of zero strength stays unknown: the factors of a light
                    // turned up from zero were never worked out.
                    if light.strength() != DVec3::ZERO && rays.wants_light_factors(depth, index) {
                        rays.light_factors(depth, index, LitFactors::UNREACHABLE);
                    }
                    if R::ACTIVE {
                        let skipped = SkippedLight {
                            scene_index: world.light_scene_index[index],
                            why: unsampled_reason(light, hit.p),
                        };
                        recorder.skipped_light(depth, &skipped);
                    }
                    continue;
                };
                let n_dot_l = hit.n.dot(sample.to_light);
                if rays.wants_light_factors(depth, index) {
                    let factors = self.light_factors(&hit, &sample, view_dir, material, n_dot_l);
                    rays.light_factors(depth, index, factors);
                }
                // Plain locals on the hot path; the record is built only for a recorder.
                let (mut cast, mut blocker) = (false, None);
                let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
                if n_dot_l > 0.0 {
                    if terms.shadows {
                        let to = LightAt { depth, index };
                        blocker = self.shadow_blocker(&hit, &sample, to, rays, counts);
                        cast = true;
                    }
                    if blocker.is_none() {
                        let local = LocalLight {
                            n: hit.n,
                            to_light: sample.to_light,
                            view: view_dir,
                            strength: sample.radiance,
                        };
                        if terms.diffuse {
                            diffuse = local.diffuse(material.diffuse, n_dot_l);
                        }
                        if terms.specular {
                            specular =
                                local.specular(material.specular, material.shininess, n_dot_l);
                        }
                        colour += diffuse + specular;
                    }
                }
                if R::ACTIVE {
                    // The recorders see the scene's index of the blocker, and the shadow
                    // ray made again (spawning is deterministic).
                    let blocked_by = blocker.map(|i| world.scene_object(i));
                    let shadow_ray = cast.then(|| {
                        let query = self.shadow_query(&hit, &sample);
                        ShadowRay {
                            ray: query.ray,
                            t_max: query.t_max,
                            blocked_by,
                        }
                    });
                    let record = LightRecord {
                        scene_index: world.light_scene_index[index],
                        strength: sample.radiance,
                        n_dot_l,
                        blocked_by,
                        shadow_ray_cast: cast,
                        shadow_ray,
                        diffuse,
                        specular,
                    };
                    recorder.light(depth, &record);
                }
            }
        } else if R::ACTIVE {
            let why = if has_local {
                LightSkip::TermsOff
            } else {
                LightSkip::NoDiffuseOrSpecular
            };
            for &scene_index in &world.light_scene_index {
                recorder.skipped_light(depth, &SkippedLight { scene_index, why });
            }
        }

        // mirror: km * colour(reflected ray), added when the chain folds back
        if terms.reflection && depth < world.max_depth && material.mirror != DVec3::ZERO {
            let d = ray.dir;
            let reflected_dir = d - 2.0 * d.dot(hit.n) * hit.n;
            counts.reflection += 1;
            let bounce = Bounce {
                local: colour,
                km: material.mirror,
            };
            return (bounce, Some(spawn_ray(&hit, reflected_dir)));
        }
        (Bounce::local(colour), None)
    }

    /// What the light of `sample` gives `hit`, kept for a quick re-shade: the lobe is
    /// the one [`LocalLight::specular`] works out, blocked or not, switched on or not.
    fn light_factors(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        view: DVec3,
        material: &Material,
        n_dot_l: f64,
    ) -> LitFactors {
        let lobe = (n_dot_l > 0.0).then(|| {
            let local = LocalLight {
                n: hit.n,
                to_light: sample.to_light,
                view,
                strength: sample.radiance,
            };
            local.specular_lobe(material.shininess, n_dot_l)
        });
        LitFactors::reached(sample, n_dot_l, lobe.flatten())
    }

    /// The object blocking the shadow ray from `hit` (at `to.depth`) to light
    /// `to.index`, if any. The ray itself is made only if `rays` has to cast it.
    #[inline]
    fn shadow_blocker(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        to: LightAt,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> Option<usize> {
        counts.shadow += 1;
        let except = self.shadow_except(hit, sample);
        rays.occluder(self.world, to.depth, to.index, except, || {
            self.shadow_query(hit, sample)
        })
    }

    /// The object a shadow ray from `hit` to the light of `sample` cannot meet: a shadow
    /// ray leaving a convex solid on its outer side, or leaving a plane, cannot meet the
    /// surface it starts on (a mesh's may: it is tested like any other).
    #[inline]
    fn shadow_except(&self, hit: &SurfacePoint, sample: &LightSample) -> Option<usize> {
        let shape = self.world.objects[hit.object].shape;
        let leaves_outward = shape == crate::trace::shapes::Primitive::Plane
            || (shape.is_convex() && hit.n_outward.dot(sample.to_light) > 0.0);
        leaves_outward.then_some(hit.object)
    }

    /// The shadow ray from `hit` to the light of `sample`.
    #[inline]
    fn shadow_query(&self, hit: &SurfacePoint, sample: &LightSample) -> ShadowQuery {
        let (ray, t_max) = match sample.light_position {
            Some(position) => spawn_ray_to(hit, position),
            None => (spawn_ray(hit, sample.to_light), f64::INFINITY),
        };
        ShadowQuery { ray, t_max }
    }

    /// Fraction of the lights that reach `hit` (in front, inside any spot cone) whose
    /// shadow ray is clear; 0 where no light reaches.
    fn shadow_mask(
        &self,
        hit: &SurfacePoint,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> f64 {
        let mut reaching = 0u32;
        let mut visible = 0u32;
        for (index, light) in self.world.lights.iter().enumerate() {
            let Some(sample) = light.sample(hit.p) else {
                continue;
            };
            if hit.n.dot(sample.to_light) <= 0.0 {
                continue;
            }
            reaching += 1;
            let to = LightAt { depth: 0, index };
            if !self.primary.shadows
                || self
                    .shadow_blocker(hit, &sample, to, rays, counts)
                    .is_none()
            {
                visible += 1;
            }
        }
        if reaching == 0 {
            0.0
        } else {
            f64::from(visible) / f64::from(reaching)
        }
    }
}
