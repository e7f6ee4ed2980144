//! The recorder that splits one camera sample into channels. It listens to the tracer's
//! own shading code (through [`Recorder`]), so every number is the one the picture
//! used; what the tracer does not report (the light a shadow took away, the terms under
//! each known bug) is computed here from the same inputs, and what a changed spot light
//! would show is traced again (the catalogue's spot bugs).
//!
//! A mirror bounce at depth d is weighted by the product of the mirror colours before it
//! (`throughput`), so a term seen in a mirror lands in the channel of the object it lies
//! on, scaled as the pixel sees it.
//!
//! For the tree nodes that might be missing, each ray is traced again in the world
//! without each tried node it may show (the nodes on the way down to the leaf it hit,
//! and nodes inside CSG objects whose solid it passes: a cut filled), and the light a
//! node's shadows take away where no other object blocks it is the shadow ray cast
//! again without it.

use glam::DVec3;

use super::context::Context;
use super::fold_watch::{FoldFlags, trace_again_watched};
use crate::compare::catalogue::{
    ClampBug, Kind, MISS, NormalBug, Part, ShadowBug, Slot, SpawnBug, SpecularBug, SpotBug,
    cone_changes, local_terms, no_falloff_change, trace_again_at,
};
use crate::trace::shapes::Primitive;
use crate::trace::{
    Branch, LightRecord, LightSample, LocalLight, Ray, Recorder, SurfacePoint, WorldLight,
    spawn_ray, spawn_ray_to,
};

/// Per-channel colour sums of one sample or one pixel: a short list, channels unique.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// `(channel, colour)` pairs.
    pub entries: Vec<(u32, DVec3)>,
}

impl Tally {
    /// Adds `value` to `channel` (nothing for a zero value).
    pub fn add(&mut self, channel: u32, value: DVec3) {
        if value == DVec3::ZERO {
            return;
        }
        match self.entries.iter_mut().find(|(c, _)| *c == channel) {
            Some((_, sum)) => *sum += value,
            None => self.entries.push((channel, value)),
        }
    }

    /// Adds every entry of `other`.
    pub fn absorb(&mut self, other: &Tally) {
        for &(channel, value) in &other.entries {
            self.add(channel, value);
        }
    }
}

/// One ray of a camera ray's tree (its index in [`SampleRecorder::chain`] is the
/// recorder's `node`).
#[derive(Clone, Copy, Debug)]
struct Bounce {
    /// This ray's mirror ray, once started.
    mirror_child: Option<usize>,
    /// Whether a transmitted ray is on the path from the camera to this ray: its own
    /// transmission is then part of that ray's, already counted.
    through_glass: bool,
    /// Whether a mirror ray is on the path from the camera to this ray: a spawning bug
    /// of a mirror before it replaces this ray's whole picture, already counted.
    through_mirror: bool,
    /// 0 for the camera ray.
    depth: u32,
    /// The leaf hit (what the channels are per).
    leaf: Option<usize>,
    /// The world object hit (a group's member, a CSG node): what its material and shape
    /// are read from.
    world_object: Option<usize>,
    hit: Option<SurfacePoint>,
    ray: Ray,
    ray_dir: DVec3,
    /// Product of the mirror and transmission colours (km, kt) of the rays before this
    /// one on its path.
    throughput: DVec3,
    /// `(km, colour of the reflected ray)` once the mirror term is known.
    mirror: Option<(DVec3, DVec3)>,
    /// The ray's colour under each clamping bug.
    clamped: [DVec3; ClampBug::ALL.len()],
}

/// The shading normal under each normal bug ([`NormalBug::normal`]) at one hit.
type BugNormals = [Option<DVec3>; NormalBug::ALL.len()];

/// Splits one sample into channels. Reused across samples: call [`SampleRecorder::start`]
/// before each.
pub struct SampleRecorder<'c, 'w> {
    ctx: &'c Context<'w>,
    chain: Vec<Bounce>,
    /// Per ray of [`Self::chain`], the normals under the normal bugs once worked out (at
    /// the hit's first light: they depend on the hit, not on the light).
    normals: Vec<Option<BugNormals>>,
    /// The channels of the current sample.
    pub tally: Tally,
    /// Per channel, squared changes of the diffuse and of the specular part (for the
    /// normal bugs: which term shows the bug more).
    pub split: Vec<[f64; 2]>,
    /// The scene object the current sample's camera ray would meet were the one it hit
    /// missing ([`MISS`]: none, or that object is not tried missing).
    pub behind: u32,
    /// What the current sample's traces again without a tree node depend on.
    pub fold: FoldFlags,
}

impl<'c, 'w> SampleRecorder<'c, 'w> {
    /// A recorder for `ctx`.
    #[must_use]
    pub fn new(ctx: &'c Context<'w>) -> Self {
        Self {
            ctx,
            chain: Vec::new(),
            normals: Vec::new(),
            tally: Tally::default(),
            split: vec![[0.0; 2]; ctx.space.count()],
            behind: MISS,
            fold: FoldFlags::default(),
        }
    }

    /// Forgets the previous sample.
    pub fn start(&mut self) {
        self.chain.clear();
        self.normals.clear();
        self.tally.entries.clear();
        self.behind = MISS;
        self.fold = FoldFlags::default();
    }

    /// The leaf the current sample's camera ray hit, if it hit something.
    #[must_use]
    pub fn primary_leaf(&self) -> Option<usize> {
        self.chain.first().and_then(|b| b.leaf)
    }

    /// Ray `node` starts, from the ray `from` names: its throughput is its parent's times
    /// the parent's km or kt.
    fn begin(&mut self, node: u32, depth: u32, from: Option<(u32, Branch)>) {
        let node = node as usize;
        self.chain.truncate(node);
        let from = from.map(|(parent, branch)| (parent as usize, branch));
        let through_glass = from.is_some_and(|(parent, branch)| {
            branch.is_transmitted() || self.chain[parent].through_glass
        });
        let through_mirror = from.is_some_and(|(parent, branch)| {
            branch == Branch::Mirror || self.chain[parent].through_mirror
        });
        let throughput = match from {
            None => DVec3::ONE,
            Some((parent, branch)) => {
                let before = &mut self.chain[parent];
                if branch == Branch::Mirror {
                    before.mirror_child = Some(node);
                }
                let weight = before.world_object.map_or(DVec3::ZERO, |o| {
                    let material = self.ctx.material(o);
                    if branch.is_transmitted() {
                        material.transmission
                    } else {
                        material.mirror
                    }
                });
                before.throughput * weight
            }
        };
        self.chain.push(Bounce {
            mirror_child: None,
            through_glass,
            through_mirror,
            depth,
            leaf: None,
            world_object: None,
            hit: None,
            ray: Ray::new(DVec3::ZERO, DVec3::ZERO),
            ray_dir: DVec3::ZERO,
            throughput,
            mirror: None,
            clamped: [DVec3::ZERO; ClampBug::ALL.len()],
        });
    }

    /// What ray `node` met.
    fn push(&mut self, node: u32, ray: &Ray, hit: Option<SurfacePoint>) {
        let bounce = &mut self.chain[node as usize];
        bounce.world_object = hit.and_then(|h| self.ctx.world.world_object_of_hit(ray, &h));
        // A group member the ray is not found on again counts as its object's first leaf.
        let nodes = self.ctx.nodes;
        bounce.leaf = hit.map(|h| match bounce.world_object {
            Some(w) => nodes.leaf(w, h.part),
            None => nodes.nodes[nodes.top(h.object)].leaves.start,
        });
        bounce.hit = hit;
        bounce.ray = *ray;
        bounce.ray_dir = ray.dir;
    }

    fn channel(&self, kind: Kind, leaf: usize) -> u32 {
        self.ctx.space.id(kind, Some(leaf))
    }

    /// Whether a light behind the surface (for raylab's normal) reaches the point: a
    /// closed solid shadows itself; a plane's other side needs a shadow ray.
    fn reaches_from_behind(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        world_object: usize,
    ) -> bool {
        let world = self.ctx.world;
        if world.objects[world_object].shape != Primitive::Plane {
            return false;
        }
        let except = Some(world_object);
        match sample.light_position {
            Some(position) => {
                let (ray, t_max) = spawn_ray_to(hit, position);
                world.occluder_except(&ray, t_max, except).is_none()
            }
            None => world
                .occluder_except(&spawn_ray(hit, sample.to_light), f64::INFINITY, except)
                .is_none(),
        }
    }

    /// A tracer whose shadow rays skip the object they leave: where the shadow ray was
    /// blocked by the hit's own object and nothing else, the light `unshadowed` (what the
    /// shadow took away) comes back.
    fn no_self_shadow(
        &mut self,
        record: &LightRecord,
        (hit, world_object, leaf): (&SurfacePoint, usize, usize),
        unshadowed: DVec3,
    ) {
        let world = self.ctx.world;
        let (Some(blocker), Some(shadow)) = (record.blocked_by, record.shadow_ray) else {
            return;
        };
        if blocker != world.scene_object(hit.object) || unshadowed == DVec3::ZERO {
            return;
        }
        if world
            .occluder_except(&shadow.ray, shadow.t_max, Some(world_object))
            .is_none()
        {
            let channel = self.channel(Kind::ShadowTest(ShadowBug::NoSelfShadow), leaf);
            self.tally.add(channel, unshadowed);
        }
    }

    /// The shadow tests of a lit point under the other shadow bugs: a shadow ray from
    /// the hit point itself (no offset: acne) and one that counts hits beyond the light.
    /// Where either is blocked, the light's terms (scaled by `t`) go. (`hit` is on world
    /// object `world_object`, of leaf `leaf`.)
    fn shadow_tests(
        &mut self,
        record: &LightRecord,
        (hit, world_object, leaf): (&SurfacePoint, Option<usize>, usize),
        sample: &LightSample,
        t: DVec3,
    ) {
        let lit = record.diffuse + record.specular;
        if !record.shadow_ray_cast || record.blocked_by.is_some() || lit == DVec3::ZERO {
            return;
        }
        let world = self.ctx.world;
        let t_max = sample
            .light_position
            .map_or(f64::INFINITY, |p| (p - hit.p).length());
        let raw = Ray::new(hit.p, sample.to_light);
        // Acne is the surface meeting its own ray: asked of it first, the whole world
        // only where it does not (the same answer, either way: any blocker blocks).
        let own =
            world_object.is_some_and(|w| world.objects[w].blocks(&raw, raw.dir.recip(), t_max));
        if own || world.occluder_except(&raw, t_max, None).is_some() {
            let channel = self.channel(Kind::ShadowTest(ShadowBug::Acne), leaf);
            self.tally.add(channel, -t * lit);
        }
        if let Some(shadow) = record.shadow_ray
            && sample.light_position.is_some()
            && world
                .occluder_except(&shadow.ray, f64::INFINITY, None)
                .is_some()
        {
            // Blocked somewhere along the whole line, and (as the shader found) not
            // before the light: beyond it.
            let channel = self.channel(Kind::ShadowTest(ShadowBug::BeyondLight), leaf);
            self.tally.add(channel, -t * lit);
        }
    }

    /// The shading normal under each normal bug at the hit of ray `node` (`None` where
    /// a bug gives raylab's or no usable normal, or the ray hit nothing shaded).
    fn bug_normals(&mut self, node: u32) -> BugNormals {
        let node = node as usize;
        if self.normals.len() <= node {
            self.normals.resize(node + 1, None);
        }
        if let Some(normals) = self.normals[node] {
            return normals;
        }
        let bounce = &self.chain[node];
        let normals = match (bounce.hit, bounce.world_object) {
            (Some(hit), Some(world_index)) => {
                let world_object = &self.ctx.world.objects[world_index];
                NormalBug::ALL.map(|bug| bug.normal(&hit, bounce.ray_dir, world_object))
            }
            _ => [None; NormalBug::ALL.len()],
        };
        self.normals[node] = Some(normals);
        normals
    }

    /// The terms under each normal and specular bug, as changes from raylab's, with the
    /// hit's `normals` under the normal bugs ([`Self::bug_normals`]).
    fn bugs(
        &mut self,
        bounce: &Bounce,
        hit: &SurfacePoint,
        record: &LightRecord,
        sample: &LightSample,
        normals: &BugNormals,
    ) {
        let (Some(object), Some(world_index)) = (bounce.leaf, bounce.world_object) else {
            return;
        };
        let material = self.ctx.material(world_index);
        let t = bounce.throughput;
        let light = LocalLight {
            n: hit.n,
            to_light: sample.to_light,
            view: -bounce.ray_dir,
            strength: record.strength,
        };
        let lit = record.n_dot_l > 0.0 && record.blocked_by.is_none();
        let mut behind: Option<bool> = None;
        for (bug, normal) in NormalBug::ALL.into_iter().zip(normals) {
            let Some(n) = *normal else {
                continue;
            };
            let visible = if record.n_dot_l > 0.0 {
                record.blocked_by.is_none()
            } else if n.dot(sample.to_light) > 0.0 {
                *behind.get_or_insert_with(|| self.reaches_from_behind(hit, sample, world_index))
            } else {
                false
            };
            let (diffuse, specular) = if visible {
                local_terms(material, &LocalLight { n, ..light })
            } else {
                (DVec3::ZERO, DVec3::ZERO)
            };
            let (d_diffuse, d_specular) = (diffuse - record.diffuse, specular - record.specular);
            let channel = self.channel(Kind::Normal(bug), object);
            self.tally.add(channel, t * (d_diffuse + d_specular));
            let split = &mut self.split[channel as usize];
            split[0] += (t * d_diffuse).length_squared();
            split[1] += (t * d_specular).length_squared();
        }
        if lit && material.specular != DVec3::ZERO {
            for bug in SpecularBug::ALL {
                let specular = bug.specular(material, &light);
                let channel = self.channel(Kind::Highlight(bug), object);
                self.tally.add(channel, t * (specular - record.specular));
            }
        }
    }
}

impl Recorder for SampleRecorder<'_, '_> {
    fn started(&mut self, node: u32, depth: u32, from: Option<(u32, Branch)>) {
        self.begin(node, depth, from);
    }

    fn hit(&mut self, node: u32, ray: &Ray, hit: &SurfacePoint) {
        self.push(node, ray, Some(*hit));
    }

    fn miss(&mut self, node: u32, ray: &Ray, background: DVec3) {
        self.push(node, ray, None);
        let t = self.chain[node as usize].throughput;
        let channel = self.ctx.space.id(Kind::Background, None);
        self.tally.add(channel, t * background);
    }

    fn ambient(&mut self, node: u32, colour: DVec3) {
        let bounce = self.chain[node as usize];
        if let Some(object) = bounce.leaf {
            let channel = self.channel(Kind::Ambient, object);
            self.tally.add(channel, bounce.throughput * colour);
        }
    }

    fn light(&mut self, node: u32, record: &LightRecord) {
        let bounce = self.chain[node as usize];
        let (Some(hit), Some(object), Some(index)) = (
            bounce.hit,
            bounce.leaf,
            self.ctx.world_light[record.scene_index],
        ) else {
            return;
        };
        let t = bounce.throughput;
        self.tally.add(
            self.channel(Kind::Diffuse(index), object),
            t * record.diffuse,
        );
        self.tally.add(
            self.channel(Kind::Specular(index), object),
            t * record.specular,
        );
        let world_light = &self.ctx.world.lights[index];
        let Some(sample) = world_light.sample(hit.p) else {
            return;
        };
        // A point light's fall-off left out is the same change as a spot's: the channel
        // is the light's, whatever its kind ("spot-no-falloff" names both).
        if matches!(
            world_light,
            WorldLight::Spot { .. } | WorldLight::Point { .. }
        ) {
            let change =
                no_falloff_change(record.diffuse + record.specular, sample.distance_squared);
            let channel = self.channel(Kind::Spot(SpotBug::NoFalloff, index), object);
            self.tally.add(channel, t * change);
        }
        // What the shadow rays took away: all of the light where a point light is
        // blocked, the hidden share of a sphere light.
        let hidden = 1.0 - record.visibility.0;
        if record.shadow_ray_cast
            && hidden > 0.0
            && let Some(world_object) = bounce.world_object
        {
            let light = LocalLight {
                n: hit.n,
                to_light: sample.to_light,
                view: -bounce.ray_dir,
                strength: record.strength,
            };
            let (diffuse, specular) = local_terms(self.ctx.material(world_object), &light);
            self.tally.add(
                self.channel(Kind::Shadow(index), object),
                t * hidden * (diffuse + specular),
            );
            self.shadow_cast(
                record,
                (&hit, world_object, object),
                &sample,
                t * (diffuse + specular),
            );
            self.no_self_shadow(
                record,
                (&hit, world_object, object),
                t * hidden * (diffuse + specular),
            );
        }
        self.shadow_tests(record, (&hit, bounce.world_object, object), &sample, t);
        let normals = self.bug_normals(node);
        self.bugs(&bounce, &hit, record, &sample, &normals);
    }

    fn reflection(&mut self, node: u32, km: DVec3, reflected: DVec3) {
        let bounce = &mut self.chain[node as usize];
        bounce.mirror = Some((km, reflected));
        let (t, object) = (bounce.throughput, bounce.leaf);
        if let Some(object) = object {
            self.tally
                .add(self.channel(Kind::Reflection, object), t * km * reflected);
            self.mirror_spawned_wrongly(node as usize, km, reflected);
        }
    }

    fn transmission(&mut self, node: u32, kt: DVec3, transmitted: DVec3, _: Branch) {
        let bounce = &self.chain[node as usize];
        let (t, object) = (bounce.throughput, bounce.leaf);
        // The first transmission on each path holds all that glass adds below it: the
        // channel is then what a picture without transmission lacks, no part twice.
        if let Some(object) = object
            && !bounce.through_glass
        {
            self.tally.add(
                self.channel(Kind::Transmission, object),
                t * kt * transmitted,
            );
        }
    }

    fn result(&mut self, node: u32, colour: DVec3) {
        let d = node as usize;
        let bounce = self.chain[d];
        // The clamp bugs take what the ray adds itself and through glass as its local
        // part: they differ in where the mirror term is clamped.
        let local = colour - bounce.mirror.map_or(DVec3::ZERO, |(km, c)| km * c);
        for (i, bug) in ClampBug::ALL.into_iter().enumerate() {
            let mirror = bounce
                .mirror
                .zip(bounce.mirror_child)
                .map(|((km, _), child)| (km, self.chain[child].clamped[i]));
            self.chain[d].clamped[i] = bug.combine(local, mirror, d == 0);
        }
        if d == 0
            && let Some(object) = bounce.leaf
        {
            let clamp = |c: DVec3| c.clamp(DVec3::ZERO, DVec3::ONE);
            for (i, bug) in ClampBug::ALL.into_iter().enumerate() {
                // Only where the written pixel changes; unclamped, as the model adds the
                // change before its own final clamp.
                let bugged = self.chain[0].clamped[i];
                if clamp(bugged) != clamp(colour) {
                    self.tally
                        .add(self.channel(Kind::Clamp(bug), object), bugged - colour);
                }
            }
            // A cone bug changes the whole picture the camera ray brings back.
            let ctx = self.ctx;
            let traced: Vec<bool> = (0..ctx.spot.len())
                .map(|k| self.spot_may_change(k))
                .collect();
            let worlds = ctx
                .spot
                .iter()
                .zip(traced)
                .filter(|(_, t)| *t)
                .map(|(w, _)| w);
            for (bug, light, change) in cone_changes(worlds, &bounce.ray, colour) {
                let channel = self.channel(Kind::Spot(bug, light), object);
                self.tally.add(channel, change);
            }
        }
        self.missing(&bounce, colour, d == 0);
    }
}

/// How many mirror bounces the wrong-side ray's tree is traced to at most.
const WRONG_SIDE_BOUNCES: u32 = 3;

impl SampleRecorder<'_, '_> {
    /// The change of the pixel were the mirror ray of ray `node` (which brought back
    /// `reflected`, weighted `km`) started on the wrong side of the surface: traced
    /// again from there, at its depth, in raylab's world. Only the first mirror on a
    /// path: below it the bug's ray replaces the whole tree, already counted.
    fn mirror_spawned_wrongly(&mut self, node: usize, km: DVec3, reflected: DVec3) {
        let bounce = self.chain[node];
        let (Some(hit), Some(leaf), Some(child)) = (bounce.hit, bounce.leaf, bounce.mirror_child)
        else {
            return;
        };
        if bounce.through_mirror {
            return;
        }
        let bug = SpawnBug::MirrorWrongSide;
        let ray = bug.ray(&hit, self.chain[child].ray.dir);
        // At most a few bounces below it: inside a closed mirror the ray would bounce to
        // `max_depth` (100 in some course scenes) for terms each a mirror's colour
        // fainter, and the bug's own tree is not raylab's below its first ray anyway.
        let world = self.ctx.world;
        let depth = (bounce.depth + 1).max(world.max_depth.saturating_sub(WRONG_SIDE_BOUNCES));
        let seen = trace_again_at(world, &ray, depth);
        if seen.is_finite() {
            let channel = self.channel(Kind::Spawn(bug), leaf);
            self.tally
                .add(channel, bounce.throughput * km * (seen - reflected));
        }
    }

    /// Whether the camera ray of the current sample may bring back another colour in
    /// spot world `k` than here. Not where that world only changes its spot light and
    /// the light's sample at every hit of the ray's tree is the same as here: the tree
    /// is the same rays (the geometry is), each shaded alike, so the trace again would
    /// give this colour bit for bit. The fall-off bug's trace adds what the light gives
    /// inside its cone too: always traced.
    pub(super) fn spot_may_change(&self, k: usize) -> bool {
        let spot = &self.ctx.spot[k];
        if !self.ctx.spot_alike[k] || spot.bug == SpotBug::NoConeNoFalloff {
            return true;
        }
        let (here, there) = (
            &self.ctx.world.lights[spot.light],
            &spot.world.lights[spot.light],
        );
        self.chain
            .iter()
            .filter_map(|b| b.hit)
            .any(|hit| here.sample(hit.p) != there.sample(hit.p))
    }

    /// What the ray of `bounce` would return without each tried node it may show (traced
    /// again in the world without it), as changes of the pixel; for the camera ray
    /// (`primary`), also the scene object it would meet without the one it hit
    /// ([`Self::behind`]).
    fn missing(&mut self, bounce: &Bounce, colour: DVec3, primary: bool) {
        let ctx = self.ctx;
        let missing = &ctx.missing;
        let chain: &[usize] = bounce.leaf.map_or(&[], |leaf| &missing.on_chain[leaf]);
        let t_hit = bounce.hit.map_or(f64::INFINITY, |h| h.t);
        let near = missing
            .in_csg
            .iter()
            .copied()
            .filter(|t| !chain.contains(t) && missing.may_change(*t, &bounce.ray, t_hit));
        for t in chain.iter().copied().chain(near) {
            let tried = &missing.tried[t];
            if primary
                && let Some(hit) = bounce.hit
                && ctx.nodes.nodes[tried.tried.node].depth() == 0
                && chain.contains(&t)
            {
                // The world without scene object o numbers the later objects one less.
                let removed = hit.object;
                self.behind = tried
                    .world
                    .intersect(&bounce.ray, f64::INFINITY)
                    .map_or(MISS, |h| {
                        let s = tried.world.scene_object(h.object);
                        (if s >= removed { s + 1 } else { s }) as u32
                    });
            }
            let seen = trace_again_watched(&tried.world, &bounce.ray, &mut self.fold);
            if !seen.is_finite() {
                continue;
            }
            let channel = match tried.tried.slot {
                Slot::Leaf(leaf) => {
                    let part = self.part_hit(bounce, leaf);
                    self.channel(Kind::Missing(part), leaf)
                }
                Slot::Inner(slot) => ctx.space.id(Kind::NodeMissing, Some(slot)),
            };
            self.tally.add(channel, bounce.throughput * (seen - colour));
        }
    }

    /// The part of leaf `leaf` the ray of `bounce` hit: a world object of its own has
    /// parts (a plane's back, a cylinder's caps); an operand of a CSG object, or a leaf
    /// the ray did not hit, is whole.
    fn part_hit(&self, bounce: &Bounce, leaf: usize) -> Part {
        match (bounce.hit, bounce.world_object) {
            (Some(hit), Some(world_object))
                if bounce.leaf == Some(leaf)
                    && self.ctx.world.objects[world_object].csg.is_none() =>
            {
                Part::at(&self.ctx.world.objects[world_object], &hit, bounce.ray_dir)
            }
            _ => Part::Whole,
        }
    }

    /// Where a node's shadow hides a light from the point `hit` (of world object
    /// `world_object`, leaf `leaf`), the light `unshadowed` it would add were that node
    /// missing: when the shadow ray, cast again in the world without it, is clear.
    fn shadow_cast(
        &mut self,
        record: &LightRecord,
        (hit, world_object, leaf): (&SurfacePoint, usize, usize),
        sample: &LightSample,
        unshadowed: DVec3,
    ) {
        let (Some(blocker), Some(shadow)) = (record.blocked_by, record.shadow_ray) else {
            return;
        };
        let ctx = self.ctx;
        // The shader's rule: a ray leaving a convex solid or a plane outward cannot meet
        // the surface it starts on.
        let object = &ctx.world.objects[world_object];
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || hit.n_outward.dot(sample.to_light) > 0.0);
        for &t in &ctx.missing.of_object[blocker] {
            let tried = &ctx.missing.tried[t];
            let node = &ctx.nodes.nodes[tried.tried.node];
            // A node shadowing itself: its own pixels are its missing picture already.
            // A cut filled only adds solid: it clears no shadow. Below the top level,
            // only a shadow ray through the node's box can clear without it.
            if node.leaves.contains(&leaf)
                || !tried.shrinks
                || (node.depth() > 0 && !ctx.missing.may_change(t, &shadow.ray, shadow.t_max))
            {
                continue;
            }
            let except = ctx
                .missing
                .index_without(t, world_object)
                .filter(|_| leaves_outward);
            if tried
                .world
                .occluder_except(&shadow.ray, shadow.t_max, except)
                .is_none()
            {
                let channel = match tried.tried.slot {
                    Slot::Leaf(leaf) => self.channel(Kind::ShadowCast, leaf),
                    Slot::Inner(slot) => ctx.space.id(Kind::NodeShadowCast, Some(slot)),
                };
                self.tally.add(channel, unshadowed);
            }
        }
    }
}
