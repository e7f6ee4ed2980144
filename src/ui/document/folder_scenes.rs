//! File > Open Next / Previous in Folder: the scene files beside the current one, in
//! name order, for going through a class's scenes one after another.

use std::path::{Path, PathBuf};

/// Whether `path` is a file Open takes: a RON scene or a course `.txt` scene.
fn is_openable(path: &Path) -> bool {
    path.is_file()
        && path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("ron") || e.eq_ignore_ascii_case("txt"))
}

/// The scene file after `current` in its folder (before it, when `forward` is false), by
/// name; `None` at either end or when the folder cannot be read.
#[must_use]
pub fn neighbour_scene(current: &Path, forward: bool) -> Option<PathBuf> {
    let folder = current.parent().filter(|f| !f.as_os_str().is_empty());
    let folder = folder.unwrap_or(Path::new("."));
    let mut files: Vec<PathBuf> = std::fs::read_dir(folder)
        .ok()?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| is_openable(p))
        .collect();
    files.sort();
    let name = current.file_name()?;
    // The current file's place among its neighbours (it may be gone, or not a scene).
    let after = files.partition_point(|p| p.file_name().is_some_and(|n| n <= name));
    let before = files.partition_point(|p| p.file_name().is_some_and(|n| n < name));
    if forward {
        files.get(after).cloned()
    } else {
        before.checked_sub(1).and_then(|i| files.get(i).cloned())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_through_the_scene_files_of_a_folder_by_name() {
        let dir = std::env::temp_dir().join(format!("raylab-folder-scenes-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for name in ["b.txt", "a.ron", "c.TXT", "b-notes.md", "d.png"] {
            std::fs::write(dir.join(name), "x").unwrap();
        }
        let next = |name: &str| neighbour_scene(&dir.join(name), true);
        let previous = |name: &str| neighbour_scene(&dir.join(name), false);
        assert_eq!(next("a.ron"), Some(dir.join("b.txt")));
        assert_eq!(next("b.txt"), Some(dir.join("c.TXT")));
        assert_eq!(next("c.TXT"), None, "the last one");
        assert_eq!(previous("b.txt"), Some(dir.join("a.ron")));
        assert_eq!(previous("a.ron"), None, "the first one");
        assert_eq!(
            next("b-notes.md"),
            Some(dir.join("b.txt")),
            "by name from anything"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
