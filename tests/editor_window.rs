//! The real editor binary in a virtual X server: it must open a window, render the
//! default scene into the viewport, take its own screenshot and exit. Needs `xvfb-run`
//! (package `xvfb` and `xauth`); without it the test fails under CI and is skipped
//! elsewhere with a notice.

mod window;

use std::collections::HashSet;

use window::{editor_screenshot, fresh_dir, xvfb_available};

#[test]
fn the_editor_window_shows_a_rendered_picture() {
    if !xvfb_available("the editor window test") {
        return;
    }
    let dir = fresh_dir("window");
    let shot = editor_screenshot(&dir, "editor.png", &[], &[]);

    let image = image::open(&shot)
        .expect("the screenshot is a PNG")
        .to_rgb8();
    assert!(
        image.width() >= 800 && image.height() >= 500,
        "{}x{}",
        image.width(),
        image.height()
    );
    // The viewport is the middle of the window: sample its central region.
    let (w, h) = (image.width(), image.height());
    let mut colours = HashSet::new();
    let mut sum = [0u64; 3];
    let mut count = 0u64;
    for y in h * 3 / 10..h * 7 / 10 {
        for x in w * 4 / 10..w * 6 / 10 {
            let p = image.get_pixel(x, y).0;
            colours.insert(p);
            for c in 0..3 {
                sum[c] += u64::from(p[c]);
            }
            count += 1;
        }
    }
    assert!(
        colours.len() > 500,
        "the viewport looks flat: {} distinct colours",
        colours.len()
    );
    let mean: Vec<u64> = sum.iter().map(|s| s / count).collect();
    assert!(
        mean.iter().any(|&m| m > 40),
        "the viewport is nearly black: mean {mean:?}"
    );
}
