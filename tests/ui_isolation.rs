//! Mute, solo and hide in the editor, through AccessKit: the outliner's and the light
//! markers' toggles change what the preview renders (the final frame equals `raylab
//! render` with the same flags) without editing the scene; hidden objects are not picked;
//! the switches follow their items through a delete and its undo, are remembered per
//! file, and the pixel inspector names what they leave out.

mod editor_harness;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use clap::Parser;
use editor_harness::{click_at, editor_harness, temp_dir, wait_for_final};
use egui::{Modifiers, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::cli::{Cli, Command as CliCommand};
use raylab::preview::Pass;
use raylab::scene::{Light, Scene, save_scene};
use raylab::trace::{Image, Isolation, PinholeCamera, RenderProgress, World, render};
use raylab::ui::files::default_scene;
use raylab::ui::{Command, EditorApp, EditorOptions, SceneEdit, Selection, VIEWPORT_LABEL};

/// The default scene, small: 160 x 120 at 4 samples a pixel.
fn small_scene() -> Scene {
    let mut scene = default_scene();
    scene.camera.width = 160;
    scene.camera.height = 120;
    scene.render.samples_per_pixel = 4;
    scene
}

/// `small_scene` saved in a fresh folder.
fn scene_file(name: &str) -> PathBuf {
    let path = temp_dir(&format!("isolation-{name}")).join("small.ron");
    save_scene(&small_scene(), &path).unwrap();
    path
}

/// An editor on `path`, with or without the preview.
fn harness_on(path: &Path, preview: bool) -> Harness<'static, EditorApp> {
    let options = EditorOptions {
        scene: Some(path.to_owned()),
        preview,
        ..EditorOptions::default()
    };
    let mut harness = editor_harness(options, Vec2::new(1280.0, 800.0), 64);
    harness.run_ok();
    harness
}

fn click(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.run_ok();
}

/// A click on the widget labelled `label` with Shift held.
fn shift_click(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness
        .get_by_label(label)
        .click_modifiers(Modifiers::SHIFT);
    harness.run_ok();
}

fn isolation(harness: &Harness<'_, EditorApp>) -> Isolation {
    harness.state().view().isolation.clone()
}

fn set(items: &[usize]) -> BTreeSet<usize> {
    items.iter().copied().collect()
}

/// What `raylab render scene.ron <flags>` renders, parsed by the real command line.
fn cli_image(scene: &Scene, flags: &[&str]) -> Image {
    let args = ["raylab", "render", "scene.ron", "-o", "out.png"];
    let cli = Cli::try_parse_from(args.iter().chain(flags)).unwrap();
    let Some(CliCommand::Render(args)) = cli.command else {
        panic!("not a render");
    };
    let options = args.options(scene).unwrap();
    let world = World::isolated(scene, &options.isolation).unwrap();
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
}

/// The screen position of scene object `index`'s origin in the viewport.
fn object_on_screen(harness: &Harness<'_, EditorApp>, index: usize) -> Pos2 {
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    let scene = &harness.state().document().scene;
    let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
    let origin = scene.objects[index]
        .transform
        .world_from_object()
        .translation;
    let p = camera.project(origin).unwrap();
    Pos2::new(
        picture.min.x + (p.x / f64::from(scene.camera.width)) as f32 * picture.width(),
        picture.min.y + (p.y / f64::from(scene.camera.height)) as f32 * picture.height(),
    )
}

#[test]
fn outliner_toggles_isolate_without_editing_and_the_final_frame_equals_the_cli() {
    let path = scene_file("toggles");
    let mut harness = harness_on(&path, true);
    wait_for_final(&mut harness);
    let before = harness.state().preview().unwrap().generation();

    click(&mut harness, "mute Point light 2");
    click(&mut harness, "solo Spot light 4");
    shift_click(&mut harness, "solo Ambient light 1");
    click(&mut harness, "hide red ball");
    let expected = Isolation {
        muted_lights: set(&[1]),
        solo_lights: set(&[0, 3]),
        hidden_objects: set(&[1]),
        hidden_parts: std::collections::BTreeSet::new(),
    };
    assert_eq!(isolation(&harness), expected);
    assert!(
        !harness.state().document().is_dirty(),
        "isolation is not a scene edit"
    );
    assert_eq!(&harness.state().document().scene, &small_scene());
    let preview = harness.state().preview().unwrap();
    assert!(preview.generation() > before, "the preview restarted");
    assert_eq!(preview.submitted_options().unwrap().isolation, expected);

    wait_for_final(&mut harness);
    let frame = harness.state().preview().unwrap().frame().unwrap();
    assert_eq!(
        frame.pass,
        Pass::Full {
            samples: 4,
            target: 4
        }
    );
    let flags = [
        "--mute-light",
        "1",
        "--solo-light",
        "0,3",
        "--hide",
        "red ball",
    ];
    let cli = cli_image(&small_scene(), &flags);
    assert!(
        frame.image.pixels == cli.pixels,
        "the preview differs from raylab render"
    );
    assert!(
        cli != cli_image(&small_scene(), &[]),
        "the flags changed the picture"
    );

    // The toolbar says the picture is not the full one, and "show all" brings it back.
    harness.get_by_label_contains("solo Ambient light 1, Spot light 4");
    harness.get_by_label_contains("hidden red ball");
    click(&mut harness, "show all");
    assert_eq!(isolation(&harness), Isolation::NONE);
    assert!(harness.query_by_label("show all").is_none());

    // A plain click on solo replaces the solo lights; a second one ends the solo.
    click(&mut harness, "solo Spot light 4");
    shift_click(&mut harness, "solo Point light 2");
    assert_eq!(isolation(&harness).solo_lights, set(&[1, 3]));
    click(&mut harness, "solo Point light 2");
    assert_eq!(isolation(&harness).solo_lights, set(&[1]));
    click(&mut harness, "solo Point light 2");
    assert!(isolation(&harness).is_none());
}

#[test]
fn a_hidden_object_is_not_picked_and_light_markers_carry_mute_and_solo() {
    // The default point light is off to the left of the picture: bring its marker in view.
    let mut scene = small_scene();
    if let Light::Point { position, .. } = &mut scene.lights[1] {
        *position = DVec3::new(-1.5, 3.0, 3.0);
    }
    let path = temp_dir("isolation-markers").join("markers.ron");
    save_scene(&scene, &path).unwrap();
    let mut harness = harness_on(&path, false);
    let ball = object_on_screen(&harness, 1);
    click_at(&mut harness, ball);
    assert_eq!(&harness.state().document().selection, &Selection::Object(1));
    click(&mut harness, "hide red ball");
    click(&mut harness, "Camera");
    click_at(&mut harness, ball);
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Object(0),
        "the click goes through the hidden ball to the floor"
    );

    assert!(
        harness
            .query_by_label("mute Point light 2 (marker)")
            .is_none()
    );
    click(&mut harness, "Point light 2");
    click(&mut harness, "mute Point light 2 (marker)");
    assert_eq!(isolation(&harness).muted_lights, set(&[1]));
    click(&mut harness, "solo Point light 2 (marker)");
    assert_eq!(isolation(&harness).solo_lights, set(&[1]));
    // A muted or solo light keeps its buttons by its marker when deselected.
    click(&mut harness, "Camera");
    harness.get_by_label("mute Point light 2 (marker)");
    click(&mut harness, "solo Point light 2 (marker)");
    click(&mut harness, "mute Point light 2 (marker)");
    assert!(
        harness
            .query_by_label("mute Point light 2 (marker)")
            .is_none()
    );
    assert!(!harness.state().document().is_dirty());
}

#[test]
fn switches_follow_a_delete_and_its_undo_and_are_remembered_per_file() {
    let path = scene_file("memory");
    let mut harness = harness_on(&path, false);
    click(&mut harness, "mute Spot light 4");
    click(&mut harness, "hide green pillar");
    harness
        .state_mut()
        .push(Command::Select(Selection::Light(2)));
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::DeleteSelected));
    harness.run_ok();
    assert_eq!(harness.state().document().scene.lights.len(), 3);
    assert_eq!(
        isolation(&harness).muted_lights,
        set(&[2]),
        "the spot moved up"
    );
    harness.get_by_label("mute Spot light 3");
    harness.state_mut().push(Command::Undo);
    harness.run_ok();
    assert_eq!(&harness.state().document().scene, &small_scene());
    assert_eq!(isolation(&harness).muted_lights, set(&[3]));
    let kept = isolation(&harness);
    assert_eq!(kept.hidden_objects, set(&[4]));

    // Another file has its own switches; coming back brings these again.
    let other = scene_file("memory-other");
    harness.state_mut().push(Command::Open(other));
    harness.run_ok();
    assert_eq!(isolation(&harness), Isolation::NONE);
    harness.state_mut().push(Command::Open(path.clone()));
    harness.run_ok();
    assert_eq!(isolation(&harness), kept);

    // A later run, given the stored memory, opens the file with its switches.
    let memory = harness.state().isolation_memory();
    assert_eq!(memory.recall(&path), kept);
    let mut later = harness_on(&path, false);
    assert_eq!(isolation(&later), Isolation::NONE);
    later.state_mut().set_isolation_memory(memory);
    later.run_ok();
    assert_eq!(isolation(&later), kept);
    assert!(!later.state().document().is_dirty());
}

#[test]
fn the_pixel_inspector_names_what_is_left_out() {
    let path = scene_file("inspector");
    let mut harness = harness_on(&path, false);
    click(&mut harness, "mute Point light 2");
    click(&mut harness, "hide mirror ball");
    let scene = harness.state().document().scene.clone();
    let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
    let p = camera.project(scene.objects[3].transform.world_from_object().translation);
    let p = p.unwrap();
    harness
        .state_mut()
        .push(Command::InspectPixel(Some((p.x as u32, p.y as u32))));
    harness.run_ok();
    let inspection = harness.state().inspection().unwrap();
    assert_eq!(&inspection.isolation, &harness.state().view().isolation);
    let pixel = inspection.result.as_ref().unwrap();
    assert_eq!(pixel.bounces[0].hit.as_ref().unwrap().object, "blue box");
    assert_eq!(pixel.lights_off, ["Point light 2"]);
    assert_eq!(pixel.hidden_objects, ["mirror ball"]);
    assert!(
        pixel.report.bounces[0]
            .lights
            .iter()
            .all(|l| l.scene_index != 1)
    );
    harness.get_by_label("off (muted or not solo): Point light 2");
    harness.get_by_label("hidden (rays pass through): mirror ball");
    // Unmuting updates the open inspector.
    click(&mut harness, "mute Point light 2");
    let pixel = harness
        .state()
        .inspection()
        .unwrap()
        .result
        .as_ref()
        .unwrap();
    assert!(pixel.lights_off.is_empty());
    assert!(
        pixel.report.bounces[0]
            .lights
            .iter()
            .any(|l| l.scene_index == 1)
    );
}
