//! Where a node of the object hierarchy splits: the surface area heuristic. A ray that
//! meets a parent box meets a child box with a chance near the ratio of their surface
//! areas, so the split that makes `area(left) * n_left + area(right) * n_right` least
//! tests the fewest objects on average. The median split it replaced put a glass ball
//! and three floor tiles in one tall leaf box, so every ray passing over the floor there
//! tested the tiles.

use glam::DVec3;

use crate::trace::shapes::Aabb;

/// Reorders `ids` (indices into `boxes`, at least two) so that the first `split` go to
/// one child and the rest to the other, lower box centres first along `axis`: the split
/// of least surface area cost over the three axes. Boxes whose areas are not finite
/// (an unbounded object) are split at the median of the axis their centres spread most.
pub(super) fn split(boxes: &[Aabb], ids: &mut [u32]) -> (usize, usize) {
    let centre = |i: u32| (boxes[i as usize].min + boxes[i as usize].max) * 0.5;
    let mut best: Option<(f64, usize, usize)> = None;
    let mut right_areas = vec![0.0; ids.len()];
    for axis in 0..3 {
        sort_along(ids, axis, &centre);
        // right_areas[i]: the area of the box around ids[i..].
        let mut around = empty();
        for (i, &id) in ids.iter().enumerate().rev() {
            around = around.union(&boxes[id as usize]);
            right_areas[i] = half_area(&around);
        }
        let mut around = empty();
        for split in 1..ids.len() {
            around = around.union(&boxes[ids[split - 1] as usize]);
            let cost =
                half_area(&around) * split as f64 + right_areas[split] * (ids.len() - split) as f64;
            // Strictly less: among equal costs the first axis and split found stay.
            if cost.is_finite() && best.is_none_or(|(least, _, _)| cost < least) {
                best = Some((cost, axis, split));
            }
        }
    }
    let (axis, split) = match best {
        Some((_, axis, split)) => (axis, split),
        None => (widest_spread(ids, &centre), ids.len() / 2),
    };
    sort_along(ids, axis, &centre);
    (axis, split)
}

/// Sorts by box centre along `axis`, ties by index, so that a build is the same every
/// time.
fn sort_along(ids: &mut [u32], axis: usize, centre: &impl Fn(u32) -> DVec3) {
    ids.sort_unstable_by(|&a, &b| centre(a)[axis].total_cmp(&centre(b)[axis]).then(a.cmp(&b)));
}

/// The axis along which the box centres spread most.
fn widest_spread(ids: &[u32], centre: &impl Fn(u32) -> DVec3) -> usize {
    let (lo, hi) = ids
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &i| {
            (lo.min(centre(i)), hi.max(centre(i)))
        });
    (hi - lo).max_position()
}

fn empty() -> Aabb {
    Aabb::new(DVec3::INFINITY, DVec3::NEG_INFINITY)
}

/// Half the surface area of a box (the factor of two cancels in every comparison).
fn half_area(b: &Aabb) -> f64 {
    let d = b.max - b.min;
    d.x * d.y + d.y * d.z + d.z * d.x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(centre: DVec3, half: f64) -> Aabb {
        Aabb::new(centre - half, centre + half)
    }

    #[test]
    fn a_tall_object_beside_a_floor_gets_a_child_of_its_own() {
        // Eight flat tiles in a row along x, and a tall ball above the middle of them:
        // the median split would put the ball with four tiles.
        let mut boxes: Vec<Aabb> = (0..8)
            .map(|i| {
                let c = DVec3::new(f64::from(i), 0.0, 0.0);
                Aabb::new(c - DVec3::new(0.5, 0.1, 0.5), c + DVec3::new(0.5, 0.1, 0.5))
            })
            .collect();
        boxes.push(cube(DVec3::new(3.5, 2.0, 0.0), 1.0));
        let mut ids: Vec<u32> = (0..9).collect();
        let (axis, split) = split(&boxes, &mut ids);
        let (left, right) = ids.split_at(split);
        let alone = if left.len() == 1 { left } else { right };
        assert_eq!((axis, alone), (1, &[8][..]), "{ids:?} split at {split}");
    }

    #[test]
    fn unbounded_boxes_split_at_the_median() {
        let mut boxes: Vec<Aabb> = (0..6)
            .map(|i| cube(DVec3::new(0.0, 0.0, f64::from(i) * 3.0), 1.0))
            .collect();
        boxes[0] = Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY);
        let mut ids: Vec<u32> = (0..6).collect();
        assert_eq!(split(&boxes, &mut ids).1, 3);
    }
}
