//! The lighting model of the contract, one ray at a time, in its order: ambient, each
//! light (with its shadow ray), the mirror and transmission terms. The shader asks a
//! [`RaySource`] for the rays it needs and tells it what each light gave each hit; the
//! recorder sees every number.

mod bounce_tree;
mod branch;
mod depth_view;
mod lighting;
mod lit_factors;
mod object_id;
mod phong;
mod ray_source;
mod record;
mod refraction;
mod shadows;
mod subtree_bound;
mod tracer;

pub use bounce_tree::RayAt;
pub(crate) use bounce_tree::{Bounce, BroughtBack, fold_within};
pub use branch::Branch;
pub use lit_factors::LitFactors;
pub use object_id::object_id_colour;
pub use phong::{
    LocalLight, diffuse_term, phong_power, seen_terms, specular_term, visible_fraction,
};
#[cfg(test)]
pub(crate) use ray_source::ShadowQuery;
pub use ray_source::{LiveRays, MakeRay, RaySource, ShadowRequest};
pub use record::{
    LightOutcome, LightRecord, LightSkip, NoRecorder, Recorder, ShadowRay, SkippedLight,
};
pub use subtree_bound::SubtreeBound;
pub use tracer::Tracer;
