//! Saving never leaves a half-written file: not when the folder is read-only, and not
//! when the process dies between writing the new file and renaming it into place.

use std::path::{Path, PathBuf};
use std::process::Command;

use raylab::scene::{SceneError, parse_scene, save_scene, write_atomically_with};

const SCENE: &str = "Scene(materials: {\"m\": ()}, objects: [(shape: Sphere, material: \"m\")])";

fn fresh_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-atomic-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Makes a folder read-only for the duration of a test, even for root (who ignores
/// permission bits): permissions first, then the immutable attribute if needed.
struct ReadOnlyDir(PathBuf);

impl ReadOnlyDir {
    fn new(dir: &Path) -> Self {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o555)).unwrap();
        let guard = ReadOnlyDir(dir.to_owned());
        if std::fs::File::create(dir.join("probe")).is_ok() {
            let _ = std::fs::remove_file(dir.join("probe"));
            let status = Command::new("chattr").arg("+i").arg(dir).status();
            assert!(
                status.is_ok_and(|s| s.success()),
                "cannot make {} read-only (running as root without chattr)",
                dir.display()
            );
            assert!(std::fs::File::create(dir.join("probe")).is_err());
        }
        guard
    }
}

impl Drop for ReadOnlyDir {
    fn drop(&mut self) {
        use std::os::unix::fs::PermissionsExt;
        let _ = Command::new("chattr").arg("-i").arg(&self.0).status();
        let _ = std::fs::set_permissions(&self.0, std::fs::Permissions::from_mode(0o755));
    }
}

#[test]
fn saving_into_a_read_only_folder_fails_clearly_and_keeps_the_old_file() {
    let dir = fresh_dir("readonly");
    let path = dir.join("scene.ron");
    std::fs::write(&path, "old contents").unwrap();
    let scene = parse_scene(SCENE).unwrap();
    {
        let _read_only = ReadOnlyDir::new(&dir);
        let error = save_scene(&scene, &path).unwrap_err();
        assert!(matches!(error, SceneError::Write { .. }), "{error}");
        let message = error.to_string();
        assert!(
            message.contains("cannot write") && message.contains("scene.ron"),
            "{message}"
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old contents");
    }
    // Writable again: the save goes through.
    save_scene(&scene, &path).unwrap();
    assert!(
        std::fs::read_to_string(&path)
            .unwrap()
            .starts_with("Scene(")
    );
}

/// The child half of the kill test: writes and dies just before the rename.
#[test]
#[ignore = "run by a_kill_between_write_and_rename_leaves_the_old_file as a child process"]
fn child_writes_then_dies_before_rename() {
    let Some(target) = std::env::var_os("RAYLAB_ATOMIC_CHILD_TARGET") else {
        return;
    };
    let _ = write_atomically_with(Path::new(&target), b"new contents, never seen", || {
        std::process::abort()
    });
    unreachable!("the process aborts before the rename");
}

#[test]
fn a_kill_between_write_and_rename_leaves_the_old_file() {
    let dir = fresh_dir("kill");
    let path = dir.join("scene.ron");
    std::fs::write(&path, "old contents").unwrap();
    let status = Command::new(std::env::current_exe().unwrap())
        .args([
            "child_writes_then_dies_before_rename",
            "--exact",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("RAYLAB_ATOMIC_CHILD_TARGET", &path)
        .status()
        .unwrap();
    assert!(!status.success(), "the child must have died");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old contents");
    // What the child wrote is complete in its temporary file, beside the intact original.
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 2, "{leftovers:?}");
}
