//! The run: every pair of a class compared in parallel on all cores, scene by scene so
//! that each scene is prepared once for its pairs ([`SharedScenes`]), finished pairs
//! reused from the cache, a bad pair made a row with its error, and a stop asked for
//! honoured between pairs so that what is done is kept.
//!
//! The pairs run on plain threads, one per core of rayon's pool, taking the next pair in
//! scene order; each comparison's own work (the split, the fit) runs on the pool. Not
//! rayon jobs: a pair waits for its scene's preparation, and a rayon job waiting there
//! could be handed another pair of the same scene to run meanwhile on its own thread,
//! which would wait for itself.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use rayon::prelude::*;

use super::cache::{cached, pair_folder, pair_key, store};
use super::pair::{LoadedScene, PairResult, compare_pair};
use super::roster::{Roster, roster};
use super::shared::SharedScenes;
use crate::compare::{CompareOptions, OtherImage, check_size};
use crate::scene::{load_any_scene, read_meshes_beside};
use crate::trace::MeshStore;

/// How to compare the pairs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClassOptions {
    /// Samples per pixel of raylab's pictures; `None` for each scene's own.
    pub samples_per_pixel: Option<u32>,
}

/// What became of one student's render of one scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Compared; `reused` when the result came from the cache.
    Done {
        /// The result.
        result: PairResult,
        /// The pair's folder (images), relative to the report folder.
        folder: PathBuf,
        /// Whether the cache held it.
        reused: bool,
    },
    /// The student handed in no render of the scene.
    Missing,
    /// The pair could not be compared: the message says why.
    Error(String),
    /// The run was stopped before this pair.
    NotRun,
}

/// One row of the class table.
#[derive(Clone, Debug, PartialEq)]
pub struct PairRow {
    /// Index of the student in the roster.
    pub student: usize,
    /// Index of the scene in the roster.
    pub scene: usize,
    /// The render's file name, if there is one.
    pub picture: Option<String>,
    /// What became of it.
    pub outcome: Outcome,
}

/// A whole run: the roster, each scene's load, and a row per student and scene.
#[derive(Clone, Debug)]
pub struct ClassRun {
    /// The scenes and students, matched.
    pub roster: Roster,
    /// Per scene, why it could not be read, if it could not.
    pub scene_errors: Vec<Option<String>>,
    /// The scenes' loaders' warnings.
    pub warnings: Vec<String>,
    /// Student by student, scene by scene.
    pub rows: Vec<PairRow>,
    /// Pairs compared in this run.
    pub computed: usize,
    /// Pairs whose result came from the cache.
    pub reused: usize,
    /// Whether a stop was asked for before every pair was done.
    pub cancelled: bool,
}

/// Reads a scene and its meshes, and the bytes its pairs' keys hash.
fn load_scene_file(path: &Path) -> Result<(LoadedScene, Vec<String>), String> {
    let mut content =
        std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let (scene, mut warnings) = load_any_scene(path)?;
    let (data, mesh_warnings) = read_meshes_beside(&scene, path)?;
    warnings.extend(mesh_warnings);
    let folder = path.parent().unwrap_or(Path::new("."));
    for (_, mesh) in crate::scene::mesh_objects(&scene) {
        // Already read once by the mesh reader; read again for the key.
        if let Ok(bytes) = std::fs::read(crate::scene::mesh_file::mesh_path(folder, mesh)) {
            content.extend_from_slice(&bytes);
        }
    }
    let meshes = MeshStore::build(&data);
    Ok((
        LoadedScene {
            scene,
            meshes,
            content,
        },
        warnings,
    ))
}

/// `path` made absolute through its nearest existing ancestor (links resolved there), so
/// a folder not created yet can be placed before anything is written.
fn resolved(path: &Path) -> Result<PathBuf, String> {
    match std::fs::canonicalize(path) {
        Ok(canonical) => Ok(canonical),
        Err(e) => match (path.parent(), path.file_name()) {
            (Some(parent), Some(name)) => {
                let parent = if parent.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    parent
                };
                Ok(resolved(parent)?.join(name))
            }
            _ => Err(format!("cannot read {}: {e}", path.display())),
        },
    }
}

/// Refuses a report folder inside an input folder (or an input inside the report):
/// nothing in the inputs may be written, and the report must not become a student.
fn check_folders(scenes: &Path, submissions: &Path, report: &Path) -> Result<(), String> {
    let report_path = resolved(report)?;
    for input in [scenes, submissions] {
        let input_path = resolved(input)?;
        if report_path.starts_with(&input_path) || input_path.starts_with(&report_path) {
            return Err(format!(
                "the report folder {} and the input folder {} overlap; write the report elsewhere",
                report.display(),
                input.display()
            ));
        }
    }
    Ok(())
}

/// One pair's work: read the picture, reuse a cached result or compare it with scene
/// `index` (`scene`), prepared once in `shared`.
fn run_pair(
    (index, scene): (usize, &LoadedScene),
    shared: &SharedScenes,
    picture: &Path,
    options: &ClassOptions,
    report: &Path,
    computed: &AtomicUsize,
) -> Outcome {
    let bytes = match std::fs::read(picture) {
        Ok(bytes) => bytes,
        Err(e) => return Outcome::Error(format!("cannot read {}: {e}", picture.display())),
    };
    let option_text = format!("spp={:?}", options.samples_per_pixel);
    let key = pair_key(&scene.content, &bytes, &option_text);
    let folder = pair_folder(&key);
    if let Some(result) = cached(report, &key) {
        return Outcome::Done {
            result,
            folder,
            reused: true,
        };
    }
    let image = match OtherImage::from_bytes(&bytes, picture) {
        Ok(image) => image,
        Err(e) => return Outcome::Error(e.to_string()),
    };
    // A picture of another size needs no preparation of its scene.
    if let Err(e) = check_size(&scene.scene, &image) {
        return Outcome::Error(e.to_string());
    }
    let compare_options = CompareOptions {
        samples_per_pixel: options.samples_per_pixel,
    };
    let prepared = match shared.prepared(index, scene, &compare_options) {
        Ok(prepared) => prepared,
        Err(e) => return Outcome::Error(e),
    };
    match compare_pair(&prepared, &image, &report.join(&folder)) {
        Ok(result) => {
            if let Err(e) = store(report, &key, &result) {
                return Outcome::Error(e);
            }
            computed.fetch_add(1, Ordering::Relaxed);
            Outcome::Done {
                result,
                folder,
                reused: false,
            }
        }
        Err(e) => Outcome::Error(e),
    }
}

/// Matches `submissions` to `scenes` and compares every pair, writing each finished
/// pair to the cache in `report` (created if needed). `progress` is told `(done, total)`
/// pairs, first with none done; once `stop` is set no new pair starts (those running
/// finish and are kept).
///
/// # Errors
/// A folder cannot be read, the scenes folder holds no scene, or the report folder
/// overlaps an input folder. A bad pair or scene is a row, not an error.
pub fn run_class(
    scenes: &Path,
    submissions: &Path,
    report: &Path,
    options: &ClassOptions,
    stop: &AtomicBool,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<ClassRun, String> {
    let roster = roster(scenes, submissions)?;
    check_folders(scenes, submissions, report)?;
    std::fs::create_dir_all(report)
        .map_err(|e| format!("cannot create {}: {e}", report.display()))?;
    let loaded: Vec<Result<(LoadedScene, Vec<String>), String>> = roster
        .scenes
        .par_iter()
        .map(|s| load_scene_file(&s.path))
        .collect();
    let mut warnings = Vec::new();
    let mut scene_errors = Vec::new();
    let mut scenes_ready = Vec::new();
    for result in loaded {
        match result {
            Ok((scene, w)) => {
                warnings.extend(w);
                scene_errors.push(None);
                scenes_ready.push(Some(scene));
            }
            Err(e) => {
                scene_errors.push(Some(e));
                scenes_ready.push(None);
            }
        }
    }
    let mut rows = Vec::new();
    for (s, student) in roster.students.iter().enumerate() {
        for scene in 0..roster.scenes.len() {
            let picture = student.renders.get(&scene);
            rows.push(PairRow {
                student: s,
                scene,
                picture: picture.map(|p| {
                    p.file_name()
                        .unwrap_or_default()
                        .to_string_lossy()
                        .into_owned()
                }),
                outcome: if picture.is_none() {
                    Outcome::Missing
                } else {
                    Outcome::NotRun
                },
            });
        }
    }
    // The pairs to run, scene by scene (each scene's preparation made once and dropped
    // after its last pair); rows of a missing render have none.
    let mut queue: Vec<usize> = (0..rows.len())
        .filter(|&r| rows[r].picture.is_some())
        .collect();
    queue.sort_by_key(|&r| rows[r].scene);
    let total = queue.len();
    let mut per_scene = vec![0; roster.scenes.len()];
    for &r in &queue {
        per_scene[rows[r].scene] += 1;
    }
    let shared = SharedScenes::new(&per_scene);
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let computed = AtomicUsize::new(0);
    let outcomes = Mutex::new(Vec::with_capacity(total));
    progress(0, total);
    let rows_read = &rows;
    let worker = || {
        while !stop.load(Ordering::Relaxed) {
            let Some(&r) = queue.get(next.fetch_add(1, Ordering::Relaxed)) else {
                return;
            };
            let row = &rows_read[r];
            let picture = &roster.students[row.student].renders[&row.scene];
            let outcome = match (&scenes_ready[row.scene], &scene_errors[row.scene]) {
                (Some(scene), _) => run_pair(
                    (row.scene, scene),
                    &shared,
                    picture,
                    options,
                    report,
                    &computed,
                ),
                (None, error) => Outcome::Error(format!(
                    "the scene does not load: {}",
                    error.as_deref().unwrap_or("?")
                )),
            };
            shared.pair_done(row.scene);
            outcomes
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .push((r, outcome));
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
        }
    };
    std::thread::scope(|scope| {
        for _ in 0..rayon::current_num_threads().max(1) {
            scope.spawn(worker);
        }
    });
    for (r, outcome) in outcomes.into_inner().unwrap_or_else(|e| e.into_inner()) {
        rows[r].outcome = outcome;
    }
    let reused = rows
        .iter()
        .filter(|r| matches!(r.outcome, Outcome::Done { reused: true, .. }))
        .count();
    let cancelled = rows.iter().any(|r| r.outcome == Outcome::NotRun);
    Ok(ClassRun {
        roster,
        scene_errors,
        warnings,
        rows,
        computed: computed.into_inner(),
        reused,
        cancelled,
    })
}
