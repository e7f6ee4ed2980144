//! A camera ray's tree of secondary rays: at each hit a mirror ray (weight km) and a
//! transmitted ray (weight kt) may start. Each ray's own colour and the weights of what
//! its rays bring back are kept, then folded from the deepest ray as
//! `colour = local + km * reflected + kt * transmitted` (or the course's mirror blend,
//! and each ray clamped, as the scene's conventions say). The shader, the tile pass and
//! the quick re-shade ([`crate::trace::reshade::quick_shade`]) fold through the one step
//! [`Bounce::returns`], so their sums agree bit for bit.

use glam::DVec3;
use smallvec::SmallVec;

use super::branch::Branch;
use super::record::Recorder;
use crate::scene::{ClampConvention, Conventions, MirrorConvention};
use crate::trace::ray::Ray;

/// What one ray contributes: its own colour (ambient, diffuse and specular at a hit, the
/// background at a miss) and the weights of the colours its mirror and transmitted rays
/// bring back (`km`, `kt`; unused where that ray was not cast).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bounce {
    pub local: DVec3,
    pub km: DVec3,
    pub kt: DVec3,
}

/// The colours a ray's own rays brought back (`None` where one was not cast).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct BroughtBack {
    pub reflected: Option<DVec3>,
    pub transmitted: Option<DVec3>,
}

impl BroughtBack {
    /// Only a mirror ray's colour (or nothing).
    #[must_use]
    pub fn reflected(reflected: Option<DVec3>) -> Self {
        Self {
            reflected,
            transmitted: None,
        }
    }
}

impl Bounce {
    /// The colour this ray returns, given what its rays brought back: the one step of
    /// every fold, the shader's, the tile pass's and the quick re-shade's.
    #[inline]
    pub fn returns(&self, brought_back: BroughtBack, conventions: &Conventions) -> DVec3 {
        ray_colour(self.unclamped(brought_back, conventions), conventions)
    }

    /// This ray's colour before any clamp. `Add`: local + km * reflected; `Blend`:
    /// (1 - km) * local + km * reflected, per channel (only where a mirror ray was cast).
    /// Then + kt * transmitted in either, as the course framework adds it (COSC342_FORMAT.md:
    /// local is not reduced).
    #[inline]
    fn unclamped(&self, brought_back: BroughtBack, conventions: &Conventions) -> DVec3 {
        let mirrored = match brought_back.reflected {
            None => self.local,
            Some(reflected) => match conventions.mirror {
                MirrorConvention::Add => self.local + self.km * reflected,
                MirrorConvention::Blend => {
                    (DVec3::ONE - self.km) * self.local + self.km * reflected
                }
            },
        };
        match brought_back.transmitted {
            None => mirrored,
            Some(transmitted) => mirrored + self.kt * transmitted,
        }
    }

    /// A ray that casts no mirror or transmitted ray.
    pub fn local(colour: DVec3) -> Self {
        Self {
            local: colour,
            km: DVec3::ZERO,
            kt: DVec3::ZERO,
        }
    }
}

/// The colour a ray returns, as the conventions say: clamped to [0, 1] with `EachRay`
/// (the course skeleton's `clip()`), as it is with `Pixel` (only the pixel is clamped,
/// when it is written).
#[inline]
fn ray_colour(colour: DVec3, conventions: &Conventions) -> DVec3 {
    match conventions.clamp {
        ClampConvention::Pixel => colour,
        ClampConvention::EachRay => colour.clamp(DVec3::ZERO, DVec3::ONE),
    }
}

/// Which ray of a camera ray's tree is shaded: its depth (0 = the camera ray; what
/// `max_depth` and the tile culling go by), its index in the tree (breadth first: what
/// recorders go by) and its parent's index and which of the parent's rays it is (what
/// the hit cache finds the ray's entry by: a tree's shape changes with the materials,
/// its indices with it, but a ray's parent and branch do not).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RayAt {
    /// 0 for the camera ray, 1 for the rays its hit starts, and so on.
    pub depth: u32,
    /// The ray's index in its tree, in the order the rays are shaded.
    pub node: u32,
    /// The parent's index and which of its rays this is; `None` for the camera ray.
    pub from: Option<(u32, Branch)>,
}

impl RayAt {
    /// The camera ray.
    pub const CAMERA: Self = Self {
        depth: 0,
        node: 0,
        from: None,
    };
}

/// The rays a shaded ray starts: a mirror ray and a transmitted one, each if cast.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Spawned {
    pub mirror: Option<Ray>,
    pub transmitted: Option<(Ray, Branch)>,
}

impl Spawned {
    /// Neither.
    pub const NONE: Self = Self {
        mirror: None,
        transmitted: None,
    };
}

/// One ray of a camera ray's tree, as the tracer walks it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node {
    pub ray: Ray,
    pub depth: u32,
    /// The parent's index in the tree and which of its rays this is; `None` at the root.
    pub from: Option<(u32, Branch)>,
    pub bounce: Bounce,
    pub brought_back: BroughtBack,
}

impl Node {
    /// A ray not shaded yet.
    pub fn new(ray: Ray, depth: u32, from: Option<(u32, Branch)>) -> Self {
        Self {
            ray,
            depth,
            from,
            bounce: Bounce::local(DVec3::ZERO),
            brought_back: BroughtBack::default(),
        }
    }
}

/// Trees up to this many rays stay on the stack; larger ones spill to the heap.
const INLINE_RAYS: usize = 8;

/// The rays of one camera ray, in the order they were shaded (breadth first, so each
/// ray's parent comes before it).
pub(crate) type Tree = SmallVec<[Node; INLINE_RAYS]>;

/// The colour of a tree of at least one shaded ray, folded from the last ray shaded to
/// the first: each ray's colour goes to its parent's slot. The recorder sees each ray's
/// `reflection` or `transmission` and `result` after everything deeper, as a recursion
/// would; on a mirror chain the order is the recursion's exactly.
#[inline]
pub(crate) fn fold_back(
    tree: &mut [Node],
    conventions: &Conventions,
    recorder: &mut impl Recorder,
) -> DVec3 {
    for index in (1..tree.len()).rev() {
        let node = tree[index];
        let colour = returned(
            index as u32,
            &node.bounce,
            node.brought_back,
            conventions,
            recorder,
        );
        let (parent, branch) = node.from.expect("every ray but the root has a parent");
        let slot = &mut tree[parent as usize];
        if branch.is_transmitted() {
            recorder.transmission(parent, slot.bounce.kt, colour, branch);
            slot.brought_back.transmitted = Some(colour);
        } else {
            recorder.reflection(parent, slot.bounce.km, colour);
            slot.brought_back.reflected = Some(colour);
        }
    }
    let root = &tree[0];
    returned(0, &root.bounce, root.brought_back, conventions, recorder)
}

/// The colour of a shaded tree (from [`super::tracer::Tracer::ray_tree`]) as a trace
/// under `conventions` with `max_depth` would fold it: the rays deeper than
/// `max_depth` were never cast there, so a ray at that depth keeps only its own colour.
/// The same steps as [`fold_back`], in the same order, so the same bits.
pub(crate) fn fold_within(tree: &[Node], conventions: &Conventions, max_depth: u32) -> DVec3 {
    let mut brought_back: SmallVec<[BroughtBack; INLINE_RAYS]> =
        SmallVec::from_elem(BroughtBack::default(), tree.len());
    for index in (1..tree.len()).rev() {
        let node = &tree[index];
        if node.depth > max_depth {
            continue;
        }
        let colour = node.bounce.returns(brought_back[index], conventions);
        let (parent, branch) = node.from.expect("every ray but the root has a parent");
        let slot = &mut brought_back[parent as usize];
        if branch.is_transmitted() {
            slot.transmitted = Some(colour);
        } else {
            slot.reflected = Some(colour);
        }
    }
    tree[0].bounce.returns(brought_back[0], conventions)
}

/// What the ray `node` returns ([`Bounce::returns`]); the recorder sees its colour, and
/// where the each-ray clamp changed it, the colour before.
#[inline]
pub(crate) fn returned<R: Recorder>(
    node: u32,
    bounce: &Bounce,
    brought_back: BroughtBack,
    conventions: &Conventions,
    recorder: &mut R,
) -> DVec3 {
    let colour = bounce.unclamped(brought_back, conventions);
    let clamped = ray_colour(colour, conventions);
    if R::ACTIVE && clamped != colour {
        recorder.clamped(node, colour);
    }
    recorder.result(node, clamped);
    clamped
}
