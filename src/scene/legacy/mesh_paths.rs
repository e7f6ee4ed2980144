//! Mesh paths of an imported scene, moved from the legacy file's folder to the folder
//! the scene is written to (the scene format reads them relative to the scene file).

use std::path::{Component, Path, PathBuf};

use crate::scene::{Scene, Shape};

/// Rewrites every relative `Mesh` path of `scene`, written relative to `from_folder`, to
/// name the same file relative to `to_folder`. Paths are compared lexically (after
/// making them absolute against the working directory); absolute paths are left alone.
pub fn rebase_mesh_paths(scene: &mut Scene, from_folder: &Path, to_folder: &Path) {
    let (Ok(from), Ok(to)) = (
        std::path::absolute(from_folder),
        std::path::absolute(to_folder),
    ) else {
        return;
    };
    let (from, to) = (normalised(&from), normalised(&to));
    if from == to {
        return;
    }
    scene.edit_nodes(|object| {
        if let Shape::Mesh { path } = &mut object.shape
            && Path::new(path.as_str()).is_relative()
        {
            *path = relative_to(&normalised(&from.join(&*path)), &to);
        }
    });
}

/// `path` without `.` and with each `..` taking back the component before it.
fn normalised(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// `target` as seen from `folder` (both absolute and normalised), with `/` separators.
fn relative_to(target: &Path, folder: &Path) -> String {
    let common = target
        .components()
        .zip(folder.components())
        .take_while(|(a, b)| a == b)
        .count();
    let mut out = PathBuf::new();
    for _ in folder.components().skip(common) {
        out.push("..");
    }
    for component in target.components().skip(common) {
        out.push(component);
    }
    out.to_string_lossy().replace('\\', "/")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Object;

    fn scene_with_mesh(path: &str) -> Scene {
        let leaf = Object {
            name: "m".into(),
            shape: Shape::Mesh { path: path.into() },
            transform: Default::default(),
            material: "x".into(),
        };
        Scene {
            objects: vec![Object {
                name: "g".into(),
                shape: Shape::Group {
                    children: vec![leaf],
                },
                transform: Default::default(),
                material: String::new(),
            }],
            ..Scene::empty()
        }
    }

    fn mesh_path(scene: &Scene) -> &str {
        match &scene.objects[0].shape.children()[0].shape {
            Shape::Mesh { path } => path,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_mesh_beside_the_legacy_file_is_found_from_the_output_folder() {
        let mut scene = scene_with_mesh("../scenes/x.obj");
        rebase_mesh_paths(&mut scene, Path::new("/a/legacy"), Path::new("/a/out/ron"));
        assert_eq!(mesh_path(&scene), "../../scenes/x.obj");
        let mut scene = scene_with_mesh("x.obj");
        rebase_mesh_paths(
            &mut scene,
            Path::new("/a/legacy"),
            Path::new("/a/legacy/./"),
        );
        assert_eq!(mesh_path(&scene), "x.obj");
        let mut scene = scene_with_mesh("/abs/x.obj");
        rebase_mesh_paths(&mut scene, Path::new("/a"), Path::new("/b"));
        assert_eq!(mesh_path(&scene), "/abs/x.obj");
    }
}
