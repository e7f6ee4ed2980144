//! The render-ready world: a [`Scene`] compiled once into what the tracer needs per ray
//! (matrices and their inverses, world bounds, materials by index, lights in unit form).

use glam::DVec3;

use super::bvh::Bvh;
use super::flatten::flatten;
use super::lights::WorldLight;
use super::object::ObjectHit;
pub use super::object::WorldObject;
use super::object_set::ObjectSet;
use super::sphere_light::SphereLight;
use crate::scene::{Light, Material, Scene, SceneError, validate};
use crate::trace::ray::Ray;
use crate::trace::shapes::{Aabb, MeshStore, TriangleHit};
use crate::trace::terms::Isolation;

/// A point on a surface where a ray hit, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Index of the object hit in [`World::objects`] (the tracer hands recorders and
    /// callers the scene's index instead: [`World::scene_object`]).
    pub object: usize,
    /// Which operand leaf of a CSG object the point is on ([`WorldObject::csg`]); 0 on
    /// other objects.
    pub part: u32,
    /// Ray parameter of the hit.
    pub t: f64,
    /// The hit point.
    pub p: DVec3,
    /// Unit outward normal of the surface.
    pub n_outward: DVec3,
    /// Unit normal turned to face the incoming ray (the shading normal).
    pub n: DVec3,
    /// Absolute bound on each component of `p`'s distance from the exact surface,
    /// including the rounding of taking a spawned ray back to object space.
    pub p_error: DVec3,
}

/// The compiled scene.
#[derive(Clone, Debug)]
pub struct World {
    /// Objects in scene order, hidden ones left out.
    pub objects: Vec<WorldObject>,
    /// Index in the scene's object list of each entry of `objects` (the object id): of
    /// the top-level object a group's member belongs to.
    pub object_scene_index: Vec<usize>,
    /// Per entry of `objects`, the child indices from its top-level object down to it
    /// (empty for a top-level object), for the editor's selection of a tree's part.
    pub object_tree_path: Vec<Vec<usize>>,
    /// Materials, indexed by [`WorldObject::material`].
    pub materials: Vec<Material>,
    /// Names of `materials`, same order.
    pub material_names: Vec<String>,
    /// Non-ambient lights in scene order, muted ones left out.
    pub lights: Vec<WorldLight>,
    /// Index in the scene's light list of each entry of `lights`.
    pub light_scene_index: Vec<usize>,
    /// Per entry of `lights`, its sphere where it has a radius (soft shadows).
    pub light_spheres: Vec<Option<SphereLight>>,
    /// Sum of the ambient lights' strengths (those that shine).
    pub ambient: DVec3,
    /// Colour of rays that hit nothing.
    pub background: DVec3,
    /// Maximum number of mirror bounces.
    pub max_depth: u32,
    /// How mirror colours combine, and where colour is clamped (the course's habits, or
    /// the contract's).
    pub conventions: crate::scene::Conventions,
    /// The scene's camera (the render size may differ from the scene's).
    pub camera: crate::scene::Camera,
    /// A length typical of the scene: the camera's distance to its target.
    pub view_distance: f64,
    /// The lights and objects left out when compiling ([`World::isolated`]).
    pub isolation: Isolation,
    /// The hierarchy over the objects, for scenes large enough to need one.
    pub(crate) bvh: Option<Bvh>,
    /// With more objects than culling covers, a hierarchy over the uncovered ones (from
    /// [`ObjectSet::CULLED_BELOW`] on) for culled queries.
    pub(crate) tail_bvh: Option<Bvh>,
    /// The meshes compiled in, for compiling variants of the scene (shared, not copied).
    pub meshes: MeshStore,
}

/// How rays find the objects they may hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Acceleration {
    /// Test every object in turn (fastest for small scenes).
    Flat,
    /// Walk a bounding volume hierarchy.
    Bvh,
}

/// From this many objects on, the world builds a BVH. It serves the queries culling does
/// not narrow (mirror rays and their shadow rays, and in a world over 64 objects the ones
/// culling does not cover): in a crowd of mirrors the tree is even with the flat list at
/// 12 objects (0.99 of its instructions, 1.01 of its time), ahead from 16 (0.96, 0.97;
/// see docs/BENCHMARKS.md).
pub const BVH_MIN_OBJECTS: usize = 16;

impl World {
    /// Validates and compiles a scene, every light and object in it (see
    /// [`World::isolated`] for fewer).
    ///
    /// # Errors
    /// The scene's first validation problem.
    pub fn new(scene: &Scene) -> Result<Self, SceneError> {
        Self::with_meshes(scene, &MeshStore::default())
    }

    /// As [`World::new`], taking each mesh object's triangles from `meshes` (keyed by the
    /// path as the scene writes it; read with `scene::read_scene_meshes`).
    ///
    /// # Errors
    /// The scene's first validation problem, or a mesh object whose file is not in
    /// `meshes`.
    pub fn with_meshes(scene: &Scene, meshes: &MeshStore) -> Result<Self, SceneError> {
        validate(scene)?;
        let material_names: Vec<String> = scene.materials.keys().cloned().collect();
        let materials = scene.materials.values().cloned().collect();
        let (objects, object_scene_index, object_tree_path) =
            flatten(scene, &material_names, meshes)?;
        let mut lights = Vec::new();
        let mut light_scene_index = Vec::new();
        let mut light_spheres = Vec::new();
        let mut ambient = DVec3::ZERO;
        for (index, light) in scene.lights.iter().enumerate() {
            match light {
                Light::Ambient { .. } => ambient += light.strength(),
                other => {
                    lights.push(WorldLight::new(other));
                    light_scene_index.push(index);
                    light_spheres.push(
                        other
                            .sphere()
                            .map(|(radius, samples)| SphereLight { radius, samples }),
                    );
                }
            }
        }
        let mut world = Self {
            object_scene_index,
            object_tree_path,
            objects,
            materials,
            material_names,
            lights,
            light_scene_index,
            light_spheres,
            ambient,
            background: scene.render.background,
            max_depth: scene.render.max_depth,
            conventions: scene.render.conventions,
            camera: scene.camera.clone(),
            view_distance: (scene.camera.look_at - scene.camera.position).length(),
            isolation: Isolation::NONE,
            bvh: None,
            tail_bvh: None,
            meshes: meshes.clone(),
        };
        if world.objects.len() >= BVH_MIN_OBJECTS {
            world.set_acceleration(Acceleration::Bvh);
        }
        Ok(world)
    }

    /// Chooses how rays find objects (the default follows [`BVH_MIN_OBJECTS`]).
    pub fn set_acceleration(&mut self, acceleration: Acceleration) {
        let boxes: Vec<Aabb> = self.objects.iter().map(|o| o.bounds).collect();
        let tree = |from: usize| {
            (acceleration == Acceleration::Bvh && from < boxes.len())
                .then(|| Bvh::build(&boxes[from..]))
        };
        self.bvh = tree(0);
        self.tail_bvh = tree(ObjectSet::CULLED_BELOW);
    }

    /// The closest hit along a world ray with `t` in (0, t_max).
    #[must_use]
    pub fn intersect(&self, ray: &Ray, t_max: f64) -> Option<SurfacePoint> {
        self.intersect_among(ray, t_max, ObjectSet::ALL)
    }

    /// As [`World::intersect`], testing only the objects of `among`: a culling step's
    /// answer that the others cannot be hit. The same hit, bit for bit, as testing all of
    /// them whenever that is so (a tie still goes to the earlier object).
    #[must_use]
    pub fn intersect_among(&self, ray: &Ray, t_max: f64, among: ObjectSet) -> Option<SurfacePoint> {
        let inv_dir = ray.dir.recip();
        // A culled set names every candidate among the objects culling covers, and
        // testing those few in the list beats walking the tree.
        let closest = match &self.bvh {
            Some(bvh) if among == ObjectSet::ALL => {
                self.closest_in_tree::<0>(bvh, ray, inv_dir, t_max, among, None)
            }
            Some(_) if self.tail_bvh.is_some() => {
                self.closest_listed_then_tail(ray, inv_dir, t_max, among)
            }
            _ => self.closest_in_list(ray, inv_dir, t_max, among, self.objects.len()),
        };
        closest.map(|(index, hit)| self.surface_point(index, ray, &hit))
    }

    /// The flat list's closest hit: the objects of `among` in scene order, each later one
    /// below `count`, tested only up to the nearest hit so far (so a tie keeps the earlier
    /// object).
    #[inline(always)]
    pub(crate) fn closest_in_list(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        among: ObjectSet,
        count: usize,
    ) -> Option<(usize, ObjectHit)> {
        let mut closest = None;
        let mut t_limit = t_max;
        for index in among.members_below(count) {
            if let Some(hit) = self.objects[index].hit(ray, inv_dir, t_limit) {
                t_limit = hit.hit.t;
                closest = Some((index, hit));
            }
        }
        closest
    }

    /// Where the ray meets object `index` first with `t` in (0, t_max), if it does: for
    /// the inspector, to show where a shadow ray met the object that blocked it.
    #[must_use]
    pub fn intersect_object(&self, index: usize, ray: &Ray, t_max: f64) -> Option<SurfacePoint> {
        let object = self.objects.get(index)?;
        let ray_in_object = ray.transformed(&object.object_from_world);
        let hit = object.hit_unbounded(&ray_in_object, t_max)?;
        Some(self.surface_point(index, ray, &hit))
    }

    /// The path of the scene node a hit lies on: its top-level object's index, then
    /// child and operand indices down to the leaf (a CSG operand's too), as the editor
    /// selects a part of a tree.
    #[must_use]
    pub fn node_path(&self, hit: &SurfacePoint) -> Vec<usize> {
        let mut path = vec![self.scene_object(hit.object)];
        if let Some(below) = self.object_tree_path.get(hit.object) {
            path.extend_from_slice(below);
        }
        if let Some(tree) = &self.objects[hit.object].csg
            && let Some(leaf) = tree.leaves.get(hit.part as usize)
        {
            path.extend_from_slice(&leaf.tree_path);
        }
        path
    }

    /// For a mesh object: which triangle the ray meets first and where on it.
    #[must_use]
    pub fn triangle_hit(&self, index: usize, ray: &Ray, t_max: f64) -> Option<TriangleHit> {
        let object = self.objects.get(index)?;
        let ray_in_object = ray.transformed(&object.object_from_world);
        object.mesh.as_ref()?.triangle_hit(&ray_in_object, t_max)
    }

    /// The first object found between the ray's origin and `t_max`, if any.
    #[must_use]
    pub fn occluder(&self, ray: &Ray, t_max: f64) -> Option<usize> {
        self.occluder_except(ray, t_max, None)
    }

    /// As [`World::occluder`], not testing object `except`: a ray leaving a convex surface
    /// on its outer side (or leaving a plane) cannot meet that surface again.
    #[must_use]
    pub fn occluder_except(&self, ray: &Ray, t_max: f64, except: Option<usize>) -> Option<usize> {
        self.occluder_except_among(ray, t_max, except, ObjectSet::ALL)
    }

    /// As [`World::occluder_except`], testing only the objects of `among`: a culling
    /// step's answer that the others cannot block this ray. The same answer as testing
    /// all of them whenever that is so (the first blocker in scene order).
    #[must_use]
    pub fn occluder_except_among(
        &self,
        ray: &Ray,
        t_max: f64,
        except: Option<usize>,
        among: ObjectSet,
    ) -> Option<usize> {
        self.occluder_in::<false>(ray, ray.dir.recip(), t_max, except, among)
    }

    /// The occlusion query of [`World::occluder_except_among`] (`ANY` false: the first
    /// blocker in scene order) and of [`World::any_occluder_among`] (`ANY` true: the
    /// first the trees' walks meet, blocked or not the same answer). One body, each
    /// query its own inlined copy.
    #[inline(always)]
    pub(crate) fn occluder_in<const ANY: bool>(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        except: Option<usize>,
        among: ObjectSet,
    ) -> Option<usize> {
        // As for the closest hit: a culled query tests its candidates in the list.
        match &self.bvh {
            Some(bvh) if among == ObjectSet::ALL => {
                let blocks = |i| Some(i) != except && self.objects[i].blocks(ray, inv_dir, t_max);
                if ANY {
                    bvh.any_blocker(ray, inv_dir, t_max, blocks)
                } else {
                    bvh.first_blocker(ray, inv_dir, t_max, blocks)
                }
            }
            // The covered candidates in the list, then the tree over the rest.
            Some(_) if self.tail_bvh.is_some() => {
                let listed = ObjectSet::CULLED_BELOW;
                self.first_blocker_in_list(ray, inv_dir, t_max, except, among, listed)
                    .or_else(|| {
                        self.blocker_in_tail::<ANY>(ray, inv_dir, t_max, |index| {
                            Some(index) != except && among.contains(index)
                        })
                    })
            }
            _ => self.first_blocker_in_list(ray, inv_dir, t_max, except, among, self.objects.len()),
        }
    }

    /// The flat list's first object of `among` below `count`, in scene order, that blocks
    /// the ray.
    #[inline(always)]
    pub(crate) fn first_blocker_in_list(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        except: Option<usize>,
        among: ObjectSet,
        count: usize,
    ) -> Option<usize> {
        // A loop, not `find`: its closure's fold stayed out of line with two callers.
        #[allow(clippy::manual_find)]
        for index in among.members_below(count) {
            if Some(index) != except && self.objects[index].blocks(ray, inv_dir, t_max) {
                return Some(index);
            }
        }
        None
    }

    /// The index into [`World::materials`] of the surface at `hit`: its object's, or on
    /// a CSG object its operand's.
    #[must_use]
    #[inline]
    pub fn material_at(&self, hit: &SurfacePoint) -> usize {
        let object = &self.objects[hit.object];
        match &object.csg {
            Some(tree) => tree.leaves[hit.part as usize].material,
            None => object.material,
        }
    }

    /// World-space details of an object-space hit.
    #[inline(always)]
    pub(crate) fn surface_point(&self, index: usize, ray: &Ray, hit: &ObjectHit) -> SurfacePoint {
        let (part, hit) = (hit.part, &hit.hit);
        let object = &self.objects[index];
        let m = &object.world_from_object;
        let p = m.transform_point3(hit.p);
        let n_outward = (object.normal_from_object * hit.n).normalize();
        let n = if n_outward.dot(ray.dir) > 0.0 {
            -n_outward
        } else {
            n_outward
        };
        SurfacePoint {
            object: index,
            part,
            t: hit.t,
            p,
            n_outward,
            n,
            p_error: object.world_error(hit, p),
        }
    }
}
