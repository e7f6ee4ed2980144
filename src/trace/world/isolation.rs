//! The isolation switches compiled into the world once: a scene with its muted lights and
//! hidden objects left out, so the tracer's loops never check a switch.
//!
//! - A muted light and a hidden object are absent: a hidden object casts no shadow, is not
//!   reflected and cannot be picked; a muted light lights nothing, seen directly or in a
//!   mirror.
//! - While lights are solo, the picture is rendered as if they were the only lights
//!   (through mirrors too); the term switches still apply on top.
//! - The background is not any light's, but for the solo images of all the lights to add
//!   up to the full picture it must go with exactly one light's solo: the first Ambient
//!   light's (as the ambient term's solo shows it), or, in a scene without an Ambient
//!   light, the first light's. The other lights' solos show black where rays miss.
//!   Muting never removes the background.
//! - Object ids and light indices stay the scene's: [`World::object_scene_index`] and
//!   [`World::light_scene_index`] map the world's lists back to the scene's.

use crate::trace::shapes::MeshStore;
use glam::DVec3;
use std::collections::BTreeSet;

use super::compiled::{SurfacePoint, World};
use crate::scene::{Light, Scene, SceneError, validate};
use crate::trace::ray::Ray;
use crate::trace::terms::Isolation;

/// Why a scene cannot be rendered with some isolation switches.
#[derive(Debug, thiserror::Error)]
pub enum IsolationError {
    /// The scene itself is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A muted or solo light index past the end of the scene's lights.
    #[error("there is no light {index}: the scene has {}", count_text(*count, "light"))]
    NoSuchLight {
        /// The index asked for.
        index: usize,
        /// How many lights the scene has.
        count: usize,
    },
    /// A hidden object index past the end of the scene's objects.
    #[error("there is no object {index}: the scene has {}", count_text(*count, "object"))]
    NoSuchObject {
        /// The index asked for.
        index: usize,
        /// How many objects the scene has.
        count: usize,
    },
}

/// "no lights", "1 light (index 0)", "4 lights (indices 0 to 3)".
fn count_text(count: usize, noun: &str) -> String {
    match count {
        0 => format!("no {noun}s"),
        1 => format!("1 {noun} (index 0)"),
        n => format!("{n} {noun}s (indices 0 to {})", n - 1),
    }
}

/// The light whose solo shows the background: the first Ambient light, else the first
/// light; `None` in a scene without lights.
#[must_use]
pub fn background_light(lights: &[Light]) -> Option<usize> {
    lights
        .iter()
        .position(|l| matches!(l, Light::Ambient { .. }))
        .or_else(|| (!lights.is_empty()).then_some(0))
}

/// Whether rays that miss show the background under `isolation`: always without a solo,
/// else only when the solo lights include [`background_light`].
#[must_use]
pub fn shows_background(isolation: &Isolation, lights: &[Light]) -> bool {
    isolation.solo_lights.is_empty()
        || background_light(lights).is_some_and(|i| isolation.solo_lights.contains(&i))
}

/// Checks that every index of `isolation` names a light or object of `scene`.
///
/// # Errors
/// The first index past the end of its list.
pub fn check_indices(isolation: &Isolation, scene: &Scene) -> Result<(), IsolationError> {
    let lights = scene.lights.len();
    if let Some(&index) = isolation
        .muted_lights
        .iter()
        .chain(&isolation.solo_lights)
        .find(|&&i| i >= lights)
    {
        return Err(IsolationError::NoSuchLight {
            index,
            count: lights,
        });
    }
    let objects = scene.objects.len();
    if let Some(&index) = isolation.hidden_objects.iter().find(|&&i| i >= objects) {
        return Err(IsolationError::NoSuchObject {
            index,
            count: objects,
        });
    }
    Ok(())
}

/// Stops a render whose world was compiled for other isolation switches than its options
/// ask for: a caller's mistake that would otherwise show the wrong lights in silence.
///
/// # Panics
/// When `world.isolation` differs from `isolation`.
pub(crate) fn assert_compiled_for(world: &World, isolation: &Isolation) {
    assert!(
        world.isolation == *isolation,
        "the world was compiled with other isolation switches than the render asks for \
         (compile it with World::isolated)"
    );
}

impl World {
    /// Validates and compiles `scene` without the lights and objects `isolation` leaves
    /// out. With [`Isolation::NONE`] this is [`World::new`].
    ///
    /// # Errors
    /// The scene's first validation problem (named by the scene's own indices), or an
    /// index of `isolation` that the scene does not have.
    pub fn isolated(scene: &Scene, isolation: &Isolation) -> Result<Self, IsolationError> {
        Self::isolated_with_meshes(scene, isolation, &MeshStore::default())
    }

    /// As [`World::isolated`], with mesh objects' triangles from `meshes` (see
    /// [`World::with_meshes`]).
    ///
    /// # Errors
    /// As [`World::isolated`], or a mesh object whose file is not in `meshes`.
    pub fn isolated_with_meshes(
        scene: &Scene,
        isolation: &Isolation,
        meshes: &MeshStore,
    ) -> Result<Self, IsolationError> {
        if isolation.is_none() {
            return Ok(Self::with_meshes(scene, meshes)?);
        }
        validate(scene)?;
        check_indices(isolation, scene)?;
        let kept_objects: Vec<usize> = (0..scene.objects.len())
            .filter(|&i| isolation.is_object_shown(i))
            .collect();
        let kept_lights: Vec<usize> = (0..scene.lights.len())
            .filter(|&i| isolation.is_light_lit(i))
            .collect();
        let mut filtered = Scene {
            objects: kept_objects
                .iter()
                .map(|&i| scene.objects[i].clone())
                .collect(),
            lights: kept_lights
                .iter()
                .map(|&i| scene.lights[i].clone())
                .collect(),
            ..scene.clone()
        };
        hide_parts(
            &mut filtered.objects,
            &kept_objects,
            &isolation.hidden_parts,
        );
        let mut world = Self::with_meshes(&filtered, meshes)?;
        world.light_scene_index = world
            .light_scene_index
            .iter()
            .map(|&i| kept_lights[i])
            .collect();
        // A group's members carry their top-level object's index in the filtered scene.
        world.object_scene_index = world
            .object_scene_index
            .iter()
            .map(|&i| kept_objects[i])
            .collect();
        if !shows_background(isolation, &scene.lights) {
            world.background = DVec3::ZERO;
        }
        world.isolation = isolation.clone();
        Ok(world)
    }

    /// The scene's index of the world's object `index` (the object id).
    #[must_use]
    pub fn scene_object(&self, index: usize) -> usize {
        self.object_scene_index.get(index).copied().unwrap_or(index)
    }

    /// The world object a hit lies on, for a hit named by its scene index (as recorders
    /// see it): the one world object of that scene object, or among a group's members
    /// the one the ray meets at the hit's `t`. `None` when none does.
    #[must_use]
    pub fn world_object_of_hit(&self, ray: &Ray, hit: &SurfacePoint) -> Option<usize> {
        // Scene order is kept, so a scene object's world objects are consecutive.
        let first = self.object_scene_index.partition_point(|&s| s < hit.object);
        let end = self
            .object_scene_index
            .partition_point(|&s| s <= hit.object);
        match end - first {
            0 => None,
            1 => Some(first),
            _ => (first..end).find(|&i| {
                self.intersect_object(i, ray, f64::INFINITY)
                    .is_some_and(|again| again.t == hit.t)
            }),
        }
    }
}

/// Empties the hidden parts of `objects` (the kept top-level objects, `kept[k]` the
/// scene index of the `k`th): each becomes an empty group where it was, so it draws
/// nothing, takes no part in its CSG solid, and every other node keeps its path (picks
/// and the inspector name nodes by path).
fn hide_parts(objects: &mut [crate::scene::Object], kept: &[usize], hidden: &BTreeSet<Vec<usize>>) {
    for path in hidden.iter().filter(|p| p.len() >= 2) {
        let Ok(top) = kept.binary_search(&path[0]) else {
            continue; // its whole object is hidden
        };
        let moved = [&[top], &path[1..]].concat();
        if let Some(part) = crate::scene::tree::object_at_mut(objects, &moved) {
            part.shape = crate::scene::Shape::Group {
                children: Vec::new(),
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn scene() -> Scene {
        crate::scene::examples::default_scene()
    }

    #[test]
    fn the_world_leaves_out_what_is_isolated_and_keeps_the_scene_indices() {
        let scene = scene();
        let isolation = Isolation {
            muted_lights: BTreeSet::from([1]),
            hidden_objects: BTreeSet::from([0, 2]),
            ..Isolation::NONE
        };
        let world = World::isolated(&scene, &isolation).unwrap();
        assert_eq!(world.objects.len(), scene.objects.len() - 2);
        assert_eq!(world.object_scene_index, vec![1, 3, 4, 5]);
        assert_eq!(world.objects[0].name, scene.objects[1].name);
        assert_eq!(world.scene_object(2), 4);
        assert_eq!(world.light_scene_index, vec![2, 3], "light 0 is ambient");
        assert_eq!(world.ambient, scene.lights[0].strength());
        assert_eq!(world.background, scene.render.background);
        assert_eq!(world.isolation, isolation);
    }

    #[test]
    fn a_hit_named_by_its_scene_object_finds_its_world_object() {
        // Object 0 hidden, object 1 a group of two spheres side by side: world objects
        // are [sphere a, sphere b, the rest], scene indices [1, 1, 2, ...].
        let mut scene = scene();
        let sphere = |x: f64, name: &str| crate::scene::Object {
            name: name.to_owned(),
            shape: crate::scene::Shape::Sphere,
            transform: crate::scene::Transform::Trs(crate::scene::Trs {
                translate: DVec3::new(x, 50.0, 0.0),
                ..Default::default()
            }),
            material: scene.objects[0].material.clone(),
        };
        scene.objects[1] = crate::scene::Object {
            name: "pair".to_owned(),
            shape: crate::scene::Shape::Group {
                children: vec![sphere(-3.0, "a"), sphere(3.0, "b")],
            },
            transform: crate::scene::Transform::default(),
            material: String::new(),
        };
        let isolation = Isolation {
            hidden_objects: BTreeSet::from([0]),
            ..Isolation::NONE
        };
        let world = World::isolated(&scene, &isolation).unwrap();
        assert_eq!(&world.object_scene_index[..3], &[1, 1, 2]);
        for (x, expected) in [(-3.0, 0), (3.0, 1)] {
            let ray = Ray::new(DVec3::new(x, 50.0, 10.0), -DVec3::Z);
            let mut hit = world.intersect(&ray, f64::INFINITY).unwrap();
            hit.object = world.scene_object(hit.object);
            assert_eq!(hit.object, 1);
            assert_eq!(world.world_object_of_hit(&ray, &hit), Some(expected));
        }
        // A scene object that is the only one of its index maps straight to it.
        let ray = Ray::new(DVec3::new(-3.0, 50.0, 10.0), -DVec3::Z);
        let mut hit = world.intersect(&ray, f64::INFINITY).unwrap();
        hit.object = 2;
        assert_eq!(world.world_object_of_hit(&ray, &hit), Some(2));
        hit.object = 0;
        assert_eq!(world.world_object_of_hit(&ray, &hit), None, "hidden");
    }

    #[test]
    fn only_the_first_ambient_light_or_else_the_first_light_carries_the_background() {
        let mut scene = scene();
        let solo = |i: usize| Isolation {
            solo_lights: BTreeSet::from([i]),
            ..Isolation::NONE
        };
        scene.lights.push(scene.lights[0].clone());
        let background = |scene: &Scene, i| World::isolated(scene, &solo(i)).unwrap().background;
        assert_eq!(background(&scene, 0), scene.render.background);
        assert_eq!(background(&scene, 4), DVec3::ZERO, "a second ambient light");
        assert_eq!(background(&scene, 1), DVec3::ZERO);
        let solo_point = World::isolated(&scene, &solo(1)).unwrap();
        assert_eq!(solo_point.ambient, DVec3::ZERO);
        assert_eq!(solo_point.light_scene_index, vec![1]);
        scene.lights.retain(|l| !matches!(l, Light::Ambient { .. }));
        assert_eq!(background_light(&scene.lights), Some(0));
        assert_eq!(background(&scene, 0), scene.render.background);
        assert_eq!(background(&scene, 1), DVec3::ZERO);
        assert_eq!(background_light(&[]), None);
    }

    #[test]
    fn an_index_the_scene_lacks_is_a_clear_error() {
        let scene = scene();
        let bad_light = Isolation {
            solo_lights: BTreeSet::from([9]),
            ..Isolation::NONE
        };
        let message = World::isolated(&scene, &bad_light).unwrap_err().to_string();
        assert_eq!(
            message,
            "there is no light 9: the scene has 4 lights (indices 0 to 3)"
        );
        let bad_object = Isolation {
            hidden_objects: BTreeSet::from([6]),
            ..Isolation::NONE
        };
        let message = World::isolated(&scene, &bad_object)
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("no object 6") && message.contains("0 to 5"),
            "{message}"
        );
    }

    #[test]
    fn scene_errors_keep_the_scene_indices_and_hiding_everything_is_fine() {
        let mut scene = scene();
        scene.objects[3].material = "missing".to_owned();
        let isolation = Isolation {
            hidden_objects: BTreeSet::from([0]),
            ..Isolation::NONE
        };
        let message = World::isolated(&scene, &isolation).unwrap_err().to_string();
        assert!(message.contains("objects[3]"), "{message}");
        let scene = self::scene();
        let all = Isolation {
            hidden_objects: (0..scene.objects.len()).collect(),
            muted_lights: (0..scene.lights.len()).collect(),
            ..Isolation::NONE
        };
        let world = World::isolated(&scene, &all).unwrap();
        assert!(world.objects.is_empty() && world.lights.is_empty());
        assert_eq!(world.background, scene.render.background);
    }
}
