//! The pixel inspector window, through egui_kittest: it sits beside the inspected pixel
//! (not over it), the wheel scrolls it anywhere over it (its title bar too), each new
//! pixel opens at its top, and it lists every light with why one adds nothing.

mod view_harness;

use egui::{Event, Modifiers, Pos2, Rect, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::trace::{TermSwitches, World};
use raylab::ui::viewport::pixel_inspector::{MAX_WIDTH, PixelInspection, inspector_window_id};
use raylab::ui::{EditorApp, FINAL_COLOUR_LABEL};
use view_harness::{click, harness, object_on_screen, picture, wait_for_probes};

fn window_rect(harness: &Harness<'_, EditorApp>) -> Rect {
    harness
        .ctx
        .memory(|m| m.area_rect(inspector_window_id()))
        .expect("the inspector window is open")
}

/// Where the final colour line is, from the window's top.
fn final_colour_offset(harness: &Harness<'_, EditorApp>) -> f32 {
    harness.get_by_label(FINAL_COLOUR_LABEL).rect().min.y - window_rect(harness).min.y
}

fn wheel(harness: &mut Harness<'_, EditorApp>, at: Pos2, lines: f32) {
    harness.event(Event::PointerMoved(at));
    for _ in 0..4 {
        harness.event(Event::MouseWheel {
            unit: egui::MouseWheelUnit::Line,
            delta: Vec2::new(0.0, lines / 4.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.run_ok();
}

/// Whether `window` sits beside `pixel`: at the gap's distance left or right of it, not
/// over it.
fn assert_beside(window: Rect, pixel: Pos2) {
    let gap = (window.min.x - pixel.x).max(pixel.x - window.max.x);
    assert!(
        (20.0..=40.0).contains(&gap),
        "{window:?} is not beside the pixel at {pixel:?} (gap {gap})"
    );
}

#[test]
fn the_window_sits_beside_the_pixel_scrolls_from_its_title_and_opens_at_the_top() {
    let mut harness = harness("window", false);
    // The mirror ball: its report has a reflection, the widest lines of all.
    let ball = object_on_screen(&harness, 2);
    click(&mut harness, ball, Modifiers::ALT);
    wait_for_probes(&mut harness);
    harness.run_ok();
    let window = window_rect(&harness);
    assert!(
        window.width() <= MAX_WIDTH,
        "{window:?} grew with its lines"
    );
    assert_beside(window, ball);
    let top = final_colour_offset(&harness);

    // The wheel over the title bar scrolls the contents.
    let title = window.left_top() + Vec2::new(window.width() * 0.5, 10.0);
    wheel(&mut harness, title, -6.0);
    let scrolled = final_colour_offset(&harness);
    assert!(scrolled < top - 20.0, "{top} -> {scrolled}");

    // A new pixel opens at the top, beside that pixel. It is an object's the window does
    // not cover (a click on the window would not reach the picture).
    let covered = window_rect(&harness).expand(4.0);
    let other = (1..harness.state().document().scene.objects.len())
        .filter(|&i| i != 2)
        .map(|i| object_on_screen(&harness, i))
        .find(|p| picture(&harness).contains(*p) && !covered.contains(*p))
        .expect("an object beside the window");
    let first = harness.state().view().looking.inspected;
    click(&mut harness, other, Modifiers::ALT);
    harness.run_ok();
    assert_ne!(
        harness.state().view().looking.inspected,
        first,
        "another pixel"
    );
    assert!(
        (final_colour_offset(&harness) - top).abs() < 1.0,
        "back at the top"
    );
    // The open window moved beside the new pixel.
    assert_beside(window_rect(&harness), other);
    assert!(picture(&harness).contains(other));
}

#[test]
fn every_light_is_listed_with_why_it_adds_nothing() {
    let mut harness = harness("lights", false);
    let scene = harness.state().document().scene.clone();
    let world = World::new(&scene).unwrap();
    // A pixel of the floor in the blue box's shadow, where the spotlight does not reach.
    let wanted = (0..scene.camera.height)
        .step_by(3)
        .flat_map(|y| (0..scene.camera.width).step_by(3).map(move |x| (x, y)))
        .find(|p| {
            let inspection = PixelInspection::traced(&world, &scene, TermSwitches::ALL_ON, *p);
            inspection.result.is_ok_and(|pixel| {
                let outcomes: Vec<&str> = pixel.bounces[0]
                    .lights
                    .iter()
                    .map(|l| l.outcome.as_str())
                    .collect();
                outcomes.contains(&"shadowed by blue box")
                    && outcomes.contains(&"outside the spot cone")
            })
        })
        .expect("such a pixel");
    let picture = picture(&harness);
    let pos = picture.min
        + Vec2::new(
            (wanted.0 as f32 + 0.5) / scene.camera.width as f32 * picture.width(),
            (wanted.1 as f32 + 0.5) / scene.camera.height as f32 * picture.height(),
        );
    click(&mut harness, pos, Modifiers::ALT);
    wait_for_probes(&mut harness);
    assert_eq!(harness.state().view().looking.inspected, Some(wanted));
    // Each light is named in the window as well as in the outliner.
    for label in [
        "Ambient light 1",
        "Point light 2",
        "Directional light 3",
        "Spot light 4",
    ] {
        assert!(harness.get_all_by_label(label).count() >= 2, "{label}");
    }
    for outcome in ["shadowed by blue box", "outside the spot cone"] {
        assert!(harness.get_all_by_label(outcome).count() >= 1, "{outcome}");
    }
}

#[test]
fn a_window_the_user_moved_stays_put_and_fits_the_screen() {
    let mut harness = harness("window_moved", false);
    let ball = object_on_screen(&harness, 2);
    click(&mut harness, ball, Modifiers::ALT);
    wait_for_probes(&mut harness);
    harness.run_ok();
    // Dragged by its title to the bottom-right corner.
    view_harness::move_inspector_away(&mut harness);
    harness.run_ok();
    let moved = window_rect(&harness);
    let screen = harness.ctx.content_rect();
    assert!(
        screen.contains_rect(moved.shrink(1.0)),
        "{moved:?} runs off {screen:?}"
    );
    // Another pixel: the window stays where the user put it.
    let other = (1..harness.state().document().scene.objects.len())
        .filter(|&i| i != 2)
        .map(|i| object_on_screen(&harness, i))
        .find(|p| picture(&harness).contains(*p) && !moved.expand(4.0).contains(*p))
        .expect("an object the window does not cover");
    let first = harness.state().view().looking.inspected;
    click(&mut harness, other, Modifiers::ALT);
    harness.run_ok();
    assert_ne!(
        harness.state().view().looking.inspected,
        first,
        "another pixel"
    );
    let after = window_rect(&harness);
    assert!(
        (after.min - moved.min).length() < 1.0,
        "{moved:?} jumped to {after:?}"
    );
}
