//! "Trace this ray again": a camera ray traced in one of the changed worlds (without a
//! tree node, with a spot light's cone bug) as raylab's picture of it would show, for
//! the channels of what that change would do to a pixel; or a secondary ray a bug starts
//! elsewhere, traced again from its depth.

use glam::DVec3;

use crate::trace::{NoRecorder, Ray, RayCounts, TermSwitches, Tracer, View, World};

/// The colour a camera ray `ray` brings back in `world` (one of the changed worlds), as
/// raylab's picture of it would show.
#[must_use]
pub fn trace_again(world: &World, ray: &Ray) -> DVec3 {
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    tracer.trace_primary(ray, &mut RayCounts::default(), &mut NoRecorder)
}

/// The colour a secondary ray `ray` at `depth` brings back in `world` (with its tree
/// below, as raylab's picture folds it): a mirror ray a bug starts elsewhere.
#[must_use]
pub fn trace_again_at(world: &World, ray: &Ray, depth: u32) -> DVec3 {
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    tracer.trace_secondary(ray, depth, &mut RayCounts::default())
}
