//! Export PNG through the editor, with no window: the file is written in the
//! background, a failed write keeps the render, a running export can be cancelled.

mod editor_harness;

use std::path::Path;

use editor_harness::{harness, step_until, temp_dir};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::ui::{Command, EditorApp};

#[test]
fn export_writes_a_png_and_keeps_the_render_when_the_file_cannot_be_written() {
    let dir = temp_dir("export");
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    harness
        .get_by_label("export width")
        .set_value_accesskit(64.0);
    harness
        .get_by_label("export height")
        .set_value_accesskit(48.0);
    harness
        .get_by_label("export samples")
        .set_value_accesskit(2.0);
    harness.run();

    let bad = dir.join("missing").join("out.png");
    set_export_path(&mut harness, &bad);
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| {
        !app.tools().export.is_running()
    });
    let status = harness.state().tools().export.status.clone().unwrap();
    assert!(
        status.as_ref().is_err_and(|e| e.contains("cannot write")),
        "{status:?}"
    );
    let kept = harness
        .state()
        .tools()
        .export
        .kept_image()
        .expect("the render is kept");
    assert_eq!((kept.width, kept.height), (64, 48));

    let good = dir.join("out.png");
    set_export_path(&mut harness, &good);
    harness.get_by_label("Save kept render").click();
    harness.run_ok();
    step_until(&mut harness, "the write", |app| {
        !app.tools().export.is_running()
    });
    let png = image::open(&good).expect("a PNG was written");
    assert_eq!((png.width(), png.height()), (64, 48));
    assert!(harness.state().tools().export.kept_image().is_none());
}

fn set_export_path(harness: &mut Harness<'_, EditorApp>, path: &Path) {
    harness.get_by_label("export path").focus();
    harness.run();
    harness.key_combination_modifiers(Modifiers::COMMAND, &[Key::A]);
    harness
        .get_by_label("export path")
        .type_text(&path.display().to_string());
    harness.run();
}

#[test]
fn a_running_export_can_be_cancelled_and_writes_nothing() {
    let dir = temp_dir("export-cancel");
    let path = dir.join("big.png");
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    // Far too much work to finish before the click below.
    harness
        .get_by_label("export width")
        .set_value_accesskit(4000.0);
    harness
        .get_by_label("export height")
        .set_value_accesskit(3000.0);
    harness
        .get_by_label("export samples")
        .set_value_accesskit(4096.0);
    harness.run();
    set_export_path(&mut harness, &path);
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    assert!(harness.state().tools().export.is_running());
    harness.get_by_label("Cancel").click();
    harness.run_ok();
    step_until(&mut harness, "the cancel", |app| {
        !app.tools().export.is_running()
    });
    let status = harness.state().tools().export.status.clone();
    assert_eq!(status, Some(Err("export cancelled".to_owned())));
    assert!(!path.exists());
}

/// The export window at `width` x `height` with one sample, writing to `path`.
fn export_window_at(harness: &mut Harness<'_, EditorApp>, width: u32, height: u32, path: &Path) {
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    harness
        .get_by_label("export width")
        .set_value_accesskit(f64::from(width));
    harness.run();
    harness.get_by_label("keep aspect").click();
    harness.run();
    harness
        .get_by_label("export height")
        .set_value_accesskit(f64::from(height));
    harness
        .get_by_label("export samples")
        .set_value_accesskit(1.0);
    harness.run();
    set_export_path(harness, path);
}

#[test]
fn the_window_stays_put_when_its_status_line_appears() {
    let dir = temp_dir("export-still");
    let mut harness = harness();
    export_window_at(&mut harness, 32, 24, &dir.join("missing").join("out.png"));
    let button = harness.get_by_label("Render and save").rect();
    let field = harness.get_by_label("export path").rect();
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| {
        !app.tools().export.is_running()
    });
    assert!(
        harness
            .state()
            .tools()
            .export
            .status
            .as_ref()
            .is_some_and(Result::is_err)
    );
    assert_eq!(harness.get_by_label("Render and save").rect(), button);
    assert_eq!(harness.get_by_label("export path").rect(), field);
}

#[test]
fn width_and_height_keep_the_aspect_ratio_until_unlinked() {
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    harness
        .get_by_label("export width")
        .set_value_accesskit(200.0);
    harness.run();
    let size = |h: &Harness<'_, EditorApp>| {
        let o = h.state().tools().export.settings.clone().unwrap();
        (o.width, o.height)
    };
    assert_eq!(size(&harness), (200, 150), "the default scene is 4:3");
    harness.get_by_label("keep aspect").click();
    harness.run();
    harness
        .get_by_label("export height")
        .set_value_accesskit(100.0);
    harness.run();
    assert_eq!(size(&harness), (200, 100));
}

#[test]
fn as_the_viewport_shows_it_exports_the_switches_view_and_hidden_objects_on_screen() {
    use raylab::trace::{Isolation, RenderOptions, RenderProgress, Term, View, World, render};
    let dir = temp_dir("export-shown");
    let path = dir.join("shown.png");
    let mut harness = harness();
    let mut shown = harness.state().view().preview_settings;
    shown.switches.set(Term::Diffuse, false);
    shown.view = View::Depth;
    harness.state_mut().push(Command::SetPreviewSettings(shown));
    harness
        .state_mut()
        .push(Command::Isolate(raylab::ui::IsolationToggle::Hide(0)));
    export_window_at(&mut harness, 40, 30, &path);
    harness.get_by_label("as the viewport shows it").click();
    harness.run();
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| {
        !app.tools().export.is_running()
    });

    let scene = harness.state().document().scene.clone();
    let options = RenderOptions {
        width: 40,
        height: 30,
        samples_per_pixel: 1,
        switches: shown.switches,
        view: shown.view,
        isolation: Isolation {
            hidden_objects: [0].into(),
            ..Isolation::NONE
        },
    };
    let world = World::isolated(&scene, &options.isolation).unwrap();
    let (expected, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let expected = image::load_from_memory(&expected.png_bytes()).unwrap();
    let whole = World::new(&scene).unwrap();
    let every_object = RenderOptions {
        isolation: Isolation::NONE,
        ..options.clone()
    };
    let (with_all, _) = render(&whole, &every_object, &RenderProgress::default()).unwrap();
    assert_ne!(
        image::load_from_memory(&with_all.png_bytes())
            .unwrap()
            .to_rgb8(),
        expected.to_rgb8(),
        "hiding the object changes the picture"
    );
    let written = image::open(&path).expect("the export was written");
    assert_eq!(
        written.to_rgb8(),
        expected.to_rgb8(),
        "what `raylab render --view depth --hide` gives"
    );
}

#[test]
fn a_scene_with_meshes_exports_with_the_meshes_the_preview_reads() {
    use raylab::trace::{MeshStore, RenderOptions, RenderProgress, World, render};
    let dir = temp_dir("export-mesh");
    let path = dir.join("mesh.png");
    let mut harness = editor_harness::harness_on_example("mesh.ron");
    export_window_at(&mut harness, 48, 36, &path);
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| {
        !app.tools().export.is_running()
    });
    let status = harness.state().tools().export.status.clone();
    assert!(
        status.as_ref().is_some_and(Result::is_ok),
        "the export of a mesh scene succeeds: {status:?}"
    );

    // What `raylab render` gives: the meshes read from the scene's folder.
    let scene = harness.state().document().scene.clone();
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let meshes = MeshStore::build(&raylab::scene::read_scene_meshes(&scene, &folder).unwrap());
    let world = World::with_meshes(&scene, &meshes).unwrap();
    let options = RenderOptions {
        width: 48,
        height: 36,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&scene)
    };
    let (expected, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let expected = image::load_from_memory(&expected.png_bytes()).unwrap();
    let written = image::open(&path).expect("the export was written");
    assert_eq!(
        written.to_rgb8(),
        expected.to_rgb8(),
        "the knot and pyramid are in it"
    );
}

#[test]
fn the_export_proposes_the_last_export_folder_else_pictures_or_home_never_the_scenes() {
    use raylab::ui::document::export::pictures_or_home;
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut harness = editor_harness::harness_on_example("glass.ron");
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    let proposed = std::path::PathBuf::from(&harness.state().tools().export.path);
    assert_eq!(proposed.file_name().unwrap(), "glass.png");
    assert_eq!(proposed.parent(), pictures_or_home().as_deref());
    assert_ne!(
        proposed.parent(),
        Some(scenes.as_path()),
        "not beside the example"
    );

    // Once a picture is written somewhere, the next scene's export is proposed there.
    let dir = temp_dir("export-folder");
    export_window_at(&mut harness, 16, 12, &dir.join("first.png"));
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| {
        !app.tools().export.is_running()
    });
    editor_harness::open_example(&mut harness, "csg.ron");
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    assert_eq!(
        std::path::PathBuf::from(&harness.state().tools().export.path),
        dir.join("csg.png")
    );
}

/// Every text the last frame painted, with where it starts.
fn painted_texts(harness: &Harness<'_, EditorApp>) -> Vec<(egui::Pos2, String)> {
    fn walk(shape: &egui::Shape, out: &mut Vec<(egui::Pos2, String)>) {
        match shape {
            egui::Shape::Vec(shapes) => shapes.iter().for_each(|s| walk(s, out)),
            egui::Shape::Text(text) => out.push((text.pos, text.galley.text().to_owned())),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for clipped in &harness.output().shapes {
        walk(&clipped.shape, &mut out);
    }
    out
}

#[test]
fn a_path_too_long_for_its_field_shows_its_end_until_it_is_edited() {
    let deep = "/home/student/courses/cosc342/assignment-two/renders/final-versions/";
    let path = format!("{deep}snowman-with-glass.png");
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    set_export_path(&mut harness, Path::new(&path));
    // While it is edited, the field shows the text as typed.
    let field = harness.get_by_label("export path").rect();
    let elided_in_field = |harness: &Harness<'_, EditorApp>| {
        painted_texts(harness)
            .into_iter()
            .find(|(pos, text)| field.contains(*pos) && text.starts_with('…'))
    };
    assert_eq!(elided_in_field(&harness), None, "editing shows it whole");
    // The edit ends (focus elsewhere): the field shows the file's name and the folder
    // nearest it, the start cut off.
    harness.get_by_label("export width").focus();
    harness.run();
    let (_, shown) = elided_in_field(&harness).expect("the path's end is shown in the field");
    assert!(
        shown.ends_with("/snowman-with-glass.png"),
        "the end of the path, with its file name: {shown:?}"
    );
    assert!(
        path.ends_with(shown.trim_start_matches('…')),
        "{shown:?} is the end of {path:?}"
    );
    assert_eq!(
        harness.state().tools().export.path,
        path,
        "the path itself is whole"
    );
}
