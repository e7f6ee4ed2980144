//! The lighting model of the contract, one ray at a time:
//!
//! ```text
//! colour = sum over ambient lights of ka * L
//!        + sum over other lights l of vis_l * L_l(p) * (kd * max(0, n.l) + ks * max(0, r.v)^s)
//!        + km * colour(reflected ray)          while depth < max_depth
//!        + kt * colour(transmitted ray)        while depth < max_depth
//! ```
//!
//! This file holds the tracer and the walk of a camera ray's tree: the camera ray, then
//! each mirror and transmitted ray, followed in a loop over a list (not a recursion) so
//! the stack stays the same size at any depth. One ray's terms are in `lighting.rs`, its
//! shadow rays in `shadows.rs`, the fold in `bounce_tree.rs`.
//!
//! Work is only done where a term can contribute: no shadow ray for a light behind the
//! surface, outside its spot cone, or for a material with no diffuse and no specular; no
//! mirror ray where km is zero, no transmitted ray where kt is. An optional [`Recorder`] sees every number the shader
//! uses, so the pixel inspector reports this very code path.

use glam::DVec3;

#[cfg(doc)]
use super::bounce_tree::fold_within;
use super::bounce_tree::{BroughtBack, Node, RayAt, Spawned, Tree, fold_back, returned};
use super::branch::Branch;
use super::depth_view::DepthRange;
use super::object_id::object_id_colour;
use super::ray_source::{LiveRays, RaySource};
use super::record::{NoRecorder, Recorder};
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::terms::{ActiveTerms, TermSwitches, View};
use crate::trace::world::World;

/// Traces rays through a world with a fixed set of switches and view.
#[derive(Clone, Copy, Debug)]
pub struct Tracer<'w> {
    pub(super) world: &'w World,
    /// The terms of camera rays.
    pub(super) primary: ActiveTerms,
    /// The terms of mirror rays (the background shows only to camera rays in a solo).
    pub(super) secondary: ActiveTerms,
    pub(super) view: View,
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
        let Some(hit) = rays.closest_hit(self.world, RayAt::CAMERA, ray) else {
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

    /// The lit colour of a camera ray and its tree of mirror and transmitted rays.
    ///
    /// A loop, not a recursion, so any `max_depth` runs in constant stack: the tree is
    /// walked breadth first, keeping each ray's local colour and weights, then folded back
    /// from the last ray shaded as `colour = local + km * reflected + kt * transmitted`
    /// (as the scene's conventions combine and clamp). That is the same arithmetic, and
    /// on a mirror chain the same recorder calls in the same order, as the recursive form
    /// (a ray's `reflection` and `result` after everything deeper).
    fn radiance(
        &self,
        ray: &Ray,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) -> DVec3 {
        self.radiance_from(ray, 0, &self.primary, rays, counts, recorder)
    }

    /// The colour a mirror or transmitted ray `ray` at `depth` brings back, with its
    /// tree below (folded as the conventions say, clamped with `EachRay`): what a ray
    /// started elsewhere than raylab starts it returns (the diff's model of a mirror
    /// ray spawned on the wrong side).
    pub fn trace_secondary(&self, ray: &Ray, depth: u32, counts: &mut RayCounts) -> DVec3 {
        let rays = &mut LiveRays::all();
        self.radiance_from(ray, depth, &self.secondary, rays, counts, &mut NoRecorder)
    }

    /// [`Self::radiance`] of a ray at `depth` (0: the camera ray) shaded with `terms`,
    /// the first ray of its own tree.
    #[inline(always)]
    fn radiance_from(
        &self,
        ray: &Ray,
        depth: u32,
        terms: &ActiveTerms,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) -> DVec3 {
        recorder.started(0, depth, None);
        let at = RayAt {
            depth,
            ..RayAt::CAMERA
        };
        let (camera_bounce, spawned) = self.shade(ray, at, terms, rays, counts, recorder);
        // Most camera rays meet no mirror and no glass: no tree to keep.
        let conventions = &self.world.conventions;
        if spawned.mirror.is_none() && spawned.transmitted.is_none() {
            let nothing = BroughtBack::default();
            return returned(0, &camera_bounce, nothing, conventions, recorder);
        }
        let mut tree = Tree::new();
        tree.push(Node {
            bounce: camera_bounce,
            ..Node::new(*ray, depth, None)
        });
        push_children(&mut tree, 0, spawned);
        self.grow(&mut tree, rays, counts, recorder);
        fold_back(&mut tree, conventions, recorder)
    }

    /// Shades the rays of `tree` after its first, breadth first, adding the rays each
    /// starts: the walk of [`Self::radiance`] below the camera ray.
    #[inline(always)]
    fn grow(
        &self,
        tree: &mut Tree,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) {
        let mut index = 1;
        while index < tree.len() {
            let node = tree[index];
            let at = RayAt {
                depth: node.depth,
                node: index as u32,
                from: node.from,
            };
            recorder.started(at.node, at.depth, node.from);
            let (bounce, spawned) =
                self.shade(&node.ray, at, &self.secondary, rays, counts, recorder);
            tree[index].bounce = bounce;
            push_children(tree, index, spawned);
            index += 1;
        }
    }

    /// The whole tree of a camera ray (in the lit view), shaded but not folded: what
    /// [`fold_within`] turns into its colour under any conventions and any depth limit
    /// up to the world's, each time as a trace with those would give it, bit for bit.
    pub(crate) fn ray_tree(&self, ray: &Ray, counts: &mut RayCounts) -> Tree {
        counts.primary += 1;
        let rays = &mut LiveRays::all();
        let (bounce, spawned) = self.shade(
            ray,
            RayAt::CAMERA,
            &self.primary,
            rays,
            counts,
            &mut NoRecorder,
        );
        let mut tree = Tree::new();
        tree.push(Node {
            bounce,
            ..Node::new(*ray, 0, None)
        });
        push_children(&mut tree, 0, spawned);
        self.grow(&mut tree, rays, counts, &mut NoRecorder);
        tree
    }
}

/// Queues the rays that ray `parent` of `tree` started, one level deeper.
#[inline]
fn push_children(tree: &mut Tree, parent: usize, spawned: Spawned) {
    let depth = tree[parent].depth + 1;
    let parent = parent as u32;
    if let Some(mirror) = spawned.mirror {
        tree.push(Node::new(mirror, depth, Some((parent, Branch::Mirror))));
    }
    if let Some((transmitted, branch)) = spawned.transmitted {
        tree.push(Node::new(transmitted, depth, Some((parent, branch))));
    }
}
