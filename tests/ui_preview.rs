//! The viewport toolbar, the NaN guard, the pixel inspector and the convergence plot,
//! through AccessKit with the real preview worker (on a small scene, so the final frame
//! comes quickly).

mod common;
mod editor_harness;

use std::path::PathBuf;

use common::cli::cli_options;
use editor_harness::{click_at, click_with, editor_harness, wait_for_final};
use egui::{Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::preview::Pass;
use raylab::scene::{Scene, save_scene};
use raylab::trace::{PinholeCamera, RenderProgress, Term, View, World, render};
use raylab::ui::files::default_scene;
use raylab::ui::{EditorApp, EditorOptions, Selection, VIEWPORT_LABEL};

/// The default scene, small: 160 x 120 at 4 samples a pixel.
fn small_scene() -> Scene {
    let mut scene = default_scene();
    scene.camera.width = 160;
    scene.camera.height = 120;
    scene.render.samples_per_pixel = 4;
    scene
}

/// An editor with the preview running on `small_scene`, saved to a temporary file.
fn harness(name: &str) -> Harness<'static, EditorApp> {
    harness_sized(name, Vec2::new(1280.0, 800.0))
}

/// As [`harness`], in a window of `size`.
fn harness_sized(name: &str, size: Vec2) -> Harness<'static, EditorApp> {
    let dir = std::env::temp_dir().join(format!("raylab-ui-preview-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path: PathBuf = dir.join("small.ron");
    save_scene(&small_scene(), &path).unwrap();
    let options = EditorOptions {
        scene: Some(path),
        preview: true,
        ..EditorOptions::default()
    };
    let mut harness = editor_harness(options, size, 64);
    harness.run_ok();
    assert_eq!(&harness.state().document().scene, &small_scene());
    harness
}

fn click(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.run_ok();
}

/// Clicks a toolbar toggle (a button: the pixel inspector lists terms by the same names).
fn toggle(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness
        .get_by_role_and_label(egui::Role::Button, label)
        .click();
    harness.run_ok();
}

/// What `raylab render scene.ron --off .. --solo .. --view ..` renders, exactly.
fn cli_image(scene: &Scene, off: &[Term], solo: Option<Term>, view: View) -> raylab::trace::Image {
    let world = World::new(scene).unwrap();
    let options = cli_options(scene, off, solo, view);
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
}

/// The preview's final image equals the CLI's pixel for pixel (exact f32 equality).
fn assert_final_frame_is(harness: &mut Harness<'_, EditorApp>, expected: &raylab::trace::Image) {
    wait_for_final(harness);
    let frame = harness.state().preview().unwrap().frame().unwrap();
    assert_eq!(
        frame.pass,
        Pass::Full {
            samples: 4,
            target: 4
        }
    );
    assert_eq!(
        (frame.image.width, frame.image.height),
        (expected.width, expected.height)
    );
    assert!(
        frame.image.pixels == expected.pixels,
        "the preview differs from raylab render"
    );
}

#[test]
fn toolbar_switches_restart_the_preview_and_its_final_frame_equals_the_cli() {
    let mut harness = harness("switches");
    wait_for_final(&mut harness);
    let scene = small_scene();
    assert_final_frame_is(&mut harness, &cli_image(&scene, &[], None, View::Beauty));
    let before = harness.state().preview().unwrap().generation();

    toggle(&mut harness, "diffuse");
    let preview = harness.state().preview().unwrap();
    let options = preview.submitted_options().unwrap();
    assert!(!options.switches.is_on(Term::Diffuse), "diffuse went off");
    assert!(options.switches.is_on(Term::Specular));
    assert!(preview.generation() > before, "the preview restarted");
    assert!(
        !harness.state().document().is_dirty(),
        "a toolbar switch is not a scene edit"
    );
    assert_eq!(&harness.state().document().scene, &scene);
    assert_final_frame_is(
        &mut harness,
        &cli_image(&scene, &[Term::Diffuse], None, View::Beauty),
    );

    // Solo specular, with diffuse still off (it shapes reflected colours only).
    click(&mut harness, "solo");
    click(&mut harness, "solo specular");
    let options = harness
        .state()
        .preview()
        .unwrap()
        .submitted_options()
        .unwrap();
    assert_eq!(options.switches.solo, Some(Term::Specular));
    assert_final_frame_is(
        &mut harness,
        &cli_image(&scene, &[Term::Diffuse], Some(Term::Specular), View::Beauty),
    );

    // Back to no solo, shadows off, and the normal view.
    click(&mut harness, "solo");
    click(&mut harness, "solo none");
    toggle(&mut harness, "shadows");
    click(&mut harness, "view");
    click(&mut harness, "view normal");
    let options = harness
        .state()
        .preview()
        .unwrap()
        .submitted_options()
        .unwrap();
    assert_eq!(options.view, View::Normal);
    assert_eq!(options.switches.solo, None);
    assert_final_frame_is(
        &mut harness,
        &cli_image(&scene, &[Term::Diffuse, Term::Shadows], None, View::Normal),
    );
    let settings = harness.state().view().preview_settings;
    assert_eq!(
        settings.render_options(&scene),
        options,
        "the settings are the request"
    );
}

#[test]
fn the_nan_guard_shows_zero_non_finite_samples() {
    let mut harness = harness("guard");
    wait_for_final(&mut harness);
    assert!(
        harness.query_by_label("0 non-finite samples").is_none(),
        "off by default"
    );
    toggle(&mut harness, "NaN guard");
    assert!(harness.state().view().preview_settings.nan_guard);
    harness.get_by_label("0 non-finite samples");
    let frame = harness.state().preview().unwrap().frame().unwrap();
    assert_eq!(frame.non_finite_samples, 0);
    assert!(frame.non_finite_pixels.is_empty());
    // With nothing to paint, the guarded texture is the picture itself.
    assert_eq!(
        raylab::ui::frame_rgba(frame, true),
        raylab::ui::frame_rgba(frame, false)
    );
}

/// The screen position of the centre of scene object `index` in the viewport.
fn object_on_screen(harness: &Harness<'_, EditorApp>, index: usize) -> Pos2 {
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    let scene = &harness.state().document().scene;
    let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
    let centre = scene.objects[index]
        .transform
        .world_from_object()
        .translation;
    let p = camera.project(centre).unwrap();
    Pos2::new(
        picture.min.x + (p.x / f64::from(scene.camera.width)) as f32 * picture.width(),
        picture.min.y + (p.y / f64::from(scene.camera.height)) as f32 * picture.height(),
    )
}

#[test]
fn inspecting_a_pixel_shows_its_object_and_terms_that_add_up_to_its_colour() {
    let mut harness = harness("inspect");
    wait_for_final(&mut harness);
    toggle(&mut harness, "Inspect");
    let ball = harness
        .state()
        .document()
        .scene
        .objects
        .iter()
        .position(|o| o.name == "red ball")
        .unwrap();
    let pos = object_on_screen(&harness, ball);
    click_at(&mut harness, pos);
    assert_eq!(
        &harness.state().document().selection,
        &Selection::None,
        "inspect does not select"
    );
    let inspection = harness
        .state()
        .inspection()
        .expect("the inspector opened")
        .clone();
    let pixel = inspection.result.as_ref().unwrap();
    let hit = pixel.bounces[0]
        .hit
        .as_ref()
        .expect("the ray hits the ball");
    assert_eq!(hit.object, "red ball");
    assert_eq!(
        hit.material,
        harness.state().document().scene.objects[ball].material
    );
    // The window shows the object's name (the outliner row is the other "red ball").
    assert!(harness.get_all_by_label("red ball").count() >= 2);
    harness.get_by_label(raylab::ui::FINAL_COLOUR_LABEL);
    for bounce in &pixel.report.bounces {
        let sum = bounce.sum_of_terms();
        assert!(
            (sum - bounce.colour).abs().max_element() < 1e-12,
            "depth {}",
            bounce.depth
        );
    }
    assert_eq!(pixel.report.bounces[0].colour, pixel.report.unclamped);
    // The inspected pixel is the image's pixel: same numbers as the one-sample render.
    let scene = harness.state().document().scene.clone();
    let world = World::new(&scene).unwrap();
    let options = raylab::trace::RenderOptions {
        samples_per_pixel: 1,
        ..raylab::trace::RenderOptions::from_scene(&scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let (x, y) = inspection.pixel;
    assert_eq!(pixel.report.unclamped.as_vec3(), image.get(x, y));

    // Switching a term off updates the open inspector.
    toggle(&mut harness, "specular");
    let updated = harness.state().inspection().unwrap();
    assert!(!updated.switches.is_on(Term::Specular));
    let lights = &updated.result.as_ref().unwrap().report.bounces[0].lights;
    assert!(lights.iter().all(|l| l.specular == glam::DVec3::ZERO));

    // Closing the window closes the inspector.
    harness.get_by_label("Close window").click();
    harness.run_ok();
    assert!(harness.state().inspection().is_none());
}

#[test]
fn an_alt_click_inspects_without_the_toggle() {
    let mut harness = harness("alt");
    wait_for_final(&mut harness);
    let pos = object_on_screen(&harness, 3);
    click_with(&mut harness, pos, Modifiers::ALT);
    assert_eq!(
        &harness.state().document().selection,
        &Selection::None,
        "alt-click does not select"
    );
    let inspection = harness.state().inspection().expect("alt-click inspects");
    let hit = inspection.result.as_ref().unwrap().bounces[0]
        .hit
        .as_ref()
        .unwrap();
    assert_eq!(hit.object, harness.state().document().scene.objects[3].name);
}

#[test]
fn the_convergence_plot_shows_the_estimated_error_of_each_anti_aliasing_pass() {
    let mut harness = harness("convergence");
    wait_for_final(&mut harness);
    toggle(&mut harness, "Convergence");
    assert!(harness.state().view().preview_settings.show_convergence);
    harness.get_by_label("Estimated remaining error");
    // Restart so the curve follows a fresh generation from its first pass.
    toggle(&mut harness, "reflection");
    wait_for_final(&mut harness);
    let preview = harness.state().preview().unwrap();
    let (generation, curve) = preview.convergence().unwrap();
    assert_eq!(generation, preview.generation());
    let passes: Vec<Pass> = curve.points().iter().map(|p| p.pass).collect();
    // 160 x 120: coarse 1/2 and 1 sample have no estimate; the 4-sample pass has one.
    assert_eq!(
        passes,
        vec![Pass::Full {
            samples: 4,
            target: 4
        }]
    );
    let point = curve.points()[0];
    assert!(point.estimated_rmse.is_finite() && point.estimated_rmse > 0.0);
    assert_eq!(point.render_time, curve.render_time(), "the last pass");
}

#[test]
fn the_status_bar_shows_samples_so_far_of_the_target_and_final() {
    let mut harness = harness("status");
    wait_for_final(&mut harness);
    let status = harness.get_by_label_contains("4/4 samples");
    let text = format!("{status:?}");
    assert!(text.contains("final") && text.contains("Mrays/s"), "{text}");
}

#[test]
fn a_narrow_viewport_scrolls_the_toolbar_to_its_last_toggle() {
    let mut harness = harness_sized("narrow", Vec2::new(760.0, 600.0));
    let toggle = harness.get_by_role_and_label(egui::Role::Button, "Convergence");
    toggle.scroll_to_me();
    harness.run_ok();
    toggle_at_visible(&mut harness, "Convergence");
    assert!(harness.state().view().preview_settings.show_convergence);
}

/// Clicks a toggle after scrolling it into view.
fn toggle_at_visible(harness: &mut Harness<'_, EditorApp>, label: &str) {
    let viewport = harness.get_by_label(VIEWPORT_LABEL).rect();
    let toggle = harness.get_by_role_and_label(egui::Role::Button, label);
    let rect = toggle.rect();
    assert!(
        rect.max.x <= viewport.max.x + 16.0 && rect.min.x >= viewport.min.x - 16.0,
        "{label} at {rect:?} is outside the viewport {viewport:?}"
    );
    toggle.click();
    harness.run_ok();
}
