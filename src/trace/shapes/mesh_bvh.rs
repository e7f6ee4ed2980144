//! The bounding volume hierarchy over a mesh's triangles: a binned SAH build (Wald,
//! "On fast construction of SAH-based bounding volume hierarchies", 2007), in parallel
//! over subtrees, into a flat array of 32-byte nodes in depth-first order.
//!
//! Boxes are f32 and computed from the f32 vertices with min/max only, so they hold their
//! triangles exactly; traversal tests them in f64.

use glam::{DVec3, Vec3};

/// One node: a box and either a leaf's triangle range or an inner node's right child
/// (its left child is the next node).
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub(crate) struct Node {
    min: [f32; 3],
    /// Triangles in a leaf; 0 for an inner node.
    count: u32,
    max: [f32; 3],
    /// A leaf's first triangle, or an inner node's right child.
    index: u32,
}

impl Node {
    /// The node's box in f64 (exactly its f32 box).
    #[inline(always)]
    pub(crate) fn bounds(&self) -> (DVec3, DVec3) {
        (
            Vec3::from_array(self.min).as_dvec3(),
            Vec3::from_array(self.max).as_dvec3(),
        )
    }

    /// For a leaf, its triangle range in build order.
    #[inline(always)]
    pub(crate) fn leaf(&self) -> Option<std::ops::Range<usize>> {
        (self.count > 0).then(|| self.index as usize..self.index as usize + self.count as usize)
    }

    /// For an inner node at `at`, its children.
    #[inline(always)]
    pub(crate) fn children(&self, at: usize) -> (usize, usize) {
        (at + 1, self.index as usize)
    }
}

/// Leaves hold at most this many triangles.
const MAX_LEAF: usize = 8;
/// Centroid bins per axis. 8 rather than 16: on the 1M-triangle knot the build takes
/// about 0.1 s less CPU and 16-sample renders trace as fast (docs/BENCHMARKS.md).
const BINS: usize = 8;
/// Cost of visiting a node, relative to testing one triangle.
const TRAVERSAL_COST: f32 = 1.0;
/// Subtrees with more triangles than this are built on separate threads.
const PARALLEL_ABOVE: usize = 16 * 1024;

#[derive(Clone, Copy)]
struct Box3 {
    min: Vec3,
    max: Vec3,
}

impl Box3 {
    const EMPTY: Box3 = Box3 {
        min: Vec3::INFINITY,
        max: Vec3::NEG_INFINITY,
    };
    fn grow(&mut self, other: &Box3) {
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }
    fn area(&self) -> f32 {
        let e = (self.max - self.min).max(Vec3::ZERO);
        e.x * e.y + e.y * e.z + e.z * e.x
    }
}

/// What the build needs of each triangle.
struct Prim {
    bounds: Box3,
    centre: Vec3,
}

/// Builds the hierarchy. Returns the nodes and the build order: `order[i]` is the
/// triangle (index into `triangles`) stored at position `i`.
pub(crate) fn build(positions: &[[f32; 3]], triangles: &[[u32; 3]]) -> (Vec<Node>, Vec<u32>) {
    use rayon::prelude::*;
    let prims: Vec<Prim> = triangles
        .par_iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| Vec3::from_array(positions[i as usize]));
            let bounds = Box3 {
                min: a.min(b).min(c),
                max: a.max(b).max(c),
            };
            Prim {
                bounds,
                centre: (bounds.min + bounds.max) * 0.5,
            }
        })
        .collect();
    let mut order: Vec<u32> =
        (0..u32::try_from(triangles.len()).expect("under 4G triangles")).collect();
    let nodes = if order.is_empty() {
        vec![Node {
            min: [f32::INFINITY; 3],
            count: 0,
            max: [f32::NEG_INFINITY; 3],
            index: 0,
        }]
    } else {
        subtree(&prims, &mut order, 0)
    };
    (nodes, order)
}

/// Builds the subtree over `ids` (which start at position `first` of the build order),
/// with node indices local to the returned vector.
fn subtree(prims: &[Prim], ids: &mut [u32], first: usize) -> Vec<Node> {
    let mut nodes = Vec::with_capacity(ids.len() / 2 + 1);
    if ids.len() > PARALLEL_ABOVE {
        let (node, split) = split_node(prims, ids, first);
        let Some(split) = split else {
            return vec![node];
        };
        let (left_ids, right_ids) = ids.split_at_mut(split);
        let (left, right) = rayon::join(
            || subtree(prims, left_ids, first),
            || subtree(prims, right_ids, first + split),
        );
        nodes.push(node);
        append_shifted(&mut nodes, &left);
        nodes[0].index = u32::try_from(nodes.len()).expect("node count");
        append_shifted(&mut nodes, &right);
    } else {
        serial(prims, ids, first, &mut nodes);
    }
    nodes
}

/// Appends a subtree built on its own, moving its inner nodes' right-child indices.
fn append_shifted(nodes: &mut Vec<Node>, part: &[Node]) {
    let offset = u32::try_from(nodes.len()).expect("node count");
    nodes.extend(part.iter().map(|node| {
        let mut node = *node;
        if node.count == 0 {
            node.index += offset;
        }
        node
    }));
}

/// Builds the subtree over `ids` on this thread, appending to `nodes`.
fn serial(prims: &[Prim], ids: &mut [u32], first: usize, nodes: &mut Vec<Node>) {
    let at = nodes.len();
    let (node, split) = split_node(prims, ids, first);
    nodes.push(node);
    if let Some(split) = split {
        let (left, right) = ids.split_at_mut(split);
        serial(prims, left, first, nodes);
        nodes[at].index = u32::try_from(nodes.len()).expect("node count");
        serial(prims, right, first + split, nodes);
    }
}

/// The node over `ids` and, unless it is a leaf, where `ids` (partitioned in place)
/// splits into its children.
fn split_node(prims: &[Prim], ids: &mut [u32], first: usize) -> (Node, Option<usize>) {
    let mut bounds = Box3::EMPTY;
    let mut centres = Box3::EMPTY;
    for &id in ids.iter() {
        let prim = &prims[id as usize];
        bounds.grow(&prim.bounds);
        centres.grow(&Box3 {
            min: prim.centre,
            max: prim.centre,
        });
    }
    let leaf = Node {
        min: bounds.min.to_array(),
        count: u32::try_from(ids.len()).expect("leaf size"),
        max: bounds.max.to_array(),
        index: u32::try_from(first).expect("under 4G triangles"),
    };
    if ids.len() <= 2 {
        return (leaf, None);
    }
    let split = best_split(prims, ids, &bounds, &centres);
    let mid = match split {
        Some((axis, bin)) => {
            let bin_of = binner(&centres, axis);
            partition(ids, |id| bin_of(prims[id as usize].centre) < bin)
        }
        None if ids.len() <= MAX_LEAF => return (leaf, None),
        // Centres all in one place (or no split pays) but too many for a leaf: halve.
        None => ids.len() / 2,
    };
    let mid = if mid == 0 || mid == ids.len() {
        ids.len() / 2
    } else {
        mid
    };
    let inner = Node {
        count: 0,
        index: 0,
        ..leaf
    };
    (inner, Some(mid))
}

/// The axis and bin boundary with the lowest surface-area cost, if splitting there
/// beats a leaf (or the node is too big to be one). One pass bins all three axes.
fn best_split(
    prims: &[Prim],
    ids: &[u32],
    bounds: &Box3,
    centres: &Box3,
) -> Option<(usize, usize)> {
    let lo = centres.min;
    let extent = centres.max - centres.min;
    let scale = Vec3::select(
        extent.cmpgt(Vec3::ZERO),
        Vec3::splat(BINS as f32) / extent,
        Vec3::ZERO,
    );
    let mut boxes = [[Box3::EMPTY; BINS]; 3];
    let mut counts = [[0_u32; BINS]; 3];
    for &id in ids {
        let prim = &prims[id as usize];
        let bins = ((prim.centre - lo) * scale)
            .as_uvec3()
            .min(glam::UVec3::splat(BINS as u32 - 1));
        for axis in 0..3 {
            let bin = bins[axis] as usize;
            boxes[axis][bin].grow(&prim.bounds);
            counts[axis][bin] += 1;
        }
    }
    let mut best: Option<(f32, usize, usize)> = None;
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let (boxes, counts) = (&boxes[axis], &counts[axis]);
        // Sweep from the right to get the cost of every right side, then from the left.
        let mut right_area = [0.0_f32; BINS];
        let mut right_count = [0_u32; BINS];
        let (mut acc, mut n) = (Box3::EMPTY, 0);
        for bin in (1..BINS).rev() {
            acc.grow(&boxes[bin]);
            n += counts[bin];
            right_area[bin] = acc.area();
            right_count[bin] = n;
        }
        let (mut acc, mut n) = (Box3::EMPTY, 0);
        for bin in 1..BINS {
            acc.grow(&boxes[bin - 1]);
            n += counts[bin - 1];
            if n == 0 || right_count[bin] == 0 {
                continue;
            }
            let cost = acc.area() * n as f32 + right_area[bin] * right_count[bin] as f32;
            if best.is_none_or(|(b, _, _)| cost < b) {
                best = Some((cost, axis, bin));
            }
        }
    }
    let (cost, axis, bin) = best?;
    let split_cost = TRAVERSAL_COST + cost / bounds.area().max(f32::MIN_POSITIVE);
    (split_cost < ids.len() as f32 || ids.len() > MAX_LEAF).then_some((axis, bin))
}

/// The bin of a centre along `axis`.
fn binner(centres: &Box3, axis: usize) -> impl Fn(Vec3) -> usize {
    // The same arithmetic as `best_split`'s, so a centre lands in the same bin.
    let lo = centres.min[axis];
    let scale = BINS as f32 / (centres.max[axis] - lo);
    move |c: Vec3| (((c[axis] - lo) * scale) as u32).min(BINS as u32 - 1) as usize
}

/// Moves the ids for which `left` holds to the front; returns how many there are.
fn partition(ids: &mut [u32], left: impl Fn(u32) -> bool) -> usize {
    let mut mid = 0;
    for i in 0..ids.len() {
        if left(ids[i]) {
            ids.swap(i, mid);
            mid += 1;
        }
    }
    mid
}
