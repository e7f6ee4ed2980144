//! The real editor binary in a virtual X server, with the spotlight selected: its cone,
//! tip and rim handles and the translate gizmo must be drawn over the preview. Compared
//! with a run where nothing with a gizmo is selected, so the rendered picture's own
//! colours cannot pass for the gizmo's. Needs `xvfb-run`; skipped elsewhere with a
//! notice (and failing under CI).
//!
//! The documentation's picture comes from the same run:
//! `RAYLAB_GIZMO_DOCS=1 cargo test --test gizmo_window` writes `docs/gizmos.png`.

mod window;

use std::path::Path;

use glam::DVec3;
use raylab::ui::files::{default_scene, save_scene_to};
use window::{editor_screenshot, fresh_dir, xvfb_available};

/// The cone's colour and the x axis colour, as the overlay paints them.
const CONE: [u8; 3] = [255, 196, 64];
const X_AXIS: [u8; 3] = [236, 72, 80];

/// Runs the editor on `scene` with `select` selected, returns the screenshot.
fn screenshot(
    dir: &Path,
    scene: &Path,
    select: &str,
    name: &str,
    final_frame: bool,
) -> std::path::PathBuf {
    let mut env = vec![("RAYLAB_SCREENSHOT_SELECT", select)];
    if final_frame {
        env.push(("RAYLAB_SCREENSHOT_FINAL", "1"));
    }
    editor_screenshot(dir, name, &[scene], &env)
}

/// Pixels within a small distance of `colour`.
fn count_near(image: &image::RgbImage, colour: [u8; 3]) -> usize {
    image
        .pixels()
        .filter(|p| {
            p.0.iter()
                .zip(colour)
                .all(|(&a, b)| (i32::from(a) - i32::from(b)).abs() <= 6)
        })
        .count()
}

#[test]
fn a_selected_spotlight_shows_its_cone_and_handles_over_the_preview() {
    if !xvfb_available("the gizmo window test") {
        return;
    }
    let dir = fresh_dir("gizmo-window");
    // The default scene seen from higher up and further back, so the spotlight is in view.
    let mut scene = default_scene();
    scene.camera.position = DVec3::new(4.6, 6.8, 12.8);
    scene.camera.look_at = DVec3::new(0.7, 2.3, 0.5);
    let scene_path = dir.join("spotlight.ron");
    save_scene_to(&scene, &scene_path).unwrap();

    let docs = std::env::var_os("RAYLAB_GIZMO_DOCS").is_some();
    let selected = screenshot(&dir, &scene_path, "Spot light 4", "spot.png", docs);
    let plain = screenshot(&dir, &scene_path, "Camera", "camera.png", false);
    let selected = image::open(&selected).expect("a PNG").to_rgb8();
    let plain = image::open(&plain).expect("a PNG").to_rgb8();

    let (cone, cone_plain) = (count_near(&selected, CONE), count_near(&plain, CONE));
    assert!(
        cone > cone_plain + 400,
        "the cone and its handles: {cone} cone-coloured pixels, {cone_plain} without the gizmo"
    );
    let (x, x_plain) = (count_near(&selected, X_AXIS), count_near(&plain, X_AXIS));
    assert!(
        x > x_plain + 40,
        "the translate gizmo's x arrow: {x} pixels, {x_plain} without it"
    );
    if docs {
        let out = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/gizmos.png");
        selected.save(&out).unwrap();
        eprintln!("wrote {}", out.display());
    }
}
