//! The split under a convention the other picture follows, made from the first split
//! (`Components::split_again`: it keeps the pixels whose samples fold alike under both
//! conventions and traces only the others), is the split made from scratch, bit for bit:
//! under every other mirror and clamp convention, from the scene's own and from the
//! course's, and at another depth limit. The scene has what changes a sample's colour
//! under the conventions (mirrors, a bright ball each-ray clamping changes, glass) and
//! what the split traces again (objects that might be missing; with a spot light added,
//! its cone bugs), so kept and traced pixels both occur.

use raylab::compare::{Components, render_components};
use raylab::scene::{ClampConvention, Conventions, MirrorConvention, Scene, parse_scene};
use raylab::trace::{RenderProgress, World};

const SCENE: &str = r#"Scene(
    camera: (position: (0.0, 1.5, 6.0), look_at: (0.0, 1.0, 0.0), fov_deg: 60.0, width: 48, height: 36),
    render: (max_depth: 4, background: (0.2, 0.3, 0.4), samples_per_pixel: 2),
    materials: {
        "floor": (ambient: (0.2, 0.2, 0.2), diffuse: (0.6, 0.6, 0.6)),
        "mirror": (ambient: (0.1, 0.1, 0.1), diffuse: (0.3, 0.2, 0.1), specular: (0.9, 0.9, 0.9), shininess: 20.0, mirror: (0.8, 0.7, 0.9)),
        "bright": (ambient: (0.9, 0.5, 0.2), diffuse: (1.5, 0.9, 0.4), specular: (1.0, 1.0, 1.0), shininess: 10.0),
        "matte": (ambient: (0.1, 0.1, 0.1), diffuse: (0.2, 0.4, 0.3)),
        "glass": (ambient: (0.0, 0.0, 0.0), diffuse: (0.1, 0.1, 0.1), transmission: (0.8, 0.9, 0.8), ior: 1.5),
    },
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (10.0, 10.0, 1.0)), material: "floor"),
        (name: "left", shape: Plane, transform: (translate: (-3.0, 1.0, 0.0), rotate_deg: (0.0, 90.0, 0.0), scale: (5.0, 3.0, 1.0)), material: "mirror"),
        (name: "ball", shape: Sphere, transform: (translate: (-0.8, 1.0, 0.0), scale: (0.7, 0.7, 0.7)), material: "bright"),
        (name: "dull", shape: Sphere, transform: (translate: (1.8, 0.6, -0.5), scale: (0.6, 0.6, 0.6)), material: "matte"),
        (name: "lens", shape: Sphere, transform: (translate: (0.6, 0.8, 1.5), scale: (0.4, 0.4, 0.4)), material: "glass"),
    ],
    lights: [
        Ambient(colour: (0.3, 0.3, 0.3)),
        Point(position: (0.0, 5.0, 3.0), colour: (1.0, 1.0, 1.0), intensity: 30.0),
    ],
)"#;

/// A spot light for [`SCENE`].
const SPOT: &str = "Spot(position: (2.5, 4.0, 1.0), direction: (-0.2, -1.0, -0.3), angle_deg: 12.0, colour: (1.0, 0.9, 0.8), intensity: 20.0),";

/// [`SCENE`], and with [`SPOT`] added.
fn scenes() -> [Scene; 2] {
    let plain = parse_scene(SCENE).unwrap();
    let lit = SCENE.replace(
        "    ],
)",
        &format!(
            "        {SPOT}
    ],
)"
        ),
    );
    let spot = parse_scene(&lit).unwrap();
    assert_eq!(spot.lights.len(), plain.lights.len() + 1);
    [plain, spot]
}

/// `scene` under `conventions` and `max_depth`, compiled.
fn under(scene: &Scene, conventions: Conventions, max_depth: u32) -> (Scene, World) {
    let mut scene = scene.clone();
    scene.render.conventions = conventions;
    scene.render.max_depth = max_depth;
    let world = World::new(&scene).unwrap();
    (scene, world)
}

fn split(scene: &Scene, world: &World) -> Components {
    let size = (scene.camera.width, scene.camera.height);
    let spp = scene.render.samples_per_pixel;
    render_components(scene, world, size, spp, &RenderProgress::default()).unwrap()
}

/// Bits of each float, so that a -0.0 for a 0.0 or another NaN shows.
fn bits(values: &[[f64; 3]]) -> Vec<[u64; 3]> {
    values.iter().map(|v| v.map(f64::to_bits)).collect()
}

/// The two lists are equal; else the first place they differ.
fn assert_same_list<T: PartialEq + std::fmt::Debug>(again: &[T], fresh: &[T], what: &str) {
    assert_eq!(again.len(), fresh.len(), "lengths of {what}");
    if let Some(i) = (0..again.len()).find(|&i| again[i] != fresh[i]) {
        panic!(
            "{what}: at {i}, {:?} made again, {:?} from scratch",
            again[i], fresh[i]
        );
    }
}

/// Every field of the two splits, bit for bit.
fn assert_same(again: &Components, fresh: &Components, what: &str) {
    assert_same_list(
        &bits(&again.beauty),
        &bits(&fresh.beauty),
        &format!("beauty, {what}"),
    );
    assert_same_list(&again.labels, &fresh.labels, &format!("labels, {what}"));
    assert_same_list(&again.mixed, &fresh.mixed, &format!("mixed, {what}"));
    assert_same_list(&again.behind, &fresh.behind, &format!("behind, {what}"));
    assert_same_list(&again.offsets, &fresh.offsets, &format!("offsets, {what}"));
    let entries = |c: &Components| -> Vec<(u32, [u32; 3])> {
        c.entries
            .iter()
            .map(|e| (e.channel, e.value.map(f32::to_bits)))
            .collect()
    };
    assert_same_list(
        &entries(again),
        &entries(fresh),
        &format!("entries, {what}"),
    );
    let split =
        |c: &Components| -> Vec<[u64; 2]> { c.split.iter().map(|s| s.map(f64::to_bits)).collect() };
    assert_same_list(
        &split(again),
        &split(fresh),
        &format!("normal bugs' split, {what}"),
    );
    assert_eq!(again.rays, fresh.rays, "rays, {what}");
    assert_same_list(&again.fold, &fresh.fold, &format!("fold flags, {what}"));
    assert_eq!(again.folded_under, fresh.folded_under, "{what}");
}

#[test]
fn the_split_made_again_under_other_conventions_is_the_split_made_from_scratch() {
    for scene in scenes() {
        split_again_is_split_from_scratch(&scene);
    }
}

/// Splits `scene` under the scene's conventions and the course's, then again under each
/// other reading, and compares with the split from scratch.
fn split_again_is_split_from_scratch(scene: &Scene) {
    let depth = scene.render.max_depth;
    let (mut kept_objects, mut traced) = (0, 0);
    for own in [Conventions::default(), Conventions::COURSE] {
        let (first_scene, first_world) = under(scene, own, depth);
        let first = split(&first_scene, &first_world);
        let mut readings = vec![(own, 12)];
        for mirror in [MirrorConvention::Add, MirrorConvention::Blend] {
            for clamp in [ClampConvention::Pixel, ClampConvention::EachRay] {
                let other = Conventions {
                    mirror,
                    clamp,
                    ..own
                };
                if other != own {
                    readings.push((other, depth));
                }
            }
        }
        for (conventions, max_depth) in readings {
            let what = format!("{own:?} -> {conventions:?} at depth {max_depth}");
            let (scene, world) = under(scene, conventions, max_depth);
            let again = first
                .split_again(&scene, &world, &RenderProgress::default())
                .unwrap();
            assert_same(&again, &split(&scene, &world), &what);
            let kept: Vec<usize> = (0..first.fold.len())
                .filter(|&p| first.fold[p].same_under(first.folded_under, again.folded_under))
                .collect();
            if max_depth != depth {
                assert!(kept.is_empty(), "another depth keeps nothing: {what}");
            }
            // Pixels showing an object (not only the background) were kept.
            kept_objects += kept.iter().filter(|&&p| first.labels[p] != MISS).count();
            traced += first.fold.len() - kept.len();
        }
    }
    // Both paths were taken: pixels kept from the first split and pixels traced again.
    assert!(kept_objects > 1000, "kept {kept_objects} pixels of objects");
    assert!(traced > 1000, "traced {traced}");
}

/// The label of a pixel whose first sample hit nothing.
const MISS: u32 = u32::MAX;

#[test]
fn a_cancelled_split_again_gives_nothing() {
    let [scene, _] = scenes();
    let (own_scene, own_world) = under(&scene, Conventions::default(), 4);
    let first = split(&own_scene, &own_world);
    let blend = Conventions {
        mirror: MirrorConvention::Blend,
        ..Conventions::default()
    };
    let (scene, world) = under(&scene, blend, 4);
    let progress = RenderProgress::default();
    progress.cancel();
    assert!(first.split_again(&scene, &world, &progress).is_none());
}
