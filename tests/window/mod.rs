//! Running the real editor binary in a virtual X server and collecting its screenshot,
//! shared by the window tests. Needs `xvfb-run` (packages `xvfb` and `xauth`, which
//! `scripts/test.sh` installs); without it a test fails under CI and is skipped elsewhere.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long the editor may take to open, render and take its screenshot.
pub const TIMEOUT: Duration = Duration::from_secs(120);

/// Whether window tests can run here; `false` (with a notice) means skip. Under CI a
/// missing `xvfb-run` is a failure.
pub fn xvfb_available(test: &str) -> bool {
    let found = std::env::var_os("PATH").is_some_and(|paths| {
        std::env::split_paths(&paths).any(|dir| dir.join("xvfb-run").is_file())
    });
    if !found {
        assert!(
            std::env::var_os("CI").is_none(),
            "xvfb-run is missing: install xvfb and xauth"
        );
        eprintln!("notice: xvfb-run not found; skipping {test}");
    }
    found
}

/// A fresh folder for one test run.
pub fn fresh_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the editor in `dir` (its stored state kept there, away from the user's) with
/// the given arguments and extra environment, waits for it to save its screenshot to
/// `dir/name` and exit, and returns that path.
pub fn editor_screenshot(dir: &Path, name: &str, args: &[&Path], env: &[(&str, &str)]) -> PathBuf {
    let shot = dir.join(name);
    let mut command = Command::new("xvfb-run");
    command
        .args(["-a", "-s", "-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_raylab"))
        .args(args)
        .env("RAYLAB_SCREENSHOT", &shot)
        .env("XDG_DATA_HOME", dir.join("data"))
        .env("XDG_CONFIG_HOME", dir.join("config"))
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for (key, value) in env {
        command.env(key, value);
    }
    let mut child = command.spawn().expect("xvfb-run starts");
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
    shot
}
