//! A bounding volume hierarchy over the objects' world boxes, for scenes with many
//! objects: split by the surface area heuristic (`super::bvh_split`), up to 4 objects a
//! leaf, the near child first by
//! the ray's sign along the split axis. It gives the flat list's answers bit for bit: a
//! tie in `t` goes to the earlier object, and an occlusion query returns the first
//! blocker in scene order (leaves are in scene order and nodes know their smallest
//! object index, so a found blocker prunes the rest). Small scenes are faster with the
//! flat list, and a tile's culled queries with the list of their few candidates (see
//! [`super::compiled::BVH_MIN_OBJECTS`] and docs/BENCHMARKS.md).

use glam::DVec3;

use super::bvh_split::split;
use crate::trace::ray::Ray;
use crate::trace::shapes::Aabb;

/// Objects per leaf at most.
const LEAF_SIZE: usize = 4;

/// One node: a leaf holds `count > 0` objects from `first` in [`Bvh::order`], in scene
/// order; an inner node (`count == 0`) has its children at `first` and `first + 1`.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    first: u32,
    count: u32,
    /// The smallest object index below the node, to skip subtrees that cannot hold an
    /// earlier blocker than the one found.
    min_object: u32,
    /// An inner node's split axis: its first child holds the lower box centres.
    axis: u32,
}

/// The hierarchy: nodes in one array, children of a node next to each other.
#[derive(Clone, Debug)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Object indices, leaves' ranges point into this.
    order: Vec<u32>,
}

impl Bvh {
    /// Builds over the objects' boxes, each node split where the surface area heuristic
    /// says.
    #[must_use]
    pub fn build(boxes: &[Aabb]) -> Self {
        let mut bvh = Self {
            nodes: Vec::with_capacity(boxes.len() * 2),
            order: (0..boxes.len() as u32).collect(),
        };
        if boxes.is_empty() {
            return bvh;
        }
        bvh.nodes.push(Node {
            bounds: union(boxes, &bvh.order),
            first: 0,
            count: boxes.len() as u32,
            min_object: 0,
            axis: 0,
        });
        let mut pending = vec![0usize];
        while let Some(index) = pending.pop() {
            let node = bvh.nodes[index];
            let (start, count) = (node.first as usize, node.count as usize);
            if count <= LEAF_SIZE {
                bvh.order[start..start + count].sort_unstable();
                continue;
            }
            let (axis, half) = split(boxes, &mut bvh.order[start..start + count]);
            let left = bvh.nodes.len();
            for (first, len) in [(start, half), (start + half, count - half)] {
                let ids = &bvh.order[first..first + len];
                bvh.nodes.push(Node {
                    bounds: union(boxes, ids),
                    first: first as u32,
                    count: len as u32,
                    min_object: ids.iter().copied().min().unwrap_or(0),
                    axis: 0,
                });
            }
            bvh.nodes[index].first = left as u32;
            bvh.nodes[index].count = 0;
            bvh.nodes[index].axis = axis as u32;
            pending.extend([left, left + 1]);
        }
        bvh
    }

    /// Visits the objects whose boxes the ray may meet before the current limit, nearer
    /// subtrees first. `visit(object, t_limit)` returns a new, smaller limit when it
    /// found a hit, or `Err(())` to stop (an occlusion query's first hit).
    pub fn traverse(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        mut t_limit: f64,
        mut visit: impl FnMut(usize, f64) -> Result<Option<f64>, ()>,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = [0u32; 64];
        let mut depth = 1;
        while depth > 0 {
            depth -= 1;
            let node = self.nodes[stack[depth] as usize];
            if !node.bounds.hit_by(ray, inv_dir, t_limit) {
                continue;
            }
            if node.count > 0 {
                for &object in &self.order[node.first as usize..(node.first + node.count) as usize]
                {
                    match visit(object as usize, t_limit) {
                        Ok(Some(t)) => t_limit = t,
                        Ok(None) => {}
                        Err(()) => return,
                    }
                }
            } else if depth + 2 <= stack.len() {
                // Push the far child first so the near one is tested first.
                let (near, far) = Self::children_near_first(&node, ray);
                stack[depth] = far;
                stack[depth + 1] = near;
                depth += 2;
            }
        }
    }
}

impl Bvh {
    /// The first object in scene order (smallest index) that `blocks` the ray, among those
    /// whose boxes it meets before `t_max`: the flat list's answer. A blocker found
    /// lets the walk skip every subtree and leaf entry from its index on.
    pub fn first_blocker(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        mut blocks: impl FnMut(usize) -> bool,
    ) -> Option<usize> {
        let mut found = u32::MAX;
        let mut stack = [0u32; 64];
        let mut depth = usize::from(!self.nodes.is_empty());
        while depth > 0 {
            depth -= 1;
            let node = self.nodes[stack[depth] as usize];
            if node.min_object >= found || !node.bounds.hit_by(ray, inv_dir, t_max) {
                continue;
            }
            if node.count > 0 {
                let leaf = &self.order[node.first as usize..(node.first + node.count) as usize];
                // Leaves are in scene order: the first blocker is the leaf's earliest.
                if let Some(&object) = leaf
                    .iter()
                    .take_while(|&&object| object < found)
                    .find(|&&object| blocks(object as usize))
                {
                    found = object;
                }
            } else if depth + 2 <= stack.len() {
                let (near, far) = Self::children_near_first(&node, ray);
                stack[depth] = far;
                stack[depth + 1] = near;
                depth += 2;
            }
        }
        (found != u32::MAX).then_some(found as usize)
    }

    /// An object that `blocks` the ray, the first the walk meets (nearer subtrees
    /// first) among those whose boxes the ray meets before `t_max`: `Some` exactly where
    /// [`Self::first_blocker`] is, without proving that no earlier object blocks.
    #[inline]
    pub fn any_blocker(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        mut blocks: impl FnMut(usize) -> bool,
    ) -> Option<usize> {
        let mut found = None;
        // The occlusion walk of `traverse`: the limit never shrinks, the first blocker
        // stops it.
        self.traverse(ray, inv_dir, t_max, |object, _| {
            if blocks(object) {
                found = Some(object);
                Err(())
            } else {
                Ok(None)
            }
        });
        found
    }

    /// An inner node's children, the one on the side the ray comes from along the split
    /// axis first.
    #[inline]
    fn children_near_first(node: &Node, ray: &Ray) -> (u32, u32) {
        let (a, b) = (node.first, node.first + 1);
        if ray.dir[node.axis as usize] >= 0.0 {
            (a, b)
        } else {
            (b, a)
        }
    }
}

fn union(boxes: &[Aabb], ids: &[u32]) -> Aabb {
    ids.iter().fold(
        Aabb::new(DVec3::INFINITY, DVec3::NEG_INFINITY),
        |acc, &i| {
            Aabb::new(
                acc.min.min(boxes[i as usize].min),
                acc.max.max(boxes[i as usize].max),
            )
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_object_is_in_exactly_one_leaf() {
        let boxes: Vec<Aabb> = (0..37)
            .map(|i| {
                let c = DVec3::new(f64::from(i % 7), f64::from(i / 7), f64::from(i % 3));
                Aabb::new(c - 0.3, c + 0.3)
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        let mut seen = vec![0; boxes.len()];
        for node in bvh.nodes.iter().filter(|n| n.count > 0) {
            assert!(node.count as usize <= LEAF_SIZE);
            for &i in &bvh.order[node.first as usize..(node.first + node.count) as usize] {
                seen[i as usize] += 1;
                assert!(node.bounds.min.cmple(boxes[i as usize].min).all());
            }
        }
        assert!(seen.iter().all(|&n| n == 1));
    }

    #[test]
    fn traversal_visits_the_boxes_a_ray_crosses() {
        let boxes: Vec<Aabb> = (0..20)
            .map(|i| {
                let c = DVec3::new(f64::from(i) * 2.0, 0.0, 0.0);
                Aabb::new(c - 0.5, c + 0.5)
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        // Down the line y = 0 from the left: every box; from above x = 10: box 5 only.
        let along = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let mut visited = Vec::new();
        bvh.traverse(&along, along.dir.recip(), f64::INFINITY, |i, _| {
            visited.push(i);
            Ok(None)
        });
        visited.sort_unstable();
        assert_eq!(visited, (0..20).collect::<Vec<_>>());
        let down = Ray::new(DVec3::new(10.0, 5.0, 0.0), -DVec3::Y);
        let mut visited = Vec::new();
        bvh.traverse(&down, down.dir.recip(), f64::INFINITY, |i, _| {
            visited.push(i);
            Ok(None)
        });
        // Box 5 and at most the other objects of its leaf; nothing else.
        assert!(
            visited.contains(&5) && visited.len() <= LEAF_SIZE,
            "{visited:?}"
        );
    }
}
