//! The panels around the viewport: the menu bar, the error and warning banners, the
//! outliner, the inspector and the status bar, each with one `*_ui` entry point that pushes commands.

pub mod inspector;
pub mod menu;
pub mod notices;
pub mod outliner;
mod outliner_tree;
pub mod status_bar;

/// The last part of a path as the scene writes it (`"meshes/knot.obj"` gives
/// `"knot.obj"`), for a short label; the path itself where it has none.
#[must_use]
pub fn file_name(path: &str) -> String {
    std::path::Path::new(path)
        .file_name()
        .map_or(path.to_owned(), |n| n.to_string_lossy().into_owned())
}
