//! Numerically hard cases, each with an exact expectation: degenerate rays, rays that
//! start on or inside surfaces, and renders of touching and nearly coincident surfaces
//! checked for acne and light leaks.

mod common;

use common::*;
use glam::DVec3;
use raylab::scene::{Light, Material, Scene, Shape};
use raylab::trace::{Image, Ray, RenderOptions, RenderProgress, TermSwitches, View, World, render};

fn world_with(objects: Vec<raylab::scene::Object>) -> World {
    let mut scene = bare_scene(Material::default());
    scene.objects = objects;
    World::new(&scene).unwrap()
}

/// An upright unit cylinder of radius r, from y = 0 to y = h, at x = z = 0... placed off
/// the origin and scaled, as scenes do.
fn upright(shape: Shape, base: DVec3, radius: f64, height: f64) -> raylab::scene::Object {
    match shape {
        // Axis z -> y: rotate -90 about x; unit z in [-1, 1] becomes y in [base, base + h].
        Shape::Cylinder => object(
            shape,
            base + DVec3::Y * height * 0.5,
            DVec3::new(-90.0, 0.0, 0.0),
            DVec3::new(radius, radius, height * 0.5),
        ),
        // Apex up: rotate +90 about x takes +z to -y; the apex sits at base + h.
        Shape::Cone => object(
            shape,
            base + DVec3::Y * height,
            DVec3::new(90.0, 0.0, 0.0),
            DVec3::new(radius, radius, height),
        ),
        _ => unreachable!(),
    }
}

fn assert_close(actual: f64, expected: f64, tolerance: f64) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{actual} vs {expected} (tolerance {tolerance})"
    );
}

#[test]
fn ray_along_a_cylinders_axis_hits_the_cap_centre() {
    let base = DVec3::new(3.0, -2.0, 1.5);
    let world = world_with(vec![upright(Shape::Cylinder, base, 0.5, 2.0)]);
    let ray = Ray::new(base + DVec3::new(0.0, 7.0, 0.0), -DVec3::Y);
    let hit = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_close(hit.t, 5.0, 1e-14 * 7.0);
    assert_eq!(hit.n, DVec3::Y);
    assert!((hit.p - (base + DVec3::Y * 2.0)).length() <= hit.p_error.length());
    // From inside, along the axis: the bottom cap from above.
    let inside = Ray::new(base + DVec3::Y, -DVec3::Y);
    let hit = world.intersect(&inside, f64::INFINITY).unwrap();
    assert_close(hit.t, 1.0, 1e-14);
    assert_eq!(hit.n, DVec3::Y, "faces the ray coming down");
}

#[test]
fn ray_through_a_cones_apex_hits_the_apex_with_a_finite_normal() {
    let base = DVec3::new(-1.0, 0.0, 2.0);
    let world = world_with(vec![upright(Shape::Cone, base, 1.0, 2.0)]);
    let apex = base + DVec3::Y * 2.0;
    for dir in [
        -DVec3::Y,
        DVec3::new(0.3, -1.0, 0.2).normalize(),
        DVec3::new(1.0, -0.2, 0.0).normalize(),
    ] {
        let ray = Ray::new(apex - dir * 4.0, dir);
        let hit = world.intersect(&ray, f64::INFINITY).unwrap();
        assert_close(hit.t, 4.0, 1e-12);
        assert!((hit.p - apex).length() < 1e-12, "{}", hit.p);
        assert!(hit.n.is_finite() && (hit.n.length() - 1.0).abs() < 1e-12);
        assert!(hit.n.dot(dir) <= 0.0);
    }
}

#[test]
fn a_cone_seen_along_its_axis_has_no_bright_apex_pixel() {
    // Apex at the origin pointing at the eye on +z, lit from the eye: the centre pixel's
    // ray meets the apex exactly. Around the apex every normal is 45 degrees off the
    // axis; the apex must not be shaded with the axis (n.l = 1 against about 0.7).
    let mut scene = bare_scene(Material {
        diffuse: DVec3::ONE,
        ..Material::default()
    });
    scene.lights = vec![point_light(scene.camera.position, 12.5)];
    let rotate = DVec3::new(180.0, 0.0, 0.0);
    scene.objects = vec![object(Shape::Cone, DVec3::ZERO, rotate, DVec3::ONE)];
    let world = World::new(&scene).unwrap();
    let options = RenderOptions::from_scene(&scene);
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let luminance = |x: u32, y: u32| image.get(x, y).dot(glam::Vec3::ONE);
    let (w, h) = (options.width, options.height);
    let centre = glam::DVec2::new(f64::from(w) / 2.0, f64::from(h) / 2.0);
    let ray = raylab::trace::PinholeCamera::new(&scene.camera, w, h).ray(centre);
    let apex = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_eq!(apex.p, DVec3::ZERO, "the centre ray meets the apex");
    let (cx, cy) = (w / 2, h / 2);
    let brightest_neighbour = (cy - 1..=cy + 1)
        .flat_map(|y| (cx - 1..=cx + 1).map(move |x| (x, y)))
        .filter(|&p| p != (cx, cy))
        .map(|(x, y)| luminance(x, y))
        .fold(0.0f32, f32::max);
    assert!(brightest_neighbour > 0.1, "the neighbours are lit");
    // The neighbours lie a little farther and turn a little away from the light, so the
    // apex is a few percent brighter (1.07); with the axis as its normal it was 1.5.
    let apex_pixel = luminance(cx, cy);
    assert!(
        apex_pixel <= brightest_neighbour * 1.15,
        "apex {apex_pixel} against at most {brightest_neighbour} around it"
    );
}

#[test]
fn ray_parallel_to_a_cones_side_hits_once_at_the_exact_point() {
    // Unit cone (apex at origin, opening along +z), moved: a ray parallel to the generator
    // x = z meets the opposite generator x = -z at t = 0.25 (see the shape's unit test).
    let offset = DVec3::new(10.0, 20.0, 30.0);
    let world = world_with(vec![object(Shape::Cone, offset, DVec3::ZERO, DVec3::ONE)]);
    let ray = Ray::new(
        offset + DVec3::new(-0.5, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 1.0),
    );
    let hit = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_close(hit.t, 0.25, 1e-13);
    assert!((hit.p - (offset + DVec3::new(-0.25, 0.0, 0.25))).length() <= 1e-12);
    // A ray exactly on the side line (through the apex along a generator) grazes it:
    // no isolated hit, and never NaN.
    let grazing = Ray::new(
        offset + DVec3::new(-1.0, 0.0, -1.0),
        DVec3::new(1.0, 0.0, 1.0),
    );
    if let Some(hit) = world.intersect(&grazing, f64::INFINITY) {
        assert!(hit.p.is_finite() && hit.n.is_finite());
    }
}

#[test]
fn ray_tangent_to_a_sphere_touches_it_at_the_tangent_point() {
    let centre = DVec3::new(5.0, -3.0, 2.0);
    let world = world_with(vec![object(
        Shape::Sphere,
        centre,
        DVec3::ZERO,
        DVec3::splat(2.0),
    )]);
    let ray = Ray::new(centre + DVec3::new(-6.0, 2.0, 0.0), DVec3::X);
    let hit = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_close(hit.t, 6.0, 1e-7); // a double root: t is only known to sqrt(eps)
    assert!((hit.n - DVec3::Y).length() < 1e-7);
    // A hair outside: a clean miss.
    let miss = Ray::new(centre + DVec3::new(-6.0, 2.0 + 1e-9, 0.0), DVec3::X);
    assert!(world.intersect(&miss, f64::INFINITY).is_none());
}

/// A group's non-uniform scale over a rotated sphere shears it: the ellipsoid is 2 long
/// on x, though each axis of its matrix is about 1.58 long. Its bounding sphere must
/// hold the whole of it (a radius of the longest axis cut its ends off).
#[test]
fn a_sphere_sheared_by_its_groups_scale_is_hit_at_its_far_ends() {
    let scene = raylab::scene::parse_scene(
        r#"Scene(format: 1,
        camera: (position: (0.0, 0.0, 6.0), look_at: (0.0, 0.0, 0.0), up: (0.0, 1.0, 0.0), fov_deg: 45.0, width: 8, height: 8),
        materials: {"m": ()},
        objects: [(name: "g", shape: Group(children: [
            (name: "ball", shape: Sphere, transform: (rotate_deg: (0.0, 0.0, 45.0)), material: "m"),
        ]), transform: (scale: (2.0, 1.0, 1.0)))])"#,
    )
    .unwrap();
    let world = World::new(&scene).unwrap();
    for x in [1.9, -1.9, 1.999] {
        // The ellipsoid's surface above (x, 0): z = sqrt(1 - (x/2)^2).
        let z = (1.0 - (x / 2.0f64).powi(2)).sqrt();
        let ray = Ray::new(DVec3::new(x, 0.0, 6.0), DVec3::NEG_Z);
        let hit = world.intersect(&ray, f64::INFINITY);
        let hit = hit.unwrap_or_else(|| panic!("the ray at x = {x} misses"));
        assert_close(hit.p.z, z, 1e-9);
    }
}

#[test]
fn ray_exactly_through_a_cap_rim_hits_at_the_rim() {
    let base = DVec3::new(0.0, 1.0, 0.0);
    let world = world_with(vec![upright(Shape::Cylinder, base, 1.0, 2.0)]);
    // Diagonally through the top rim at (1, 3, 0), from outside above.
    let rim = base + DVec3::new(1.0, 2.0, 0.0);
    let dir = DVec3::new(-1.0, -1.0, 0.0).normalize();
    let ray = Ray::new(rim - dir * 3.0, dir);
    let hit = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_close(hit.t, 3.0, 1e-12);
    assert!((hit.p - rim).length() < 1e-12);
    assert!(hit.n.is_finite() && hit.n.dot(dir) <= 0.0);
}

#[test]
fn ray_starting_on_a_surface_does_not_hit_that_surface() {
    let world = world_with(vec![object(
        Shape::Sphere,
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::ZERO,
        DVec3::splat(2.0),
    )]);
    let on_surface = DVec3::new(1.0, 2.0, 3.0) + DVec3::new(0.6, 0.0, 0.8) * 2.0;
    // Outward: nothing else to hit.
    assert!(
        world
            .intersect(
                &Ray::new(on_surface, DVec3::new(0.6, 0.0, 0.8)),
                f64::INFINITY
            )
            .is_none()
    );
    // Tangential: nothing.
    assert!(
        world
            .intersect(&Ray::new(on_surface, DVec3::Y), f64::INFINITY)
            .is_none()
    );
    // Inward: the far side, 4 units away along the diameter.
    let hit = world
        .intersect(
            &Ray::new(on_surface, DVec3::new(-0.6, 0.0, -0.8)),
            f64::INFINITY,
        )
        .unwrap();
    assert_close(hit.t, 4.0, 1e-12);
    // Same for a floor: a ray starting on it and leaving does not see it.
    let world = world_with(vec![floor(0.5, 10.0)]);
    let start = DVec3::new(0.3, 0.5, -0.7);
    assert!(
        world
            .intersect(&Ray::new(start, DVec3::new(0.2, 1.0, 0.1)), f64::INFINITY)
            .is_none()
    );
    assert!(
        world
            .intersect(&Ray::new(start, DVec3::new(0.2, -1.0, 0.1)), f64::INFINITY)
            .is_none()
    );
}

#[test]
fn ray_starting_inside_hits_the_inside_with_the_normal_facing_it() {
    let world = world_with(vec![object(
        Shape::Cube,
        DVec3::new(0.0, 0.0, -10.0),
        DVec3::new(0.0, 45.0, 0.0),
        DVec3::splat(2.0),
    )]);
    let ray = Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Y);
    let hit = world.intersect(&ray, f64::INFINITY).unwrap();
    assert_close(hit.t, 2.0, 1e-12);
    assert!((hit.n - -DVec3::Y).length() < 1e-12);
    assert!((hit.n_outward - DVec3::Y).length() < 1e-12);
}

/// A 96x72 render and its object ids.
fn render_with_ids(scene: &Scene) -> (Image, Image) {
    let world = World::new(scene).unwrap();
    let options = |view| RenderOptions {
        width: 96,
        height: 72,
        samples_per_pixel: 1,
        switches: TermSwitches::ALL_ON,
        view,
        isolation: Default::default(),
    };
    let progress = RenderProgress::default();
    (
        render(&world, &options(View::Beauty), &progress).unwrap().0,
        render(&world, &options(View::ObjectId), &progress)
            .unwrap()
            .0,
    )
}

/// Pixels much darker than all their same-object neighbours: acne and speckles.
fn isolated_dark_pixels(beauty: &Image, ids: &Image) -> Vec<(u32, u32)> {
    let luminance = |x: u32, y: u32| beauty.get(x, y).dot(glam::Vec3::splat(1.0 / 3.0));
    let mut found = Vec::new();
    for y in 1..beauty.height - 1 {
        for x in 1..beauty.width - 1 {
            let id = ids.get(x, y);
            let neighbours: Vec<(u32, u32)> = (-1i32..=1)
                .flat_map(|dy| (-1i32..=1).map(move |dx| (dx, dy)))
                .filter(|&d| d != (0, 0))
                .map(|(dx, dy)| ((x as i32 + dx) as u32, (y as i32 + dy) as u32))
                .collect();
            if id == glam::Vec3::ZERO || neighbours.iter().any(|&(nx, ny)| ids.get(nx, ny) != id) {
                continue;
            }
            let darkest_neighbour = neighbours
                .iter()
                .map(|&(nx, ny)| luminance(nx, ny))
                .fold(f32::INFINITY, f32::min);
            if darkest_neighbour > 0.05 && luminance(x, y) < 0.6 * darkest_neighbour {
                found.push((x, y));
            }
        }
    }
    found
}

fn contact_scene(objects: Vec<raylab::scene::Object>) -> Scene {
    let mut scene = bare_scene(Material {
        ambient: DVec3::splat(0.1),
        diffuse: DVec3::splat(0.7),
        specular: DVec3::splat(0.3),
        shininess: 20.0,
        ..Material::default()
    });
    scene.camera.position = DVec3::new(0.0, 2.5, 6.0);
    scene.camera.look_at = DVec3::new(0.0, 0.5, 0.0);
    scene.camera.fov_deg = 35.0;
    scene.lights = vec![
        Light::Ambient {
            colour: DVec3::ONE,
            intensity: 1.0,
        },
        point_light(DVec3::new(2.0, 6.0, 3.0), 40.0),
        Light::Directional {
            direction: DVec3::new(-0.3, -1.0, -0.2),
            colour: DVec3::splat(0.4),
            intensity: 1.0,
        },
    ];
    scene.objects = objects;
    scene
}

fn assert_clean(name: &str, scene: &Scene) {
    let (beauty, ids) = render_with_ids(scene);
    let acne = isolated_dark_pixels(&beauty, &ids);
    assert!(acne.is_empty(), "{name}: isolated dark pixels at {acne:?}");
}

#[test]
fn sphere_resting_on_a_plane_has_no_acne_and_a_dark_contact() {
    let scene = contact_scene(vec![
        floor(0.0, 6.0),
        object(Shape::Sphere, DVec3::Y, DVec3::ZERO, DVec3::ONE),
    ]);
    assert_clean("sphere on plane", &scene);
    // Right beside the contact point, under the sphere, the floor is in shadow of both
    // lights: only ambient (0.1 * 1) remains; never light leaking under the ball.
    let mut switches = TermSwitches::ALL_ON;
    switches.solo = Some(raylab::trace::Term::Diffuse);
    let under = Ray::new(DVec3::new(0.05, 0.001, 0.0), DVec3::new(0.0, -1.0, 0.0));
    assert_eq!(trace(&scene, under, switches), DVec3::ZERO);
}

#[test]
fn cylinder_standing_on_its_cap_has_no_acne() {
    assert_clean(
        "cylinder on floor",
        &contact_scene(vec![
            floor(0.0, 6.0),
            upright(Shape::Cylinder, DVec3::ZERO, 0.7, 1.5),
        ]),
    );
}

#[test]
fn cone_with_its_apex_on_the_floor_has_no_acne() {
    // Apex down: rotate -90 about x takes +z to +y; the apex sits on the floor.
    let cone = object(
        Shape::Cone,
        DVec3::ZERO,
        DVec3::new(-90.0, 0.0, 0.0),
        DVec3::new(0.8, 0.8, 1.6),
    );
    assert_clean(
        "cone on its apex",
        &contact_scene(vec![floor(0.0, 6.0), cone]),
    );
}

#[test]
fn tori_lying_and_standing_on_the_floor_have_no_acne() {
    // Lying flat (axis up, resting on its underside) and standing on its rim; and a
    // spindle torus, whose surface meets itself at the axis.
    let lying = object(
        Shape::Torus { minor: 0.3 },
        DVec3::new(-1.2, 0.3, 0.0),
        DVec3::new(-90.0, 0.0, 0.0),
        DVec3::ONE,
    );
    let standing = object(
        Shape::Torus { minor: 0.25 },
        DVec3::new(1.2, 0.75 * 1.25, 0.0),
        DVec3::new(0.0, 30.0, 0.0),
        DVec3::splat(0.75),
    );
    let spindle = object(
        Shape::Torus { minor: 1.4 },
        DVec3::new(0.0, 0.56, -1.5),
        DVec3::new(-90.0, 0.0, 0.0),
        DVec3::splat(0.4),
    );
    assert_clean(
        "tori on the floor",
        &contact_scene(vec![floor(0.0, 6.0), lying, standing, spindle]),
    );
}

#[test]
fn tubes_standing_and_lying_on_the_floor_have_no_acne() {
    // Standing on a ring, seen into its hole; lying on its outer barrel, its hole wide
    // enough to span several pixels (a one-pixel view into a dark hole is not acne).
    let standing = object(
        Shape::Tube { inner: 0.6 },
        DVec3::new(-1.0, 0.6, 0.0),
        DVec3::new(-90.0, 0.0, 0.0),
        DVec3::new(0.8, 0.8, 0.6),
    );
    let lying = object(
        Shape::Tube { inner: 0.7 },
        DVec3::new(1.2, 0.5, 0.0),
        DVec3::new(0.0, 60.0, 0.0),
        DVec3::new(0.5, 0.5, 0.9),
    );
    assert_clean(
        "tubes on the floor",
        &contact_scene(vec![floor(0.0, 6.0), standing, lying]),
    );
}

#[test]
fn an_octahedron_on_its_vertex_has_no_acne() {
    let octahedron = object(
        Shape::Octahedron,
        DVec3::new(0.0, 0.9, 0.0),
        DVec3::new(0.0, 20.0, 0.0),
        DVec3::splat(0.9),
    );
    assert_clean(
        "octahedron on its vertex",
        &contact_scene(vec![floor(0.0, 6.0), octahedron]),
    );
}

#[test]
fn two_planes_a_ten_thousandth_apart_never_fight() {
    let mut top = floor(1e-4, 1.2);
    top.material = "top".into();
    let mut scene = contact_scene(vec![floor(0.0, 6.0), top]);
    scene.materials.insert(
        "top".into(),
        Material {
            ambient: DVec3::new(0.1, 0.0, 0.0),
            diffuse: DVec3::new(0.8, 0.1, 0.1),
            ..Material::default()
        },
    );
    assert_clean("two planes", &scene);
    // Every camera ray that meets the top square sees the top square, not the floor.
    let world = World::new(&scene).unwrap();
    let camera = raylab::trace::PinholeCamera::new(&scene.camera, 96, 72);
    let mut seen = 0;
    for y in 0..72 {
        for x in 0..96 {
            let ray = camera.ray(glam::DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
            let Some(hit) = world.intersect(&ray, f64::INFINITY) else {
                continue;
            };
            if hit.p.x.abs() < 1.15 && hit.p.z.abs() < 1.15 {
                assert_eq!(
                    hit.object, 1,
                    "floor seen through the top plane at pixel ({x}, {y})"
                );
                seen += 1;
            }
        }
    }
    assert!(seen > 100);
    // And the floor right under the top plane is shadowed from the light above (no leak
    // through the 1e-4 gap).
    let under = Ray::new(DVec3::new(0.2, 0.00005, 0.3), -DVec3::Y);
    let mut solo = TermSwitches::ALL_ON;
    solo.solo = Some(raylab::trace::Term::Diffuse);
    assert_eq!(trace(&scene, under, solo), DVec3::ZERO);
}
