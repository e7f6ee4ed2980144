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
use smallvec::SmallVec;

use super::depth_view::DepthRange;
pub use super::object_id::object_id_colour;
use super::phong::LocalLight;
use super::ray::Ray;
pub use super::ray_counts::RayCounts;
use super::record::{LightSkip, ShadowRay, SkippedLight, unsampled_reason};
use super::spawn::{spawn_ray, spawn_ray_to};
use super::terms::{ActiveTerms, Term, TermSwitches, View};
use super::tile_cull::Candidates;
use super::world::{SurfacePoint, World};

/// One light's part in shading a point, as the inspector shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightRecord {
    /// Index of the light in the scene's light list.
    pub scene_index: usize,
    /// L_l(p): the light's strength arriving at the point, before visibility.
    pub strength: DVec3,
    /// n.l (may be negative: the light is behind the surface).
    pub n_dot_l: f64,
    /// The scene index of the object that blocked the shadow ray, if one did.
    pub blocked_by: Option<usize>,
    /// Whether a shadow ray was cast at all.
    pub shadow_ray_cast: bool,
    /// The shadow ray, when one was cast.
    pub shadow_ray: Option<ShadowRay>,
    /// The diffuse contribution added.
    pub diffuse: DVec3,
    /// The specular contribution added.
    pub specular: DVec3,
}

/// Receives the numbers behind one traced ray. Every method has an empty default, so the
/// renderer's [`NoRecorder`] costs nothing.
pub trait Recorder {
    /// Whether the recorder wants the calls at all: the shader does the extra work of
    /// accounting for skipped lights only when it does.
    const ACTIVE: bool = true;
    /// A ray at `depth` (0 = primary) hit `hit`.
    fn hit(&mut self, _depth: u32, _ray: &Ray, _hit: &SurfacePoint) {}
    /// A ray at `depth` hit nothing and returns `background`.
    fn miss(&mut self, _depth: u32, _ray: &Ray, _background: DVec3) {}
    /// The ambient term at `depth`.
    fn ambient(&mut self, _depth: u32, _colour: DVec3) {}
    /// A light at a point at `depth` that can reach it (in front of the surface or not).
    fn light(&mut self, _depth: u32, _record: &LightRecord) {}
    /// A light passed over at a point at `depth`, and why.
    fn skipped_light(&mut self, _depth: u32, _skipped: &SkippedLight) {}
    /// The mirror term at `depth`: `km * reflected` was added.
    fn reflection(&mut self, _depth: u32, _km: DVec3, _reflected: DVec3) {}
    /// The colour returned for the ray at `depth`.
    fn result(&mut self, _depth: u32, _colour: DVec3) {}
}

/// A recorder that records nothing.
pub struct NoRecorder;

impl Recorder for NoRecorder {
    const ACTIVE: bool = false;
}

/// What one ray of the mirror chain contributes: its own colour (ambient, diffuse and
/// specular at a hit, the background at a miss) and the weight of the colour its mirror
/// ray brings back (`km`; unused when no mirror ray was cast).
#[derive(Clone, Copy, Debug)]
struct Bounce {
    local: DVec3,
    km: DVec3,
}

impl Bounce {
    /// A ray that casts no mirror ray.
    fn local(colour: DVec3) -> Self {
        Self {
            local: colour,
            km: DVec3::ZERO,
        }
    }
}

/// Mirror chains up to this long stay on the stack; longer ones spill to the heap.
const INLINE_BOUNCES: usize = 8;

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
        let view = if view == View::Beauty && switches.solo == Some(Term::Shadows) {
            View::ShadowMask
        } else {
            view
        };
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

    /// The colour of a camera ray, unclamped, as the view asks for it.
    pub fn trace_primary<R: Recorder>(
        &self,
        ray: &Ray,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        self.trace_primary_among(ray, Candidates::ALL, counts, recorder)
    }

    /// As [`Self::trace_primary`] for a camera ray that can meet only what `among` names
    /// (see [`super::tile_cull`]); the same colour whenever that is so.
    pub fn trace_primary_among<R: Recorder>(
        &self,
        ray: &Ray,
        among: Candidates,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        counts.primary += 1;
        let camera_hit = || self.world.intersect_among(ray, f64::INFINITY, among.camera);
        match self.view {
            View::Beauty => self.radiance(ray, among, counts, recorder),
            View::Normal => camera_hit().map_or(DVec3::ZERO, |hit| hit.n * 0.5 + 0.5),
            View::Depth => camera_hit().map_or(DVec3::ZERO, |hit| {
                DVec3::splat(self.depth_range.map_or(1.0, |range| range.grey(hit.t)))
            }),
            View::ObjectId => camera_hit().map_or(DVec3::ZERO, |hit| {
                object_id_colour(self.world.scene_object(hit.object))
            }),
            View::ShadowMask => camera_hit().map_or(DVec3::ZERO, |hit| {
                DVec3::splat(self.shadow_mask(&hit, among, counts))
            }),
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
        among: Candidates,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) -> DVec3 {
        let (camera_bounce, mirror_ray) =
            self.shade(ray, among, 0, &self.primary, counts, recorder);
        // Most camera rays meet no mirror: no chain to keep.
        let Some(mut ray) = mirror_ray else {
            recorder.result(0, camera_bounce.local);
            return camera_bounce.local;
        };
        let mut chain: SmallVec<[Bounce; INLINE_BOUNCES]> = SmallVec::new();
        chain.push(camera_bounce);
        let everything = Candidates::ALL;
        loop {
            let depth = chain.len() as u32;
            let (bounce, mirror_ray) =
                self.shade(&ray, everything, depth, &self.secondary, counts, recorder);
            chain.push(bounce);
            match mirror_ray {
                Some(next) => ray = next,
                None => break,
            }
        }
        // Fold back: the deepest ray returns its own colour, each one before it adds km
        // times the colour of the one after.
        let mut depth = chain.len() - 1;
        let mut colour = chain[depth].local;
        recorder.result(depth as u32, colour);
        while depth > 0 {
            depth -= 1;
            let bounce = &chain[depth];
            recorder.reflection(depth as u32, bounce.km, colour);
            colour = bounce.local + bounce.km * colour;
            recorder.result(depth as u32, colour);
        }
        colour
    }

    /// One ray of the mirror chain at `depth`: what it adds itself, and the mirror ray to
    /// follow, if one is cast. Inlined into both calls in [`Self::radiance`], so the pair
    /// it returns is not passed through memory (callgrind: about 2% more instructions per
    /// camera ray when it is not).
    #[inline(always)]
    fn shade<R: Recorder>(
        &self,
        ray: &Ray,
        among: Candidates,
        depth: u32,
        terms: &ActiveTerms,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> (Bounce, Option<Ray>) {
        let Some(hit) = self.world.intersect_among(ray, f64::INFINITY, among.camera) else {
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
                let mut record = LightRecord {
                    scene_index: world.light_scene_index[index],
                    strength: sample.radiance,
                    n_dot_l,
                    blocked_by: None,
                    shadow_ray_cast: false,
                    shadow_ray: None,
                    diffuse: DVec3::ZERO,
                    specular: DVec3::ZERO,
                };
                if n_dot_l > 0.0 {
                    if terms.shadows {
                        let shadow_ray =
                            self.shadow_ray(&hit, &sample, among.shadow(index), counts);
                        record.shadow_ray_cast = true;
                        // The recorders see the scene's index of the blocker.
                        let blocked_by = shadow_ray.blocked_by.map(|i| world.scene_object(i));
                        record.blocked_by = blocked_by;
                        record.shadow_ray = Some(ShadowRay {
                            blocked_by,
                            ..shadow_ray
                        });
                    }
                    if record.blocked_by.is_none() {
                        let local = LocalLight {
                            n: hit.n,
                            to_light: sample.to_light,
                            view: view_dir,
                            strength: sample.radiance,
                        };
                        if terms.diffuse {
                            record.diffuse = local.diffuse(material.diffuse, n_dot_l);
                        }
                        if terms.specular {
                            record.specular =
                                local.specular(material.specular, material.shininess, n_dot_l);
                        }
                        colour += record.diffuse + record.specular;
                    }
                }
                recorder.light(depth, &record);
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

    /// Casts the shadow ray from `hit` to a light: the ray and the blocking object, if any.
    fn shadow_ray(
        &self,
        hit: &SurfacePoint,
        sample: &super::lights::LightSample,
        blockers: super::object_set::ObjectSet,
        counts: &mut RayCounts,
    ) -> ShadowRay {
        counts.shadow += 1;
        // Every shape is convex or flat: a shadow ray leaving a solid on its outer side,
        // or leaving a plane, cannot meet the surface it starts on.
        let leaves_outward = self.world.objects[hit.object].shape == crate::scene::Shape::Plane
            || hit.n_outward.dot(sample.to_light) > 0.0;
        let except = leaves_outward.then_some(hit.object);
        let (ray, t_max) = match sample.light_position {
            Some(position) => spawn_ray_to(hit, position),
            None => (spawn_ray(hit, sample.to_light), f64::INFINITY),
        };
        let blocked_by = self
            .world
            .occluder_except_among(&ray, t_max, except, blockers);
        ShadowRay {
            ray,
            t_max,
            blocked_by,
        }
    }

    /// Fraction of the lights that reach `hit` (in front, inside any spot cone) whose
    /// shadow ray is clear; 0 where no light reaches.
    fn shadow_mask(&self, hit: &SurfacePoint, among: Candidates, counts: &mut RayCounts) -> f64 {
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
            if !self.primary.shadows
                || self
                    .shadow_ray(hit, &sample, among.shadow(index), counts)
                    .blocked_by
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
