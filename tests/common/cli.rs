//! Helpers for the command-line tests: run the `raylab` binary, and a scratch folder.

use std::path::PathBuf;
use std::process::{Command, Output};

use raylab::cli::RenderArgs;
use raylab::scene::Scene;
use raylab::trace::{RenderOptions, Term, View};

/// Runs the built `raylab` binary with `args` and returns what it printed and its exit.
pub fn raylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raylab"))
        .args(args)
        .output()
        .unwrap()
}

/// A scratch folder for one test binary's outputs, `raylab-<name>-<pid>` under the
/// system temp folder, created if missing.
pub fn out_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Render options as `raylab render scene.ron --off .. --solo .. --view ..` builds them
/// from its arguments.
pub fn cli_options(scene: &Scene, off: &[Term], solo: Option<Term>, view: View) -> RenderOptions {
    let args = RenderArgs {
        scene: "scene.ron".into(),
        output: "out.png".into(),
        width: None,
        height: None,
        spp: None,
        off: off.to_vec(),
        solo,
        view,
        isolation: Default::default(),
        conventions: Default::default(),
        bug: None,
    };
    args.options(scene).unwrap()
}
