//! File > Compare with Image under egui_kittest: a comparison opened from a path runs in
//! the background and replaces the viewport; each mode shows; clicking an explanation
//! highlights its pixels and selects its object; the pixel inspector shows both values;
//! a wrong-size picture and a dropped PNG.

mod editor_harness;

use std::path::{Path, PathBuf};

use egui::{Key, Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::compare::ExplainedTerm;
use raylab::scene::{Scene, load_scene};
use raylab::trace::{RenderOptions, RenderProgress, Term, World, render};
use raylab::ui::compare::{
    COMPARE_PATH_LABEL, COMPARE_PICTURE_LABEL, CompareMode, OtherSource, ZoomView,
    explanation_label, picture_frames,
};
use raylab::ui::viewport::pixel_inspector::{OTHER_VALUE_LABEL, RAYLAB_VALUE_LABEL, compared_rows};
use raylab::ui::{EditorApp, EditorOptions, Selection};

use editor_harness::{click_at, drop_file, editor_harness, temp_dir};

const LAB: &str = "tests/compare/lab.ron";

fn lab() -> Scene {
    load_scene(Path::new(LAB)).unwrap()
}

/// The lab scene rendered by raylab with the red ball's diffuse colour halved, as PNG.
fn halved_ball_png(dir: &Path) -> PathBuf {
    let mut scene = lab();
    let ball = scene.objects.iter().find(|o| o.name == "red ball").unwrap();
    let material = scene.materials.get_mut(&ball.material.clone()).unwrap();
    material.diffuse *= 0.5;
    let world = World::new(&scene).unwrap();
    let (image, _) = render(
        &world,
        &RenderOptions::from_scene(&scene),
        &RenderProgress::default(),
    )
    .unwrap();
    let path = dir.join("theirs.png");
    std::fs::write(&path, image.png_bytes()).unwrap();
    path
}

fn harness() -> Harness<'static, EditorApp> {
    editor_harness(
        EditorOptions {
            scene: Some(PathBuf::from(LAB)),
            ..EditorOptions::default()
        },
        Vec2::new(1280.0, 860.0),
        64,
    )
}

/// File > Compare with Image…, the path typed, Compare; then waits for the job.
fn compare_through_the_window(harness: &mut Harness<'_, EditorApp>, path: &Path) {
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Compare with Image…").click();
    harness.run();
    harness.get_by_label(COMPARE_PATH_LABEL).focus();
    harness.run();
    harness.key_combination_modifiers(Modifiers::COMMAND, &[Key::A]);
    harness
        .get_by_label(COMPARE_PATH_LABEL)
        .type_text(&path.display().to_string());
    harness.run();
    harness.get_by_label("Compare").click();
    harness.run();
    wait_for_comparison(harness);
}

fn wait_for_comparison(harness: &mut Harness<'_, EditorApp>) {
    for _ in 0..3000 {
        harness.step();
        if !harness.state().tools().compare.is_running() {
            harness.run();
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    panic!("the comparison did not finish");
}

/// The screen point over the centre of image pixel `p` in the first frame.
fn screen_of_pixel(harness: &Harness<'_, EditorApp>, mode: CompareMode, p: u32) -> Pos2 {
    let c = harness.state().tools().compare.comparison().unwrap();
    let (x, y) = (p % c.width, p / c.width);
    let label = format!("{COMPARE_PICTURE_LABEL}: {}", mode.label());
    let outer = harness.get_by_label(&label).rect();
    let frame = picture_frames(mode, outer, c.width as f32 / c.height as f32)[0];
    let pos = Pos2::new(
        frame.min.x + (x as f32 + 0.5) / c.width as f32 * frame.width(),
        frame.min.y + (y as f32 + 0.5) / c.height as f32 * frame.height(),
    );
    assert_eq!(
        ZoomView::default().pixel_at(frame, pos, c.width, c.height),
        Some((x, y))
    );
    pos
}

#[test]
fn a_comparison_from_a_path_shows_every_mode_and_its_explanations_select_and_highlight() {
    let dir = temp_dir("compare");
    let theirs = halved_ball_png(&dir);
    let mut harness = harness();
    compare_through_the_window(&mut harness, &theirs);
    let app = harness.state();
    assert!(
        app.tools().compare.error().is_none(),
        "{:?}",
        app.tools().compare.error()
    );
    let c = app
        .tools()
        .compare
        .comparison()
        .expect("the comparison is shown")
        .clone();
    let ball = app
        .document()
        .scene
        .objects
        .iter()
        .position(|o| o.name == "red ball")
        .unwrap();
    let top = &c.explanations[0];
    assert_eq!(
        (top.term, top.object),
        (ExplainedTerm::Term(Term::Diffuse), Some(ball))
    );

    // The view replaces the viewport; each mode button switches to its picture, and
    // "Close comparison" stays where it was whatever the mode's controls.
    let close = harness.get_by_label("Close comparison").rect();
    for mode in CompareMode::ALL {
        harness.get_by_label(mode.label()).click();
        harness.run();
        assert_eq!(harness.state().tools().compare.mode, mode);
        harness.get_by_label(&format!("{COMPARE_PICTURE_LABEL}: {}", mode.label()));
        assert_eq!(
            harness.get_by_label("Close comparison").rect(),
            close,
            "{mode:?}"
        );
    }
    // Flip shows the other picture, and back.
    harness.get_by_label("Flip to other image").click();
    harness.run();
    harness.get_by_label("Flip to raylab").click();
    harness.run();

    // Under its title, a sentence a person reads: how many pixels, what share, how sure
    // (not "15143 pixels, factor, sure: high").
    let detail = format!("It covers {} pixels and", top.pixels.len());
    harness.get_by_label_contains(&detail);
    assert!(harness.query_by_label_contains("sure:").is_none());
    // Clicking the top explanation selects the ball and highlights its pixels.
    assert!(
        harness
            .state()
            .tools()
            .compare
            .highlighted_pixels()
            .is_empty()
    );
    let scene = harness.state().document().scene.clone();
    harness
        .get_by_label(&explanation_label(0, top, &scene))
        .click();
    harness.run();
    let app = harness.state();
    assert_eq!(&app.document().selection, &Selection::Object(ball));
    assert_eq!(app.tools().compare.highlighted(), Some(0));
    assert_eq!(
        app.tools().compare.highlighted_pixels(),
        top.pixels.as_slice()
    );
    // Clicking it again clears the highlight.
    harness
        .get_by_label(&explanation_label(0, top, &scene))
        .click();
    harness.run();
    assert!(
        harness
            .state()
            .tools()
            .compare
            .highlighted_pixels()
            .is_empty()
    );

    // Scrolling over the picture zooms about the pointer.
    let pos = screen_of_pixel(&harness, CompareMode::Flip, top.pixels[0]);
    harness.event(egui::Event::PointerMoved(pos));
    harness.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: Vec2::new(0.0, 400.0),
        modifiers: Modifiers::NONE,
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
    });
    for _ in 0..30 {
        harness.step();
    }
    assert!(
        harness.state().tools().compare.view.zoom > 2.0,
        "{:?}",
        harness.state().tools().compare.view
    );

    // Close comparison: the live viewport is back.
    harness.get_by_label("Close comparison").click();
    harness.run();
    assert!(!harness.state().tools().compare.is_showing());
    harness.get_by_label(raylab::ui::VIEWPORT_LABEL);
}

#[test]
fn clicking_a_compared_pixel_shows_both_pictures_values_in_the_inspector() {
    let dir = temp_dir("compare-inspect");
    let theirs = halved_ball_png(&dir);
    let mut harness = harness();
    compare_through_the_window(&mut harness, &theirs);
    let c = harness
        .state()
        .tools()
        .compare
        .comparison()
        .unwrap()
        .clone();
    let p = c.explanations[0].pixels[c.explanations[0].pixels.len() / 2];
    let pos = screen_of_pixel(&harness, CompareMode::Swipe, p);
    click_at(&mut harness, pos);
    let (x, y) = (p % c.width, p / c.width);
    let inspection = harness.state().inspection().expect("the inspector opened");
    assert_eq!(inspection.pixel, (x, y));
    let values = c.pixel(x, y);
    assert_ne!(
        values.raylab_rgb, values.other_rgb,
        "a pixel of the halved ball"
    );
    // The inspector's rows show the comparison's bytes at that pixel, raylab's and the
    // other picture's, and the explanation that covers it.
    let rows = compared_rows(&values);
    let shown = |label: &str| {
        let (_, text) = rows.iter().find(|(l, _)| *l == label).unwrap();
        harness.get_by_label(&format!("{label}: {text}"));
        text.clone()
    };
    let raylab_text = shown(RAYLAB_VALUE_LABEL);
    assert!(
        raylab_text.starts_with(&format!("{:?}", values.raylab_rgb)),
        "{raylab_text}"
    );
    let other_text = shown(OTHER_VALUE_LABEL);
    assert!(
        other_text.starts_with(&format!("{:?}", values.other_rgb)),
        "{other_text}"
    );
    assert!(shown("explained by").split(", ").any(|n| n == "1"));
}

#[test]
fn a_wrong_size_picture_is_a_clear_error_and_a_dropped_png_compares() {
    let dir = temp_dir("compare-errors");
    let small = dir.join("small.png");
    image::RgbImage::new(10, 7).save(&small).unwrap();
    let mut harness = harness();
    compare_through_the_window(&mut harness, &small);
    let error = harness
        .state()
        .tools()
        .compare
        .error()
        .expect("an error")
        .to_owned();
    assert!(
        error.contains("10x7") && error.contains("120x90"),
        "{error}"
    );
    harness.get_by_label_contains("10x7");
    assert!(!harness.state().tools().compare.is_showing());

    // Dropping a PNG on the window compares with it.
    let theirs = halved_ball_png(&dir);
    drop_file(&mut harness, &theirs);
    wait_for_comparison(&mut harness);
    assert!(harness.state().tools().compare.error().is_none());
    let compared = harness.state().tools().compare.compared().expect("shown");
    assert_eq!(compared.source, OtherSource::File(theirs));
}

#[test]
fn every_explanation_reads_without_scrolling_the_list() {
    // Many differences at once, so there are many explanations.
    let dir = temp_dir("compare-many");
    let mut scene = lab();
    for (k, material) in scene.materials.values_mut().enumerate() {
        material.diffuse *= 0.3 + 0.25 * k as f64;
        material.specular *= 1.6 - 0.3 * k as f64;
        material.ambient *= 2.0;
        material.mirror *= 0.5;
    }
    if let raylab::scene::Light::Point { source, .. } = &mut scene.lights[1] {
        source.intensity *= 0.6;
    }
    if let raylab::scene::Light::Directional { intensity, .. } = &mut scene.lights[2] {
        *intensity *= 1.8;
    }
    let world = World::new(&scene).unwrap();
    let (image, _) = render(
        &world,
        &RenderOptions::from_scene(&scene),
        &RenderProgress::default(),
    )
    .unwrap();
    let theirs = dir.join("theirs.png");
    std::fs::write(&theirs, image.png_bytes()).unwrap();

    let mut harness = harness();
    compare_through_the_window(&mut harness, &theirs);
    let c = harness
        .state()
        .tools()
        .compare
        .comparison()
        .unwrap()
        .clone();
    assert!(
        c.explanations.len() >= 5,
        "{} explanations",
        c.explanations.len()
    );
    let window = harness.ctx.content_rect();
    let scene = harness.state().document().scene.clone();
    let row_of = |i: usize| {
        harness
            .get_by_label(&explanation_label(i, &c.explanations[i], &scene))
            .rect()
    };
    let span = row_of(c.explanations.len() - 1).max.y - row_of(0).min.y;
    assert!(span > 150.0, "more than a 150 px box holds: {span}");
    for i in 0..c.explanations.len() {
        let row = row_of(i);
        assert!(
            window.contains_rect(row),
            "explanation {i} of {} is at {row:?}, outside the window {window:?}: the list must be scrolled to read it",
            c.explanations.len()
        );
    }
}

/// File > Compare with Image… on `scenes/mesh.ron` (opened as a user opens it): the
/// comparison reads the scene's mesh files beside it as the preview and Export PNG do,
/// instead of failing with "the mesh file "knot.obj" is not loaded".
#[test]
fn a_scene_with_meshes_compares_with_the_meshes_read_beside_it() {
    use raylab::scene::read_scene_meshes;
    use raylab::trace::MeshStore;
    use raylab::ui::{Command, SceneEdit};

    let mut harness = editor_harness::harness_on_example("mesh.ron");
    assert_eq!(harness.state().document().scene.objects[1].name, "knot");
    // A small picture keeps the test quick; the size is the scene's, as a user sets it.
    let mut camera = harness.state().document().scene.camera.clone();
    (camera.width, camera.height) = (64, 48);
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::SetCamera(camera)));
    harness.run();

    // Their picture: what `raylab render` gives, the meshes read from the scene's folder.
    let scene = harness.state().document().scene.clone();
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let meshes = MeshStore::build(&read_scene_meshes(&scene, &folder).unwrap());
    let world = World::with_meshes(&scene, &meshes).unwrap();
    let (image, _) = render(
        &world,
        &RenderOptions::from_scene(&scene),
        &RenderProgress::default(),
    )
    .unwrap();
    let dir = temp_dir("compare-mesh");
    let theirs = dir.join("theirs.png");
    std::fs::write(&theirs, image.png_bytes()).unwrap();

    compare_through_the_window(&mut harness, &theirs);
    let app = harness.state();
    assert_eq!(
        app.tools().compare.error(),
        None,
        "the comparison of a mesh scene runs"
    );
    let c = app
        .tools()
        .compare
        .comparison()
        .expect("the comparison is shown");
    for mesh in ["knot", "pyramid"] {
        let index = scene.objects.iter().position(|o| o.name == mesh).unwrap();
        assert!(
            c.objects.contains(&Some(index)),
            "the {mesh} is in raylab's picture"
        );
    }
}
