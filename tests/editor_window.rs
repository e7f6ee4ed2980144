//! The real editor binary in a virtual X server: it must open a window, render the
//! default scene into the viewport, take its own screenshot and exit. Needs `xvfb-run`
//! (package `xvfb` and `xauth`); without it the test fails under CI and is skipped
//! elsewhere with a notice.

use std::collections::HashSet;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const TIMEOUT: Duration = Duration::from_secs(120);

fn has_xvfb_run() -> bool {
    std::env::var_os("PATH").is_some_and(|paths| {
        std::env::split_paths(&paths).any(|dir| dir.join("xvfb-run").is_file())
    })
}

#[test]
fn the_editor_window_shows_a_rendered_picture() {
    if !has_xvfb_run() {
        assert!(
            std::env::var_os("CI").is_none(),
            "xvfb-run is missing: install xvfb and xauth"
        );
        eprintln!("notice: xvfb-run not found; skipping the editor window test");
        return;
    }
    let dir = std::env::temp_dir().join(format!("raylab-window-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let shot: PathBuf = dir.join("editor.png");

    let mut child = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_raylab"))
        .env("RAYLAB_SCREENSHOT", &shot)
        // Keep the user's stored editor state out of it, and ours out of theirs.
        .env("XDG_DATA_HOME", dir.join("data"))
        .env("XDG_CONFIG_HOME", dir.join("config"))
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("xvfb-run starts");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > TIMEOUT {
            let _ = child.kill();
            let output = child.wait_with_output().unwrap();
            panic!(
                "the editor did not finish within {TIMEOUT:?}\nstderr:\n{}",
                String::from_utf8_lossy(&output.stderr)
            );
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let output = child.wait_with_output().unwrap();
    assert!(
        status.success() && shot.exists(),
        "the editor exited with {status} without a screenshot\nstderr:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );

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
