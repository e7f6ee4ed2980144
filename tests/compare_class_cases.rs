//! The diff on the cases a class writes that it used to get wrong: a missing light
//! beside a mirror (read as the course's conventions before the joint fit), spot lights
//! without cone and fall-off on several lights at once (a saturated picture), and a
//! tracer that never lets an object shadow itself. Each student picture comes from the
//! independent test shader (tests/compare/shader.rs), not from raylab's own models.

#[path = "compare/one_sample.rs"]
mod one_sample;
#[path = "compare/shader.rs"]
mod shader;

use one_sample::diff;
use raylab::compare::{Cause, ClampBug, ExplainedTerm, ShadowBug, SpawnBug, SpotBug};
use raylab::scene::{Light, load_scene};
use raylab::trace::Term;
use shader::{Bugs, render};

fn example(name: &str) -> raylab::scene::Scene {
    at_quarter_size(&format!("scenes/{name}"))
}

/// The scene at `path` (from the crate's folder) at a quarter of its size.
fn at_quarter_size(path: &str) -> raylab::scene::Scene {
    let mut scene = at_half_size(path);
    scene.camera.width /= 2;
    scene.camera.height /= 2;
    scene
}

/// The scene at `path` (from the crate's folder) at half its size.
fn at_half_size(path: &str) -> raylab::scene::Scene {
    let path = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    let mut scene = load_scene(std::path::Path::new(&path)).unwrap();
    scene.camera.width /= 2;
    scene.camera.height /= 2;
    scene
}

/// `scene` rendered by the test shader at 1 sample with `bugs`, diffed: the
/// comparison and its report.
fn student_diff(scene: &raylab::scene::Scene, bugs: Bugs) -> (raylab::compare::Comparison, String) {
    let c = diff(scene, &render(scene, 1, &bugs));
    let report = c.text_lines().join("\n");
    (c, report)
}

/// `default.ron` rendered by the test shader at `spp` samples with its directional
/// light left out, diffed: the comparison and its report. The diff
/// must name the light first, as missing.
fn missing_directional_light(spp: u32) -> (raylab::compare::Comparison, String) {
    let scene = example("default.ron");
    let directional = scene
        .lights
        .iter()
        .position(|l| matches!(l, Light::Directional { .. }))
        .unwrap();
    let other = render(
        &scene,
        spp,
        &Bugs {
            drop_light: Some(directional),
            ..Bugs::default()
        },
    );
    let c = diff(&scene, &other);
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert_eq!(first.cause, Cause::Factor, "{report}");
    assert_eq!(first.light, Some(directional), "{report}");
    (c, report)
}

#[test]
fn a_missing_light_beside_a_mirror_is_a_missing_light_not_a_convention() {
    let (c, report) = missing_directional_light(1);
    let first = &c.explanations[0];
    assert!(first.factor < 0.05, "{report}");
    assert!(
        c.explanations
            .iter()
            .all(|e| e.term != ExplainedTerm::Conventions),
        "{report}"
    );
}

#[test]
fn spots_without_cone_and_falloff_on_every_light_are_named_in_a_saturated_picture() {
    let scene = example("spotlights.ron");
    let other = render(
        &scene,
        1,
        &Bugs {
            spots_without_cone_or_falloff: true,
            ..Bugs::default()
        },
    );
    let white = other.rgb.iter().filter(|p| **p == [255, 255, 255]).count();
    assert!(
        white * 3 > other.rgb.len(),
        "the picture saturates: {white} white pixels"
    );
    let c = diff(&scene, &other);
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert_eq!(
        first.cause,
        Cause::Spot(SpotBug::NoConeNoFalloff),
        "{report}"
    );
    assert_eq!(first.light, None, "every spot light at once: {report}");
}

#[test]
fn an_object_that_never_shadows_itself_is_named() {
    let scene = example("csg.ron");
    let (c, report) = student_diff(
        &scene,
        Bugs {
            no_self_shadow: true,
            ..Bugs::default()
        },
    );
    let first = &c.explanations[0];
    assert_eq!(
        first.cause,
        Cause::ShadowTest(ShadowBug::NoSelfShadow),
        "{report}"
    );
    assert_eq!(first.term, ExplainedTerm::Term(Term::Shadows), "{report}");
}

/// Whether `cause` claims a bug (as opposed to saying where, or how the picture was
/// written or sampled).
fn claims_a_bug(cause: Cause) -> bool {
    !matches!(
        cause,
        Cause::Sampling | Cause::Silhouette | Cause::Shading | Cause::Encoding(_)
    )
}

#[test]
fn a_correct_anti_aliased_render_draws_no_verdict_but_sampling() {
    for name in ["default.ron", "spotlights.ron", "shapes.ron"] {
        let scene = example(name);
        // The student's tracer is right but takes 4 samples per pixel; the diff, at 1,
        // sees every edge differ by whole colours.
        let other = render(&scene, 4, &Bugs::default());
        let c = diff(&scene, &other);
        let report = c.text_lines().join("\n");
        assert!(
            c.explanations.iter().all(|e| !claims_a_bug(e.cause)),
            "{name}: {report}"
        );
        assert_eq!(c.explanations[0].cause, Cause::Sampling, "{name}: {report}");
    }
}

#[test]
fn a_bug_under_anti_aliasing_is_still_named() {
    let (c, report) = missing_directional_light(4);
    assert!(c.explanations[0].factor < 0.05, "{report}");
}

/// The scene's picture with `bugs` planted (as `raylab render --bug` takes them).
fn planted(scene: &raylab::scene::Scene, bugs: &str) -> raylab::compare::OtherImage {
    let bugs = raylab::compare::plant::parse_bugs(bugs, scene).unwrap();
    raylab::compare::plant::plant(
        scene,
        &raylab::trace::MeshStore::default(),
        &bugs,
        1,
        &raylab::trace::RenderProgress::default(),
    )
    .unwrap()
}

#[test]
fn the_last_light_skipped_and_the_ambient_per_light_are_named_as_loop_bugs() {
    let scene = example("default.ron");
    let c = diff(&scene, &planted(&scene, "last-light-skipped"));
    let first = &c.explanations[0];
    assert_eq!(
        first.light,
        Some(scene.lights.len() - 1),
        "{:#?}",
        c.text_lines()
    );
    assert!(
        first.summary.contains("the last light"),
        "{}",
        first.summary
    );

    let c = diff(&scene, &planted(&scene, "ambient-per-light"));
    let first = &c.explanations[0];
    assert_eq!(
        first.term,
        ExplainedTerm::Term(Term::Ambient),
        "{:#?}",
        c.text_lines()
    );
    assert!(
        first.summary.contains("once per light"),
        "{}",
        first.summary
    );

    let c = diff(&scene, &planted(&scene, "last-object-skipped"));
    let first = &c.explanations[0];
    assert_eq!(
        first.node,
        vec![scene.objects.len() - 1],
        "{:#?}",
        c.text_lines()
    );
    assert!(first.summary.contains("last object"), "{}", first.summary);
}

/// Plants `spot-no-falloff` on `scene`'s point light and checks the diff names it first,
/// on that light.
fn point_light_falloff_is_named_first(scene: &raylab::scene::Scene) {
    let point = scene
        .lights
        .iter()
        .position(|l| matches!(l, Light::Point { .. }))
        .expect("the scene has a point light");
    let c = diff(scene, &planted(scene, &format!("spot-no-falloff@{point}")));
    let first = &c.explanations[0];
    assert_eq!(
        first.cause,
        Cause::Spot(SpotBug::NoFalloff),
        "{:#?}",
        c.text_lines()
    );
    assert_eq!(first.light, Some(point), "{:#?}", c.text_lines());
}

#[test]
fn a_point_light_without_its_falloff_is_named() {
    point_light_falloff_is_named_first(&example("default.ron"));
}

/// Whether an explanation of `c` names `cause` (as the diff names causes).
fn names(c: &raylab::compare::Comparison, cause: &str) -> bool {
    c.explanations.iter().any(|e| e.cause.name() == cause)
}

#[test]
fn a_bug_on_a_few_pixels_beside_a_larger_one_is_named() {
    // Acne on the cylinder changes a handful of pixels; the second light's diffuse at
    // half changes most of the picture. The acne's share of the whole is far below the
    // search's share floor, but it makes its own pixels right.
    let scene = example("shapes.ron");
    let c = diff(
        &scene,
        &planted(&scene, "shadow-acne@cylinder,diffuse=0.5@1"),
    );
    let report = c.text_lines().join("\n");
    assert!(names(&c, "shadow-acne"), "{report}");
    assert!(names(&c, "factor"), "{report}");
}

/// The random scene of tuning seed 2 (`raylab bench --diff-accuracy --tuning`): a floor
/// under a directional, a spot and a point light of several colours.
fn coloured_lights_scene() -> raylab::scene::Scene {
    raylab::bench::random_scene::random_scene(2, 200, 150)
}

#[test]
fn an_extra_ball_under_several_coloured_lights_is_an_extra_object() {
    // Every colour is some lighting of the floor under those lights, so the first
    // reading called the ball "shading varies across 'floor'"; the stricter one finds it.
    let scene = coloured_lights_scene();
    let c = diff(&scene, &planted(&scene, "extra-object"));
    let report = c.text_lines().join("\n");
    assert_eq!(c.explanations[0].cause.name(), "extra-object", "{report}");
}

#[test]
fn a_light_without_falloff_that_whitens_the_floor_is_named() {
    // The point light without its fall-off clips most of the picture to white, where
    // the linear fit sees nothing; the spot bugs are then tried on the clipped bytes.
    point_light_falloff_is_named_first(&coloured_lights_scene());
}

#[test]
fn a_mirror_ray_started_on_the_wrong_side_is_named() {
    // The student's tracer starts each mirror ray 1e-4 under the surface it leaves: it
    // meets that surface again from behind, so the ball and the floor reflect their own
    // unlit insides. Read as the reflection term missing before the cause was known.
    let scene = example("default.ron");
    let (c, report) = student_diff(
        &scene,
        Bugs {
            mirror_wrong_side: true,
            ..Bugs::default()
        },
    );
    assert_eq!(
        c.explanations[0].cause,
        Cause::Spawn(SpawnBug::MirrorWrongSide),
        "{report}"
    );
}

#[test]
fn reflections_kept_as_bytes_between_rays_are_named() {
    // Each reflected ray's colour cut to floor(255 c) / 255: a level or less per bounce,
    // up to three levels where mirrors face each other. The scene clamps each ray as
    // the course does, so the clamp alone explains nothing.
    let scene = at_quarter_size("tests/compare/facing_mirrors.ron");
    let (c, report) = student_diff(
        &scene,
        Bugs {
            truncate_each_ray: true,
            ..Bugs::default()
        },
    );
    assert_eq!(
        c.explanations[0].cause,
        Cause::Clamp(ClampBug::TruncateEachRay),
        "{report}"
    );
}

#[test]
fn a_missing_light_is_one_line_for_its_diffuse_and_its_specular() {
    // At this size the point light's highlights clear the search's floor on their own:
    // its diffuse and its specular term were two lines, as if two bugs.
    let scene = at_half_size("scenes/default.ron");
    let point = scene
        .lights
        .iter()
        .position(|l| matches!(l, Light::Point { .. }))
        .unwrap();
    let (c, report) = student_diff(
        &scene,
        Bugs {
            drop_light: Some(point),
            ..Bugs::default()
        },
    );
    let first = &c.explanations[0];
    assert_eq!(first.term, ExplainedTerm::Light, "{report}");
    assert_eq!(first.light, Some(point), "{report}");
    assert!(first.factor < 0.05, "{report}");
    assert!(
        first.summary.starts_with("Light 1 (Point) is missing"),
        "{report}"
    );
    assert!(
        c.explanations[1..].iter().all(|e| e.light != Some(point)),
        "{report}"
    );
}

#[test]
fn shadows_missing_on_an_object_that_only_shadows_itself_read_as_the_self_shadow_bug() {
    // Tuning seed 3: an object whose shadows are all its own. "Its shadows are
    // missing" and "it never shadows itself" are one picture; a tracer that drops one
    // object's shadows is rare, one whose shadow ray skips its own object is not.
    let scene = raylab::bench::random_scene::random_scene(3, 200, 150);
    let (c, report) = student_diff(
        &scene,
        Bugs {
            no_self_shadow: true,
            ..Bugs::default()
        },
    );
    let first = &c.explanations[0];
    assert_eq!(
        first.cause,
        Cause::ShadowTest(ShadowBug::NoSelfShadow),
        "{report}"
    );
    assert!(
        first.confidence >= raylab::compare::HIGH_CONFIDENCE,
        "{report}"
    );
}
