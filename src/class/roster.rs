//! Which render belongs to which scene: the scenes of a class (a folder of `.ron` and
//! course `.txt` files) and each student's folder of renders, matched by file name
//! without extension, ignoring case and a suffix such as `_render`, `-out` or `_final`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Extensions of scene files.
const SCENE_EXTENSIONS: [&str; 2] = ["ron", "txt"];

/// Words a student may add after the scene's name, each after `_`, `-`, `.` or a space;
/// several may follow one another (`default_render_final.png`).
const SUFFIXES: [&str; 8] = [
    "render",
    "rendered",
    "out",
    "output",
    "final",
    "image",
    "result",
    "raytraced",
];

/// One scene of the class.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneFile {
    /// The file name without extension, as written (`default`).
    pub name: String,
    /// The file.
    pub path: PathBuf,
}

/// One student's folder, matched against the scenes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Student {
    /// The folder's name.
    pub name: String,
    /// For each scene index, the render that matched it.
    pub renders: BTreeMap<usize, PathBuf>,
    /// Files that matched no scene (or a scene another file already matched), by name.
    pub unmatched: Vec<String>,
}

impl Student {
    /// Indices of the scenes (of `scene_count`) with no render.
    #[must_use]
    pub fn missing(&self, scene_count: usize) -> Vec<usize> {
        (0..scene_count)
            .filter(|s| !self.renders.contains_key(s))
            .collect()
    }
}

/// The scenes and the students, matched.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Roster {
    /// The scenes, sorted by name.
    pub scenes: Vec<SceneFile>,
    /// The students, sorted by name.
    pub students: Vec<Student>,
    /// Files directly in the submissions folder, outside any student's folder.
    pub loose_files: Vec<String>,
}

/// The key a file name is matched by: lowercase, without extension.
fn stem_key(path: &Path) -> String {
    path.file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .to_lowercase()
}

/// `key` and the keys left after taking off suffix words one at a time from the end,
/// longest first.
fn candidate_keys(key: &str) -> Vec<String> {
    let mut keys = vec![key.to_owned()];
    let mut rest = key;
    while let Some((head, last)) = rest.rsplit_once(['_', '-', '.', ' ']) {
        if !SUFFIXES.contains(&last) || head.is_empty() {
            break;
        }
        keys.push(head.to_owned());
        rest = head;
    }
    keys
}

/// Entries of a folder, sorted by name, hidden ones (a leading `.`) left out.
fn entries(folder: &Path) -> Result<Vec<PathBuf>, String> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(folder)
        .map_err(|e| format!("cannot read {}: {e}", folder.display()))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| {
            !p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    paths.sort();
    Ok(paths)
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned()
}

/// The scene files of `folder`, sorted by name.
///
/// # Errors
/// The folder cannot be read, holds no scene, or two scenes share a name (ignoring case
/// and extension: `a.ron` and `A.txt` could not be told apart by a render's name).
pub fn scene_files(folder: &Path) -> Result<Vec<SceneFile>, String> {
    let scenes: Vec<SceneFile> = entries(folder)?
        .into_iter()
        .filter(|p| p.is_file())
        .filter(|p| {
            p.extension()
                .is_some_and(|x| SCENE_EXTENSIONS.iter().any(|e| x.eq_ignore_ascii_case(e)))
        })
        .map(|path| SceneFile {
            name: path
                .file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned(),
            path,
        })
        .collect();
    if scenes.is_empty() {
        return Err(format!(
            "{} holds no scene (.ron or course .txt)",
            folder.display()
        ));
    }
    for (i, a) in scenes.iter().enumerate() {
        if let Some(b) = scenes[i + 1..]
            .iter()
            .find(|b| stem_key(&b.path) == stem_key(&a.path))
        {
            return Err(format!(
                "{} and {} have the same name: a render could not say which it is",
                a.path.display(),
                b.path.display()
            ));
        }
    }
    Ok(scenes)
}

/// Matches one student's files to `scenes`: an exact name (ignoring case) first, then a
/// name with suffix words taken off; a second file for a scene is unmatched.
#[must_use]
pub fn match_student(name: String, files: &[PathBuf], scenes: &[SceneFile]) -> Student {
    let index: BTreeMap<String, usize> = scenes
        .iter()
        .enumerate()
        .map(|(i, s)| (stem_key(&s.path), i))
        .collect();
    let mut student = Student {
        name,
        ..Student::default()
    };
    let found: Vec<Option<(usize, usize)>> = files
        .iter()
        .map(|file| {
            candidate_keys(&stem_key(file))
                .iter()
                .enumerate()
                .find_map(|(strip, key)| index.get(key).map(|&s| (s, strip)))
        })
        .collect();
    // Fewer suffix words taken off wins a scene: `default.png` before `default_final.png`.
    let mut order: Vec<usize> = (0..files.len()).collect();
    order.sort_by_key(|&f| found[f].map_or(usize::MAX, |(_, strip)| strip));
    for f in order {
        match found[f] {
            Some((scene, _)) if !student.renders.contains_key(&scene) => {
                student.renders.insert(scene, files[f].clone());
            }
            _ => student.unmatched.push(file_name(&files[f])),
        }
    }
    student.unmatched.sort();
    student
}

/// Reads the scenes and the students' folders and matches them. Nothing is written.
///
/// # Errors
/// A folder cannot be read, or the scenes folder holds no scene (see [`scene_files`]).
pub fn roster(scenes: &Path, submissions: &Path) -> Result<Roster, String> {
    let scenes = scene_files(scenes)?;
    let mut roster = Roster {
        scenes,
        ..Roster::default()
    };
    for path in entries(submissions)? {
        if path.is_dir() {
            let files: Vec<PathBuf> = entries(&path)?
                .into_iter()
                .filter(|p| p.is_file())
                .collect();
            let student = match_student(file_name(&path), &files, &roster.scenes);
            roster.students.push(student);
        } else {
            roster.loose_files.push(file_name(&path));
        }
    }
    Ok(roster)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scenes(names: &[&str]) -> Vec<SceneFile> {
        names
            .iter()
            .map(|n| SceneFile {
                name: (*n).to_owned(),
                path: PathBuf::from(format!("{n}.ron")),
            })
            .collect()
    }

    #[test]
    fn names_match_ignoring_case_extension_and_suffixes() {
        let scenes = scenes(&["default", "glass", "mirror_cap", "shapes"]);
        let files: Vec<PathBuf> = [
            "Default.PNG",
            "glass_render.ppm",
            "mirror_cap-out_final.png",
            "notes.txt",
            "shapes_v2.png",
        ]
        .iter()
        .map(PathBuf::from)
        .collect();
        let student = match_student("ann".to_owned(), &files, &scenes);
        assert_eq!(student.renders[&0], PathBuf::from("Default.PNG"));
        assert_eq!(student.renders[&1], PathBuf::from("glass_render.ppm"));
        assert_eq!(
            student.renders[&2],
            PathBuf::from("mirror_cap-out_final.png")
        );
        assert_eq!(student.unmatched, vec!["notes.txt", "shapes_v2.png"]);
        assert_eq!(student.missing(4), vec![3]);
    }

    #[test]
    fn an_exact_name_wins_over_a_suffixed_one() {
        let scenes = scenes(&["default"]);
        let files: Vec<PathBuf> = ["default_render.png", "default.png"]
            .iter()
            .map(PathBuf::from)
            .collect();
        let student = match_student("bo".to_owned(), &files, &scenes);
        assert_eq!(student.renders[&0], PathBuf::from("default.png"));
        assert_eq!(student.unmatched, vec!["default_render.png"]);
    }
}
