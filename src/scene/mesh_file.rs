//! Reading triangle meshes from Wavefront OBJ files (with the `tobj` crate) for
//! `Shape::Mesh`. The scene refers to the file by a path relative to the scene's folder;
//! nothing here ever writes an OBJ. Hostile input is refused with the file's name (and
//! the line, where one can be found); what can be skipped is skipped with a warning.

use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap};
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};

use super::obj_reader::{LoadWatch, WatchedReader, line_of_byte};
use super::{Object, Scene, SceneError, Shape};

/// The largest OBJ file read: about 20 million triangles. Larger files are refused before
/// reading a byte, so a stray multi-gigabyte file cannot exhaust memory.
pub const MAX_OBJ_FILE_BYTES: u64 = 1 << 30;

/// The largest coordinate accepted, in the file's units: far beyond any model, small
/// enough that products in the intersection test cannot overflow.
pub const MAX_OBJ_COORDINATE: f32 = 1e12;

/// A triangle mesh as read from a file: shared vertices, optional per-vertex normals.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// Vertex positions in object space.
    pub positions: Vec<[f32; 3]>,
    /// Per-vertex normals, same length as `positions`, or empty where the file has none.
    pub normals: Vec<[f32; 3]>,
    /// Triangles as indices into `positions`, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// What was skipped or ignored while reading, one sentence each.
    pub warnings: Vec<String>,
}

/// Reads an OBJ file: polygons fanned into triangles, negative (relative) indices
/// resolved, groups and materials ignored (with one warning), zero-area triangles
/// skipped (with one warning).
///
/// # Errors
/// A missing or unreadable file, one over [`MAX_OBJ_FILE_BYTES`], a syntax error or an
/// index out of range (with the line), a coordinate that is not finite or is larger than
/// [`MAX_OBJ_COORDINATE`] (with the line), or a file without a single usable triangle.
pub fn load_obj(path: &Path) -> Result<MeshData, SceneError> {
    load_obj_watched(path, &LoadWatch::default())
}

/// As [`load_obj`], reporting progress to `watch` and stopping when it is cancelled.
///
/// # Errors
/// As [`load_obj`]; and "loading was cancelled" once `watch` is cancelled.
pub fn load_obj_watched(path: &Path, watch: &LoadWatch) -> Result<MeshData, SceneError> {
    let file = std::fs::File::open(path).map_err(|source| read_error(path, source))?;
    let size = file
        .metadata()
        .map_err(|source| read_error(path, source))?
        .len();
    if size > MAX_OBJ_FILE_BYTES {
        return Err(invalid(
            path,
            None,
            &format!(
                "the file is {} MiB, over the {} MiB limit for OBJ files",
                size >> 20,
                MAX_OBJ_FILE_BYTES >> 20
            ),
        ));
    }
    watch.start(size);
    let mut reader = WatchedReader {
        inner: BufReader::new(file),
        watch,
    };
    let options = tobj::LoadOptions {
        triangulate: true,
        // Positions and normals keep their own indices (see `unify`): a file without
        // normals, or with normals indexed as its positions, is used without copying.
        single_index: false,
        ..tobj::LoadOptions::default()
    };
    let asked_for_materials = std::cell::Cell::new(false);
    let (models, _) = tobj::load_obj_buf(&mut reader, &options, |_| {
        asked_for_materials.set(true);
        Ok((Vec::new(), Default::default()))
    })
    .map_err(|error| {
        if watch.is_cancelled() {
            invalid(path, None, "loading was cancelled")
        } else {
            // The line the parser stopped in: the file's newlines up to where it was.
            let line =
                std::fs::File::open(path).map_or(1, |file| line_of_byte(file, watch.bytes_read()));
            invalid(path, Some(line), &error.to_string())
        }
    })?;
    let mut mesh = MeshData::default();
    let has_materials =
        asked_for_materials.get() || models.iter().any(|m| m.mesh.material_id.is_some());
    if models.len() > 1 || has_materials {
        mesh.warnings.push(format!(
            "{}: groups and materials in the file are ignored; the object's material applies",
            path.display()
        ));
    }
    let unified: Vec<Unified<'_>> = models.iter().map(|m| unify(&m.mesh)).collect();
    let with_normals = !unified.is_empty() && unified.iter().all(|m| !m.normals.is_empty());
    for model in &unified {
        append_model(path, model, with_normals, &mut mesh)?;
    }
    if mesh.triangles.is_empty() {
        return Err(invalid(path, None, "the file has no triangles with area"));
    }
    Ok(mesh)
}

/// A model's triangles over one index: per-vertex normals (or none) beside positions.
struct Unified<'m> {
    positions: Cow<'m, [f32]>,
    normals: Cow<'m, [f32]>,
    indices: Cow<'m, [u32]>,
}

/// A tobj model with one index for position and normal: borrowed where the file already
/// indexes them alike (or has no normals), else with a vertex for each pair used.
fn unify(model: &tobj::Mesh) -> Unified<'_> {
    let aligned = model.normal_indices.is_empty() || model.normal_indices == model.indices;
    if model.normals.is_empty() || (aligned && model.normals.len() == model.positions.len()) {
        return Unified {
            positions: Cow::Borrowed(&model.positions),
            normals: Cow::Borrowed(if aligned { &model.normals } else { &[] }),
            indices: Cow::Borrowed(&model.indices),
        };
    }
    if model.normal_indices.len() != model.indices.len() {
        // Some corners without a normal: the mesh is shaded flat.
        return Unified {
            positions: Cow::Borrowed(&model.positions),
            normals: Cow::Borrowed(&[]),
            indices: Cow::Borrowed(&model.indices),
        };
    }
    let mut seen = HashMap::new();
    let (mut positions, mut normals, mut indices) = (Vec::new(), Vec::new(), Vec::new());
    for (&p, &n) in model.indices.iter().zip(&model.normal_indices) {
        let next = u32::try_from(seen.len()).unwrap_or(u32::MAX);
        let index = *seen.entry((p, n)).or_insert_with(|| {
            let (p, n) = (p as usize * 3, n as usize * 3);
            // Out-of-range indices were refused by tobj; guard anyway with NaN, which
            // the coordinate check then reports.
            positions.extend(model.positions.get(p..p + 3).unwrap_or(&[f32::NAN; 3]));
            normals.extend(model.normals.get(n..n + 3).unwrap_or(&[0.0; 3]));
            next
        });
        indices.push(index);
    }
    Unified {
        positions: Cow::Owned(positions),
        normals: Cow::Owned(normals),
        indices: Cow::Owned(indices),
    }
}

/// Appends one model's vertices and triangles, checking coordinates and indices.
fn append_model(
    path: &Path,
    model: &Unified<'_>,
    with_normals: bool,
    mesh: &mut MeshData,
) -> Result<(), SceneError> {
    let base = u32::try_from(mesh.positions.len())
        .map_err(|_| invalid(path, None, "the file has more than 4 billion vertices"))?;
    for chunk in model.positions.chunks_exact(3) {
        let p = [chunk[0], chunk[1], chunk[2]];
        if !p
            .iter()
            .all(|c| c.is_finite() && c.abs() <= MAX_OBJ_COORDINATE)
        {
            let line = find_bad_vertex_line(path);
            return Err(invalid(
                path,
                line,
                &format!(
                    "vertex ({}, {}, {}) is not finite or is larger than {MAX_OBJ_COORDINATE:e}",
                    p[0], p[1], p[2]
                ),
            ));
        }
        mesh.positions.push(p);
    }
    if with_normals {
        for chunk in model.normals.chunks_exact(3) {
            let n = [chunk[0], chunk[1], chunk[2]];
            // A broken normal is harmless: the flat normal stands in for it.
            let ok = n.iter().all(|c| c.is_finite()) && n.iter().any(|c| *c != 0.0);
            mesh.normals.push(if ok { n } else { [0.0; 3] });
        }
    }
    let count = model.positions.len() / 3;
    let mut skipped = 0_usize;
    for corners in model.indices.chunks_exact(3) {
        if corners.iter().any(|&i| i as usize >= count) {
            return Err(invalid(
                path,
                None,
                "a face refers to a vertex that does not exist",
            ));
        }
        let [a, b, c] =
            [corners[0], corners[1], corners[2]].map(|i| mesh.positions[(base + i) as usize]);
        if zero_area(a, b, c) {
            skipped += 1;
            continue;
        }
        mesh.triangles
            .push([corners[0] + base, corners[1] + base, corners[2] + base]);
    }
    if skipped > 0 {
        mesh.warnings.push(format!(
            "{}: {skipped} triangle(s) with zero area skipped",
            path.display()
        ));
    }
    Ok(())
}

/// Whether a triangle has no area (its corners are on one line), exactly in f64.
fn zero_area(a: [f32; 3], b: [f32; 3], c: [f32; 3]) -> bool {
    let d = |p: [f32; 3], q: [f32; 3]| [0, 1, 2].map(|i| f64::from(p[i]) - f64::from(q[i]));
    let (e1, e2) = (d(b, a), d(c, a));
    let cross = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    cross.iter().all(|c| *c == 0.0)
}

/// The 1-based line of the first vertex line whose coordinates are out of bounds, found
/// again only on the error path (tobj reports values, not lines).
fn find_bad_vertex_line(path: &Path) -> Option<usize> {
    let reader = BufReader::new(std::fs::File::open(path).ok()?);
    reader.lines().enumerate().find_map(|(index, line)| {
        let line = line.ok()?;
        let rest = line.trim_start().strip_prefix("v ")?;
        rest.split_whitespace()
            .take(3)
            .any(|word| {
                word.parse::<f32>()
                    .is_ok_and(|c| !c.is_finite() || c.abs() > MAX_OBJ_COORDINATE)
            })
            .then_some(index + 1)
    })
}

/// Every mesh object of a scene (through trees too) with its path as written, in scene
/// order. No file is touched.
#[must_use]
pub fn mesh_objects(scene: &Scene) -> Vec<(&Object, &str)> {
    scene
        .nodes()
        .filter_map(|node| match &node.object.shape {
            Shape::Mesh { path } => Some((node.object, path.as_str())),
            _ => None,
        })
        .collect()
}

/// Every mesh file a scene refers to, read from the scene's folder, keyed by the path as
/// written in the scene. Each file is read once, in scene order.
///
/// # Errors
/// The first file that cannot be read, named with the object that refers to it.
pub fn read_scene_meshes(
    scene: &Scene,
    folder: &Path,
) -> Result<BTreeMap<String, MeshData>, SceneError> {
    let mut meshes = BTreeMap::new();
    for (object, path) in mesh_objects(scene) {
        if meshes.contains_key(path) {
            continue;
        }
        let data = load_obj(&mesh_path(folder, path))
            .map_err(|error| SceneError::Invalid(format!("object \"{}\": {error}", object.name)))?;
        meshes.insert(path.to_owned(), data);
    }
    Ok(meshes)
}

/// Writes every mesh path of `scene` that is absolute and lies under `folder` relative to
/// it (with `/` separators), so a scene saved in `folder` keeps working when the folder
/// moves. Other paths are left as they are.
pub fn relative_mesh_paths(scene: &mut Scene, folder: &Path) {
    scene.edit_nodes(|object| {
        if let Shape::Mesh { path } = &mut object.shape
            && let Ok(below) = Path::new(path.as_str()).strip_prefix(folder)
            && Path::new(path.as_str()).is_absolute()
            && let Some(text) = below.to_str()
        {
            *path = text.replace('\\', "/");
        }
    });
}

/// Where a mesh path written in a scene points, for a scene in `folder`.
#[must_use]
pub fn mesh_path(folder: &Path, path: &str) -> PathBuf {
    folder.join(path)
}

fn read_error(path: &Path, source: std::io::Error) -> SceneError {
    SceneError::Read {
        path: path.to_path_buf(),
        source,
    }
}

/// The last part of a mesh path as the scene writes it (`"meshes/knot.obj"` gives
/// `"knot.obj"`), for a short label; the path itself where it has none.
#[must_use]
pub fn mesh_file_name(path: &str) -> String {
    Path::new(path)
        .file_name()
        .map_or(path.to_owned(), |n| n.to_string_lossy().into_owned())
}

fn invalid(path: &Path, line: Option<usize>, message: &str) -> SceneError {
    SceneError::Invalid(match line {
        Some(line) => format!("{}, line {line}: {message}", path.display()),
        None => format!("{}: {message}", path.display()),
    })
}
