//! One ray's colour in the contract's order (SCENE_FORMAT.md, "Lighting model"):
//!
//! ```text
//! colour = sum over ambient lights of ka * L
//!        + sum over other lights l of vis_l * L_l(p) * (kd * max(0, n.l) + ks * max(0, r.v)^s)
//!        + km * colour(reflected ray)          while depth < max_depth
//! ```
//!
//! The mirror term is added when the chain folds back (`tracer.rs`); here a ray returns
//! its local colour, its mirror weight and the mirror ray to follow. What the re-shade
//! cache needs it gets through one call, [`RaySource::keep_light_factors`].

use glam::DVec3;

use super::lit_factors::LitFactors;
use super::mirror_chain::Bounce;
use super::phong::LocalLight;
use super::ray_source::RaySource;
use super::record::{LightRecord, LightSkip, Recorder, ShadowRay, SkippedLight, unsampled_reason};
use super::shadows::LightAt;
use super::tracer::Tracer;
use crate::scene::Material;
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::terms::ActiveTerms;
use crate::trace::world::{LightSample, SurfacePoint, spawn_ray};

/// Where a ray is shaded: its hit, the material there, its depth in the mirror chain and
/// the direction back along it.
struct ShadingPoint<'a> {
    hit: &'a SurfacePoint,
    material: &'a Material,
    depth: u32,
    view_dir: DVec3,
}

impl Tracer<'_> {
    /// One ray of the mirror chain at `depth`: what it adds itself, and the mirror ray to
    /// follow, if one is cast. Inlined into both calls in [`Tracer::radiance`], so the pair
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
        let material = &world.materials[world.material_at(&hit)];
        let at = ShadingPoint {
            hit: &hit,
            material,
            depth,
            // Camera rays are unit length and mirror reflection keeps the length.
            view_dir: -ray.dir,
        };
        let mut colour = DVec3::ZERO;

        // ambient: ka * (sum of ambient lights)
        if terms.ambient {
            let ambient = material.ambient * world.ambient;
            recorder.ambient(depth, ambient);
            colour += ambient;
        }

        // diffuse and specular, light by light, each behind its shadow ray
        let has_local = material.diffuse != DVec3::ZERO || material.specular != DVec3::ZERO;
        if (terms.diffuse || terms.specular) && has_local {
            for index in 0..world.lights.len() {
                if let Some(lit) = self.light(&at, index, terms, rays, counts, recorder) {
                    colour += lit;
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

    /// What light `index` adds at `at`: `vis * L * (kd max(0, n.l) + ks max(0, r.v)^s)`,
    /// or `None` where it adds nothing (it cannot reach the point, is behind the surface
    /// or is blocked). Offers the ray source the light's factors on the way.
    #[inline(always)]
    fn light<R: Recorder>(
        &self,
        at: &ShadingPoint,
        index: usize,
        terms: &ActiveTerms,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> Option<DVec3> {
        let world = self.world;
        let (hit, material, depth) = (at.hit, at.material, at.depth);
        let light = &world.lights[index];
        let Some(sample) = light.sample(hit.p) else {
            // A light of zero strength stays unknown: the factors of a light turned up
            // from zero were never worked out.
            if light.strength() != DVec3::ZERO {
                rays.keep_light_factors(depth, index, || LitFactors::UNREACHABLE);
            }
            if R::ACTIVE {
                let skipped = SkippedLight {
                    scene_index: world.light_scene_index[index],
                    why: unsampled_reason(light, hit.p),
                };
                recorder.skipped_light(depth, &skipped);
            }
            return None;
        };
        let n_dot_l = hit.n.dot(sample.to_light);
        rays.keep_light_factors(depth, index, || {
            self.light_factors(hit, &sample, at.view_dir, material, n_dot_l)
        });
        // Plain locals on the hot path; the record is built only for a recorder.
        let (mut cast, mut blocker) = (false, None);
        let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
        let mut lit = None;
        if n_dot_l > 0.0 {
            if terms.shadows {
                let to = LightAt { depth, index };
                blocker = self.shadow_blocker(hit, &sample, to, rays, counts);
                cast = true;
            }
            if blocker.is_none() {
                let local = LocalLight {
                    n: hit.n,
                    to_light: sample.to_light,
                    view: at.view_dir,
                    strength: sample.radiance,
                };
                if terms.diffuse {
                    diffuse = local.diffuse(material.diffuse, n_dot_l);
                }
                if terms.specular {
                    specular = local.specular(material.specular, material.shininess, n_dot_l);
                }
                lit = Some(diffuse + specular);
            }
        }
        if R::ACTIVE {
            // The recorders see the scene's index of the blocker, and the shadow ray
            // made again (spawning is deterministic).
            let blocked_by = blocker.map(|i| world.scene_object(i));
            let shadow_ray = cast.then(|| {
                let query = self.shadow_query(hit, &sample);
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
        lit
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
}
