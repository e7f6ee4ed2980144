//! One ray's colour in the contract's order (SCENE_FORMAT.md, "Lighting model"):
//!
//! ```text
//! colour = sum over ambient lights of ka * L
//!        + sum over other lights l of vis_l * L_l(p) * (kd * max(0, n.l) + ks * max(0, r.v)^s)
//!        + km * colour(reflected ray)          while depth < max_depth
//!        + kt * colour(transmitted ray)        while depth < max_depth
//! ```
//!
//! The mirror and transmission terms are added when the tree folds back (`tracer.rs`);
//! here a ray returns its local colour, its weights and the rays to follow. What the re-shade
//! cache needs it gets through one call, [`RaySource::keep_light_factors`].

use glam::DVec3;

use super::bounce_tree::{Bounce, RayAt, Spawned};
use super::branch::Branch;
use super::lit_factors::LitFactors;
use super::phong::{LocalLight, seen_terms};
use super::ray_source::RaySource;
use super::record::{LightRecord, LightSkip, Recorder, ShadowRay, SkippedLight, unsampled_reason};
use super::refraction::{Transmitted, media, mirror_dir, refract};
use super::shadows::{LightAt, Visibility};
use super::tracer::Tracer;
use crate::scene::Material;
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shapes::Primitive;
use crate::trace::terms::ActiveTerms;
use crate::trace::world::{LightSample, SurfacePoint, spawn_ray};

/// Where a ray is shaded: its hit, the material there, which ray it is and the direction
/// back along it.
struct ShadingPoint<'a> {
    hit: &'a SurfacePoint,
    material: &'a Material,
    depth: u32,
    node: u32,
    view_dir: DVec3,
}

impl Tracer<'_> {
    /// One ray of a camera ray's tree: what it adds itself, and the mirror and
    /// transmitted rays to follow, where they are cast. Inlined into both calls in
    /// [`Tracer::radiance`], so the pair it returns is not passed through memory
    /// (callgrind: about 2% more instructions per camera ray when it is not).
    #[inline(always)]
    pub(crate) fn shade<R: Recorder>(
        &self,
        ray: &Ray,
        at: RayAt,
        terms: &ActiveTerms,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> (Bounce, Spawned) {
        let RayAt { depth, node, .. } = at;
        let Some(hit) = rays.closest_hit(self.world, at, ray) else {
            let background = if terms.background {
                self.world.background
            } else {
                DVec3::ZERO
            };
            recorder.miss(node, ray, background);
            return (Bounce::local(background), Spawned::NONE);
        };
        // Recorders see the scene's object index, whatever the world left out.
        recorder.hit(
            node,
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
            node,
            // Camera rays are unit length and mirror reflection keeps the length.
            view_dir: -ray.dir,
        };
        let mut colour = DVec3::ZERO;

        // ambient: ka * (sum of ambient lights)
        if terms.ambient {
            let ambient = material.ambient * world.ambient;
            recorder.ambient(node, ambient);
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
                recorder.skipped_light(node, &SkippedLight { scene_index, why });
            }
        }

        // mirror and transmission: km * colour(reflected ray) + kt * colour(transmitted
        // ray), added when the tree folds back
        let deeper = depth < world.max_depth;
        let mut spawned = Spawned::NONE;
        if terms.reflection && deeper && material.mirror != DVec3::ZERO {
            counts.reflection += 1;
            spawned.mirror = Some(spawn_ray(&hit, mirror_dir(ray.dir, hit.n)));
        }
        if terms.transmission && deeper && material.transmission != DVec3::ZERO {
            counts.transmission += 1;
            spawned.transmitted = Some(self.transmitted_ray(ray, &hit, material));
        }
        let bounce = Bounce {
            local: colour,
            km: material.mirror,
            kt: material.transmission,
        };
        (bounce, spawned)
    }

    /// The transmitted ray from `hit`: bent by Snell's law between air and the
    /// material's `ior` (the ratio flipped for a ray leaving the object), along the mirror
    /// direction where Snell has no solution. A plane has no inside: its transmitted ray
    /// goes straight on. The origin is offset to the side the ray leaves on.
    #[inline]
    fn transmitted_ray(&self, ray: &Ray, hit: &SurfacePoint, material: &Material) -> (Ray, Branch) {
        let transmitted = if self.world.objects[hit.object].shape == Primitive::Plane {
            Transmitted::Refracted(ray.dir)
        } else {
            let (from, to) = media(ray.dir, hit.n_outward, material.ior);
            refract(ray.dir, hit.n, from, to)
        };
        let branch = match transmitted {
            Transmitted::Refracted(_) => Branch::Refracted,
            Transmitted::InternallyReflected(_) => Branch::InternallyReflected,
        };
        (spawn_ray(hit, transmitted.dir()), branch)
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
        let (hit, material, depth, node) = (at.hit, at.material, at.depth, at.node);
        let light = &world.lights[index];
        let Some(sample) = light.sample(hit.p) else {
            // A light of zero strength stays unknown: the factors of a light turned up
            // from zero were never worked out.
            if light.strength() != DVec3::ZERO {
                rays.keep_light_factors(node, index, || LitFactors::UNREACHABLE);
            }
            if R::ACTIVE {
                let skipped = SkippedLight {
                    scene_index: world.light_scene_index[index],
                    why: unsampled_reason(light, hit.p),
                };
                recorder.skipped_light(node, &skipped);
            }
            return None;
        };
        let n_dot_l = hit.n.dot(sample.to_light);
        rays.keep_light_factors(node, index, || {
            self.light_factors(hit, &sample, at.view_dir, material, n_dot_l)
        });
        // Plain locals on the hot path; the record is built only for a recorder.
        let mut cast = false;
        let mut seen = Visibility {
            fraction: 1.0,
            blocker: None,
            rays: 0,
        };
        let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
        let mut lit = None;
        if n_dot_l > 0.0 {
            if terms.shadows {
                let to = LightAt { depth, node, index };
                seen = self.visibility(hit, &sample, to, rays, counts, recorder);
                cast = true;
            }
            if seen.fraction > 0.0 {
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
                (diffuse, specular) = seen_terms(seen.fraction, diffuse, specular);
                lit = Some(diffuse + specular);
            }
        }
        if R::ACTIVE {
            // The recorders see the scene's index of the blocker, and the shadow ray
            // made again (spawning is deterministic).
            let blocked_by = seen.blocker.map(|i| world.scene_object(i));
            let point_light = world.light_spheres[index].is_none();
            let shadow_ray = (cast && point_light).then(|| {
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
                visibility: (seen.fraction, seen.rays),
                diffuse,
                specular,
            };
            recorder.light(node, &record);
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
