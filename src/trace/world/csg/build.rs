//! Compiling a scene's CSG node into a [`CsgTree`], with a work list instead of
//! recursion so the depth of the tree never reaches the call stack.

use std::sync::Arc;

use glam::{DAffine3, DVec3};

use super::tree::{CsgLeaf, CsgTree, Extent, Step, combine_extents};
use crate::scene::{CsgOp, Object, SceneError, Shape};
use crate::trace::shapes::{self, Aabb, MeshStore, Primitive, TriangleMesh};

/// What is left to do for the node being compiled.
enum Work<'a> {
    /// Compile this object, placed in the node's space, with the material it inherits
    /// and its tree path.
    Visit {
        object: &'a Object,
        node_from_object: DAffine3,
        material: &'a str,
        path: String,
        /// Operand indices from the compiled node down to this object.
        below: Vec<usize>,
    },
    /// All operands of a node are compiled: combine them.
    Emit { op: CsgOp, operands: u32 },
    /// A node's first operand is compiled: if it is empty along a ray, skip the rest.
    Check,
    /// A run of `leaves` leaf operands starts whose boxes together lie in `bounds`.
    ChunkStart { bounds: Aabb, leaves: u32 },
    /// That run ends.
    ChunkEnd,
}

impl CsgTree {
    /// Compiles a CSG node's operands, `material` being the node's own (inherited by
    /// operands that name none) and `path` its tree path. A Group among the operands
    /// stands for the union of its children; a Mesh operand takes its triangles from
    /// `meshes`.
    ///
    /// # Errors
    /// An operand the tracer cannot draw, a mesh that is not loaded or not closed, or a
    /// leaf left without a material, named by its tree path.
    pub fn build(
        op: CsgOp,
        operands: &[Object],
        material: &str,
        path: &str,
        material_index: &dyn Fn(&str) -> Option<usize>,
        meshes: &MeshStore,
    ) -> Result<Self, SceneError> {
        let mut tree = CsgTree {
            leaves: Vec::new(),
            steps: Vec::new(),
            extent: Extent::Empty,
            bounding_sphere: None,
            convex: false,
            closed_form: false,
        };
        let mut extents: Vec<Extent> = Vec::new();
        // Per operand on the stack, a sphere leaf's placement that holds all of it.
        let mut spheres: Vec<Option<DAffine3>> = Vec::new();
        // Per operand on the stack, whether its solid is known to be convex.
        let mut convex: Vec<bool> = Vec::new();
        // The SkipIfEmpty steps waiting for their node's end (nodes nest, so a stack).
        let mut checks: Vec<usize> = Vec::new();
        let mut chunks: Vec<usize> = Vec::new();
        let mut work = Vec::new();
        push_operands(
            &mut work,
            op,
            operands,
            &DAffine3::IDENTITY,
            material,
            path,
            &[],
        );
        while let Some(item) = work.pop() {
            match item {
                Work::ChunkStart { bounds, leaves } => {
                    chunks.push(tree.steps.len());
                    tree.steps.push(Step::SkipIfMissed {
                        bounds,
                        lists: leaves,
                        skip_to: 0,
                    });
                }
                Work::ChunkEnd => {
                    let start = chunks.pop().expect("a chunk ends after it starts");
                    let end = u32::try_from(tree.steps.len()).expect("under 2^32 steps");
                    if let Step::SkipIfMissed { skip_to, .. } = &mut tree.steps[start] {
                        *skip_to = end;
                    }
                }
                Work::Check => {
                    checks.push(tree.steps.len());
                    tree.steps.push(Step::SkipIfEmpty { skip_to: 0 });
                }
                Work::Emit { op, operands } => {
                    tree.steps.push(Step::Combine { op, operands });
                    if skips(op, operands) {
                        let check = checks.pop().expect("a Check precedes its Emit");
                        let end = u32::try_from(tree.steps.len()).expect("under 2^32 steps");
                        tree.steps[check] = Step::SkipIfEmpty { skip_to: end };
                    }
                    let first = extents.len() - operands as usize;
                    let combined = combine_extents(op, &extents[first..]);
                    let sphere = bounding_sphere(op, &spheres[first..]);
                    // Intersections of convex solids are convex; nothing else here is
                    // known to be.
                    let all_convex = convex[first..].iter().all(|&c| c);
                    let node_convex = all_convex && (op == CsgOp::Intersection || operands == 1);
                    convex.truncate(first);
                    convex.push(node_convex);
                    extents.truncate(first);
                    extents.push(combined);
                    spheres.truncate(first);
                    spheres.push(sphere);
                }
                Work::Visit {
                    object,
                    node_from_object,
                    material,
                    path,
                    below,
                } => match &object.shape {
                    Shape::Csg { op, operands } => {
                        let place = &node_from_object;
                        push_operands(&mut work, *op, operands, place, material, &path, &below);
                    }
                    Shape::Group { children } => {
                        let union = CsgOp::Union;
                        let place = &node_from_object;
                        push_operands(&mut work, union, children, place, material, &path, &below);
                    }
                    shape => {
                        let (primitive, mesh) = match shape {
                            Shape::Mesh { path: file } => {
                                (Primitive::Mesh, Some(solid_mesh(meshes, file, &path)?))
                            }
                            _ => (
                                Primitive::of(shape).ok_or_else(|| {
                                    SceneError::Invalid(format!(
                                        "object \"{path}\": the tracer cannot draw a {} yet",
                                        shape.name()
                                    ))
                                })?,
                                None,
                            ),
                        };
                        let material = material_index(material).ok_or_else(|| {
                            SceneError::Invalid(format!(
                                "object \"{path}\": no material (neither its own nor a parent's)"
                            ))
                        })?;
                        let index = u32::try_from(tree.leaves.len()).expect("under 2^32 leaves");
                        tree.steps.push(Step::Leaf(index));
                        // Most unit shapes are convex; a torus, a tube or a mesh may not be.
                        convex.push(mesh.is_none() && primitive.is_convex());
                        let mut leaf =
                            CsgLeaf::new(primitive, mesh, path, material, node_from_object);
                        leaf.tree_path = below;
                        extents.push(leaf.bounds.map_or(Extent::Unbounded, Extent::Box));
                        spheres.push((primitive == Primitive::Sphere).then_some(node_from_object));
                        tree.leaves.push(leaf);
                    }
                },
            }
        }
        tree.extent = extents.pop().unwrap_or(Extent::Empty);
        tree.bounding_sphere = spheres.pop().flatten();
        tree.convex = convex.pop().unwrap_or(false);
        tree.closed_form = tree.closed_form_applies();
        Ok(tree)
    }
}

/// Queues a node's operands (first one on top) followed by its combination.
fn push_operands<'a>(
    work: &mut Vec<Work<'a>>,
    op: CsgOp,
    operands: &'a [Object],
    node_from_parent: &DAffine3,
    material: &'a str,
    path: &str,
    below: &[usize],
) {
    let operands_count = u32::try_from(operands.len()).expect("under 2^32 operands");
    work.push(Work::Emit {
        op,
        operands: operands_count,
    });
    let visit = |(k, operand): (usize, &'a Object)| Work::Visit {
        object: operand,
        node_from_object: *node_from_parent * operand.transform.world_from_object(),
        material: if operand.material.is_empty() {
            material
        } else {
            &operand.material
        },
        path: format!("{path}/{}", operand.name),
        below: [below, &[k]].concat(),
    };
    let rest = operands.get(1..).unwrap_or_default();
    for chunk in chunks(rest, node_from_parent).iter().rev() {
        let members = &rest[chunk.first..chunk.first + chunk.len];
        if chunk.len > 1 {
            work.push(Work::ChunkEnd);
        }
        let first = 1 + chunk.first;
        work.extend(
            members
                .iter()
                .enumerate()
                .rev()
                .map(|(k, o)| visit((first + k, o))),
        );
        if chunk.len > 1 {
            work.push(Work::ChunkStart {
                bounds: chunk.bounds,
                leaves: u32::try_from(chunk.len).expect("a small chunk"),
            });
        }
    }
    if let Some(first) = operands.first() {
        if skips(op, operands_count) {
            work.push(Work::Check);
        }
        work.push(visit((0, first)));
    }
}

/// A run of operands to test as one box first: bounded leaves lying close together.
struct Chunk {
    first: usize,
    len: usize,
    bounds: Aabb,
}

/// Most leaves one chunk takes.
const CHUNK_MAX: usize = 8;

/// Splits operands into runs of bounded leaves that stay together (the box around a run
/// has no more surface than its members' boxes together, as the pips on one face of a
/// die) and single operands; a ray that misses a run's box skips all its leaves.
fn chunks(operands: &[Object], node_from_parent: &DAffine3) -> Vec<Chunk> {
    let area = |b: &Aabb| {
        let d = (b.max - b.min).max(DVec3::ZERO);
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    };
    let mut out: Vec<Chunk> = Vec::new();
    let mut members_area = 0.0;
    for (k, operand) in operands.iter().enumerate() {
        let bounds = Primitive::of(&operand.shape)
            .filter(|&p| p != Primitive::Plane && p != Primitive::Mesh)
            .map(|p| {
                let placed = *node_from_parent * operand.transform.world_from_object();
                shapes::object_bounds(p).transformed(&placed)
            });
        let Some(bounds) = bounds else {
            out.push(Chunk {
                first: k,
                len: 1,
                bounds: Aabb::new(DVec3::ZERO, DVec3::ZERO),
            });
            members_area = f64::INFINITY; // nothing joins a non-leaf
            continue;
        };
        if let Some(last) = out.last_mut() {
            let joined = last.bounds.union(&bounds);
            if last.len < CHUNK_MAX && area(&joined) <= members_area + area(&bounds) {
                last.len += 1;
                last.bounds = joined;
                members_area += area(&bounds);
                continue;
            }
        }
        out.push(Chunk {
            first: k,
            len: 1,
            bounds,
        });
        members_area = area(&bounds);
    }
    out
}

/// A Mesh operand's triangles, if they are loaded and bound a solid (a CSG operand
/// needs an inside).
fn solid_mesh(meshes: &MeshStore, file: &str, path: &str) -> Result<Arc<TriangleMesh>, SceneError> {
    let mesh = meshes.for_object(file, path)?;
    if !mesh.is_closed() {
        return Err(SceneError::Invalid(format!(
            "object \"{path}\": the mesh \"{file}\" is not closed (some edge is not shared \
             by exactly two triangles facing the same way), so it has no inside and cannot \
             be a CSG operand; use it outside the CSG node, or close the surface"
        )));
    }
    Ok(Arc::clone(mesh))
}

/// Whether a node gets a SkipIfEmpty after its first operand: an Intersection or a
/// Difference is empty wherever its first operand is.
fn skips(op: CsgOp, operands: u32) -> bool {
    op != CsgOp::Union && operands >= 2
}

/// A sphere that holds a whole node, as the placement of the unit sphere, from its
/// operands' (each `None` or such a placement): a Difference's first operand's, a
/// Union's only if it has one operand, and for an Intersection the smallest of its
/// operands' and of the lens balls of each two of them.
fn bounding_sphere(op: CsgOp, operands: &[Option<DAffine3>]) -> Option<DAffine3> {
    let radius = |m: &DAffine3| shapes::largest_stretch(&m.matrix3);
    match (op, operands) {
        (CsgOp::Difference, [first, ..]) | (CsgOp::Union, [first]) => *first,
        (CsgOp::Intersection, _) => {
            let spheres: Vec<DAffine3> = operands.iter().flatten().copied().collect();
            let lenses = spheres
                .iter()
                .enumerate()
                .flat_map(|(i, a)| spheres[i + 1..].iter().filter_map(|b| lens_ball(a, b)));
            spheres
                .iter()
                .copied()
                .chain(lenses)
                .min_by(|a, b| radius(a).total_cmp(&radius(b)))
        }
        _ => None,
    }
}

/// A ball holding the intersection of two balls (each the unit sphere placed by `a` or
/// `b`, taken at the radius of its largest stretch), when that is a lens of two caps
/// each at most a hemisphere: the ball round their common circle. A point of such a cap
/// at height `y` over the circle's plane lies within `h^2 - 2 a y <= h^2` of its centre
/// squared (`a >= 0` the plane's distance from the cap's own centre), so inside it.
/// `None` where the balls do not make such a lens.
fn lens_ball(a: &DAffine3, b: &DAffine3) -> Option<DAffine3> {
    let (c1, r1) = (a.translation, shapes::largest_stretch(&a.matrix3));
    let (c2, r2) = (b.translation, shapes::largest_stretch(&b.matrix3));
    let d = (c2 - c1).length();
    // From the first centre to the circle's plane.
    let along = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    let circle_sq = r1 * r1 - along * along;
    if !(d > 0.0 && along >= 0.0 && along <= d && circle_sq > 0.0) {
        return None;
    }
    // Padded by far more than the rounding of the arithmetic above (the square root of
    // a difference of squares loses half the digits where the circle is small), and
    // still by a few parts in 1e5 of the balls' size.
    let radius = (circle_sq + 1e-9 * (r1 + r2) * (r1 + r2)).sqrt();
    let centre = c1 + (c2 - c1) * (along / d);
    Some(DAffine3::from_scale_rotation_translation(
        DVec3::splat(radius),
        glam::DQuat::IDENTITY,
        centre,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit sphere placed at `centre` with `radius`, turned.
    fn ball(centre: DVec3, radius: f64, turn: f64) -> DAffine3 {
        DAffine3::from_scale_rotation_translation(
            DVec3::splat(radius),
            glam::DQuat::from_euler(glam::EulerRot::XYZ, turn, 2.0 * turn, -turn),
            centre,
        )
    }

    /// Pairs of balls of many sizes and overlaps: where a lens ball is given, every point
    /// inside both balls (and every point of their common circle) is inside it, and it is
    /// no larger than either; where a cap would be more than a hemisphere, none is given.
    #[test]
    fn the_lens_ball_holds_all_of_two_balls_intersection() {
        let mut cases = crate::test_cases::Xorshift(0x9e37_79b9_7f4a_7c15);
        let mut unit = move || cases.unit();
        let (mut lenses, mut refused, mut points) = (0, 0, 0);
        for _ in 0..3000 {
            let mut vector =
                |scale: f64| DVec3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5) * scale;
            let (c1, c2) = (vector(4.0), vector(4.0));
            let (r1, r2) = (0.1 + 2.0 * unit(), 0.1 + 2.0 * unit());
            let (a, b) = (ball(c1, r1, unit()), ball(c2, r2, unit()));
            let Some(lens) = lens_ball(&a, &b) else {
                let d = (c2 - c1).length();
                if d < r1 + r2 && d > (r1 - r2).abs() {
                    refused += 1; // they meet, but a cap is more than a hemisphere
                }
                continue;
            };
            lenses += 1;
            let (centre, radius) = (lens.translation, shapes::largest_stretch(&lens.matrix3));
            assert!(
                radius <= r1.min(r2) * (1.0 + 1e-4),
                "{radius} against {r1}, {r2}"
            );
            // Points of the smaller ball inside the other one.
            let (small, small_r, other, other_r) = if r1 < r2 {
                (c1, r1, c2, r2)
            } else {
                (c2, r2, c1, r1)
            };
            for _ in 0..200 {
                let p = small + (DVec3::new(unit(), unit(), unit()) * 2.0 - 1.0) * small_r;
                if (p - small).length() <= small_r && (p - other).length() <= other_r {
                    points += 1;
                    assert!((p - centre).length() <= radius, "{p} outside the lens ball");
                }
            }
            // The common circle, where the caps meet.
            let axis = (c2 - c1).normalize();
            let d = (c2 - c1).length();
            let along = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
            let circle = (r1 * r1 - along * along).sqrt();
            let (u, v) = axis.any_orthonormal_pair();
            for k in 0..16 {
                let angle = f64::from(k) * std::f64::consts::TAU / 16.0;
                let p = c1 + axis * along + (u * angle.cos() + v * angle.sin()) * circle;
                assert!((p - centre).length() <= radius);
            }
        }
        assert!(
            lenses > 300 && refused > 100,
            "{lenses} lenses, {refused} refused"
        );
        assert!(points > 10_000, "{points} points tested");
    }
}
