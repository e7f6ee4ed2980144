//! Random scenes made of what both raylab and a course dialect can say (the unit shapes,
//! transforms made of translate / rotate / scale, Phong materials, every light kind the
//! dialect has, any camera), exported and imported again: the export warns about
//! nothing, passes the course grammar, and comes back as the same scene (names, shapes,
//! materials, light strengths exactly; placements and the camera's view to float noise)
//! rendering the same PNG.

#[path = "common/course_grammar.rs"]
mod course_grammar;

use std::collections::BTreeMap;

use course_grammar::{Framework, check};
use glam::DVec3;
use proptest::prelude::*;
use raylab::scene::legacy::{Dialect, import_legacy, write_course_scene};
use raylab::scene::{
    Camera, Conventions, Light, LightSource, Material, Object, RenderSettings, Scene, Shape,
    Transform, Trs,
};
use raylab::trace::{RenderOptions, RenderProgress, World, render};

fn colour(max: f64) -> impl Strategy<Value = DVec3> {
    (0.0..=max, 0.0..=max, 0.0..=max).prop_map(|(r, g, b)| DVec3::new(r, g, b))
}

fn point(size: f64) -> impl Strategy<Value = DVec3> {
    (-size..size, -size..size, -size..size).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// An angle about X or Z: often a round one (as people type), else any, in the range
/// the importer's decomposition gives back, (-180, 180).
fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => (-11i32..=11).prop_map(|k| f64::from(k) * 15.0),
        1 => typed(-179.99, 179.99),
    ]
}

/// An angle about Y, in (-90, 90) as the decomposition gives it back (at +-90 only the
/// sum of the other two is defined).
fn middle_angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => (-5i32..=5).prop_map(|k| f64::from(k) * 15.0),
        1 => typed(-89.99, 89.99),
    ]
}

/// A number as people type it (two decimals), or any.
fn typed(low: f64, high: f64) -> impl Strategy<Value = f64> {
    let (l, h) = ((low * 100.0) as i32, (high * 100.0) as i32);
    prop_oneof![
        3 => (l..h).prop_map(|k| f64::from(k) / 100.0),
        1 => low..high,
    ]
}

fn typed_point(size: f64) -> impl Strategy<Value = DVec3> {
    (typed(-size, size), typed(-size, size), typed(-size, size))
        .prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn trs() -> impl Strategy<Value = Transform> {
    let scale = prop_oneof![
        typed(0.2, 3.0).prop_map(DVec3::splat),
        (typed(0.2, 3.0), typed(0.2, 3.0), typed(0.2, 3.0))
            .prop_map(|(x, y, z)| DVec3::new(x, y, z)),
    ];
    (typed_point(3.0), (angle(), middle_angle(), angle()), scale).prop_map(
        |(translate, (x, y, z), scale)| {
            Transform::Trs(Trs {
                translate,
                rotate_deg: DVec3::new(x, y, z),
                scale,
            })
        },
    )
}

fn material(dialect: Dialect) -> impl Strategy<Value = Material> {
    let glass = match dialect {
        // Grey transmission and an index: the 2020 extension's Opacity and RefractiveIndex.
        Dialect::Framework2020 => {
            prop_oneof![Just((0.0, 1.0)), (0.1..0.95f64, 1.0..2.0f64)].boxed()
        }
        Dialect::Framework2016 => Just((0.0, 1.0)).boxed(),
    };
    (
        colour(0.3),
        colour(1.0),
        colour(1.0),
        0.0..200.0f64,
        colour(0.6),
        glass,
    )
        .prop_map(
            |(ambient, diffuse, specular, shininess, mirror, (kt, ior))| Material {
                ambient,
                diffuse,
                specular,
                shininess,
                mirror,
                transmission: DVec3::splat(kt),
                ior,
            },
        )
}

fn shape(dialect: Dialect) -> impl Strategy<Value = Shape> {
    let base = vec![
        Shape::Sphere,
        Shape::Plane,
        Shape::Cube,
        Shape::Cylinder,
        Shape::Cone,
    ];
    match dialect {
        Dialect::Framework2016 => proptest::sample::select(base).boxed(),
        Dialect::Framework2020 => prop_oneof![
            proptest::sample::select(base),
            Just(Shape::Torus { minor: 0.5 }),
            Just(Shape::Octahedron),
            (0.05..0.95f64).prop_map(|inner| Shape::Tube { inner }),
        ]
        .boxed(),
    }
}

fn light(dialect: Dialect) -> BoxedStrategy<Light> {
    let point_light =
        (point(6.0), colour(2.0), 0.1..20.0f64).prop_map(|(position, colour, intensity)| {
            Light::Point {
                position,
                source: LightSource::point(colour, intensity),
            }
        });
    match dialect {
        Dialect::Framework2016 => point_light.boxed(),
        Dialect::Framework2020 => prop_oneof![
            point_light,
            (colour(1.0), 0.1..2.0f64)
                .prop_map(|(colour, intensity)| Light::Ambient { colour, intensity }),
            (point(1.0), colour(1.0)).prop_filter_map("a direction", |(direction, colour)| {
                (direction.length() > 0.1).then_some(Light::Directional {
                    direction,
                    colour,
                    intensity: 1.0,
                })
            }),
            (
                point(6.0),
                point(1.0),
                5.0..170.0f64,
                colour(2.0),
                (0.0..0.5f64, 1u32..8)
            )
                .prop_filter_map(
                    "a direction",
                    |(position, direction, angle_deg, colour, (radius, samples))| {
                        (direction.length() > 0.1).then_some(Light::Spot {
                            position,
                            direction,
                            angle_deg,
                            source: LightSource {
                                colour,
                                intensity: 3.0,
                                radius,
                                samples: if radius > 0.0 { samples } else { 1 },
                            },
                        })
                    },
                ),
        ]
        .boxed(),
    }
}

fn camera() -> impl Strategy<Value = Camera> {
    (
        point(8.0),
        point(1.0),
        15.0..100.0f64,
        (6u32..20, 6u32..20),
        any::<bool>(),
    )
        .prop_filter_map(
            "the eye away from the target, up off the view",
            |(position, look_at, fov_deg, (width, height), tilted)| {
                let view = look_at - position;
                let up = if tilted {
                    DVec3::new(0.3, 1.0, -0.2)
                } else {
                    DVec3::Y
                };
                (view.length() > 1.0 && view.normalize().cross(up.normalize()).length() > 0.1)
                    .then_some(Camera {
                        position,
                        look_at,
                        up,
                        fov_deg,
                        width,
                        height,
                    })
            },
        )
}

fn scene(dialect: Dialect) -> impl Strategy<Value = Scene> {
    let ambient_first = match dialect {
        // The 2016 framework's one ambient colour is read before the lights.
        Dialect::Framework2016 => proptest::option::of(colour(0.5)).boxed(),
        Dialect::Framework2020 => Just(None).boxed(),
    };
    (
        camera(),
        (0u32..6, colour(0.3)),
        proptest::collection::vec(material(dialect), 1..4),
        proptest::collection::vec((shape(dialect), trs(), 0usize..3, any::<bool>()), 1..5),
        (
            ambient_first,
            proptest::collection::vec(light(dialect), 0..4),
        ),
    )
        .prop_map(
            |(camera, (max_depth, background), materials, objects, (ambient, lights))| {
                let names: Vec<String> = (0..materials.len()).map(|i| format!("m{i}")).collect();
                let objects = objects
                    .into_iter()
                    .enumerate()
                    .map(|(i, (shape, transform, m, named))| Object {
                        name: if named {
                            format!("thing {i}")
                        } else {
                            format!("{} {i}", shape.name())
                        },
                        shape,
                        transform,
                        material: names[m % names.len()].clone(),
                    })
                    .collect();
                let lights = ambient
                    .map(|colour| Light::Ambient {
                        colour,
                        intensity: 1.0,
                    })
                    .into_iter()
                    .chain(lights)
                    .collect();
                Scene {
                    format: 1,
                    camera,
                    render: RenderSettings {
                        max_depth,
                        background,
                        samples_per_pixel: 1,
                        conventions: Conventions::COURSE,
                    },
                    materials: names.into_iter().zip(materials).collect::<BTreeMap<_, _>>(),
                    objects,
                    lights,
                }
            },
        )
}

fn png(scene: &Scene) -> Vec<u8> {
    let world = World::new(scene).expect("a valid scene");
    let options = RenderOptions::from_scene(scene);
    let (image, _) = render(&world, &options, &RenderProgress::default()).expect("not cancelled");
    image.png_bytes_as(scene.render.conventions.quantise)
}

/// Whether every object came back with the very same transform (round angles and
/// scales do; any angle comes back to float noise, checked in `assert_same_scene`, which
/// can move a pixel across an edge, so only then are the renders compared bit for bit).
fn same_placements(scene: &Scene, back: &Scene) -> bool {
    scene
        .objects
        .iter()
        .zip(&back.objects)
        .all(|(s, b)| s.transform.world_from_object() == b.transform.world_from_object())
}

/// `back` with `scene`'s camera: the camera comes back to float noise (checked in
/// `assert_same_scene`), which can move a pixel across an edge; everything else must
/// render the same to the bit.
fn with_camera(mut back: Scene, scene: &Scene) -> Scene {
    back.camera = scene.camera.clone();
    back
}

fn close(a: DVec3, b: DVec3, tolerance: f64) -> bool {
    (a - b).abs().max_element() <= tolerance * b.abs().max_element().max(1.0)
}

/// Exports `scene`, checks the text and imports it; the scene that comes back.
fn round_trip(
    scene: &Scene,
    dialect: Dialect,
    framework: Framework,
) -> Result<Scene, TestCaseError> {
    let written =
        write_course_scene(scene, dialect).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(written.warnings.is_empty(), "{:?}", written.warnings);
    check(&written.text, framework).map_err(TestCaseError::fail)?;
    let back = import_legacy(&written.text)
        .map_err(|e| TestCaseError::fail(format!("{e}\n{}", written.text)))?;
    Ok(back.scene)
}

fn assert_same_scene(scene: &Scene, back: &Scene) -> Result<(), TestCaseError> {
    // `Opacity a` says kt = 1 - a: below 0.5 that moves in steps of 1's last place, so
    // a transmission comes back to within half of one (else exactly).
    let mut materials = back.materials.clone();
    for (name, material) in &mut materials {
        let original = scene.materials[name].transmission;
        let moved = (material.transmission - original).abs().max_element();
        prop_assert!(moved <= f64::EPSILON / 2.0, "{}: {}", name, moved);
        material.transmission = original;
    }
    prop_assert_eq!(&materials, &scene.materials);
    prop_assert_eq!(back.render.max_depth, scene.render.max_depth);
    prop_assert_eq!(back.render.background, scene.render.background);
    prop_assert_eq!(back.objects.len(), scene.objects.len());
    for (b, s) in back.objects.iter().zip(&scene.objects) {
        prop_assert_eq!(&b.name, &s.name);
        prop_assert_eq!(&b.shape, &s.shape);
        prop_assert_eq!(&b.material, &s.material);
        let (bm, sm) = (
            b.transform.world_from_object(),
            s.transform.world_from_object(),
        );
        for (bc, sc) in [
            (bm.matrix3.x_axis, sm.matrix3.x_axis),
            (bm.matrix3.y_axis, sm.matrix3.y_axis),
            (bm.matrix3.z_axis, sm.matrix3.z_axis),
            (bm.translation, sm.translation),
        ] {
            prop_assert!(
                close(bc, sc, 1e-12),
                "{}: {:?} vs {:?}",
                s.name,
                b.transform,
                s.transform
            );
        }
    }
    let strengths = |s: &Scene| s.lights.iter().map(Light::strength).collect::<Vec<_>>();
    prop_assert_eq!(strengths(back), strengths(scene));
    let kinds = |s: &Scene| s.lights.iter().map(Light::kind_name).collect::<Vec<_>>();
    prop_assert_eq!(kinds(back), kinds(scene));
    let (b, s) = (&back.camera, &scene.camera);
    prop_assert_eq!((b.width, b.height), (s.width, s.height));
    prop_assert_eq!(b.position, s.position);
    let forward = |c: &Camera| (c.look_at - c.position).normalize();
    prop_assert!(close(forward(b), forward(s), 1e-12));
    prop_assert!((b.fov_deg - s.fov_deg).abs() < 1e-9);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn random_2020_scenes_come_back_the_same(scene in scene(Dialect::Framework2020)) {
        let back = round_trip(&scene, Dialect::Framework2020, Framework::Y2020)?;
        assert_same_scene(&scene, &back)?;
        if same_placements(&scene, &back) {
            prop_assert!(png(&with_camera(back, &scene)) == png(&scene), "the renders differ");
        }
    }

    #[test]
    fn random_2016_scenes_come_back_the_same(scene in scene(Dialect::Framework2016)) {
        let back = round_trip(&scene, Dialect::Framework2016, Framework::Y2016)?;
        assert_same_scene(&scene, &back)?;
        if same_placements(&scene, &back) {
            prop_assert!(png(&with_camera(back, &scene)) == png(&scene), "the renders differ");
        }
    }
}
