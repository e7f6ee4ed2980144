//! Everything the panels can ask for, as values. Panels push commands while laying out;
//! the app applies them once per frame (`app.rs`), which also feeds undo and restarts the
//! preview. Scene edits are plain functions here, testable without a window; edits of the
//! object trees go through `scene::tree`.

mod placement;
mod scene_edit;
mod selection;

use std::path::PathBuf;

pub use crate::scene::LightKind;
pub use crate::scene::tree::unique_name;
pub use scene_edit::{CSG_OPS, SceneEdit, material_users};
pub use selection::{Selection, repair_selection};

/// Everything a panel, shortcut or dialog can ask the app to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Change what the inspector shows.
    Select(Selection),
    /// Edit the scene (one undo step, unless part of a drag).
    Edit(SceneEdit),
    /// Go back one undo step.
    Undo,
    /// Go forward one undo step.
    Redo,
    /// Replace the scene by a new one (asks first if there are unsaved changes).
    New,
    /// Show the Open dialog (asks first if there are unsaved changes).
    OpenDialog,
    /// Open a scene file (asks first if there are unsaved changes).
    Open(PathBuf),
    /// Open the next scene file in the current one's folder (`false`: the previous one).
    OpenInFolder {
        /// Whether to step to the next file by name (else the previous).
        forward: bool,
    },
    /// Save to the current file, or ask for one.
    Save,
    /// Show the Save As dialog.
    SaveAsDialog,
    /// Save to a file, which becomes the current file.
    SaveAs(PathBuf),
    /// Show the Import Legacy dialog (asks first if there are unsaved changes).
    ImportLegacyDialog,
    /// Import a legacy text scene (asks first if there are unsaved changes).
    ImportLegacy(PathBuf),
    /// Show the Import OBJ dialog: the mesh picked joins the scene as a Mesh object.
    ImportObjDialog,
    /// Add a Mesh object for the OBJ file at this path (named after the file).
    ImportObj(PathBuf),
    /// Stop reading the mesh file the preview is reading.
    CancelMeshLoading,
    /// Show the Export PNG window.
    ShowExport,
    /// Show the Export Course Scene dialog for a framework's dialect.
    ExportCourseDialog(crate::scene::legacy::Dialect),
    /// Write the scene in the course's text format, in a dialect, to a file.
    ExportCourse(PathBuf, crate::scene::legacy::Dialect),
    /// Show the keyboard shortcuts.
    ShowHelp,
    /// Close the window (asks first if there are unsaved changes).
    Quit,
    /// Pick the Export PNG file with a file dialog.
    BrowseExportPath,
    /// Show a file dialog for the picture to compare with.
    BrowseCompareImage,
    /// Use the in-app file dialog even where a native one can be shown (editor setting).
    SetPreferInAppFileDialog(bool),
    /// Scale an imported OBJ to a unit box once its size is known (editor setting).
    SetFitImportedMeshes(bool),
    /// Hide the error area.
    DismissError,
    /// Hide the warning area.
    DismissWarning,
    /// Put the keyboard focus in the inspector's name field (outliner "Rename").
    FocusName,
    /// Change the preview's switches, view and debug overlays (editor state, not undoable).
    SetPreviewSettings(crate::ui::state::PreviewSettings),
    /// Inspect a pixel of the scene camera's image, or close the pixel inspector (`None`).
    InspectPixel(Option<(u32, u32)>),
    /// Cast the ray under a click (off the UI thread) to select or inspect what it meets.
    Pick(crate::ui::state::PickRequest),
    /// Move the view camera (editor state: no edit, no undo step).
    SetView(crate::ui::state::ViewCamera),
    /// Look through the scene camera, or back at the view camera.
    ToggleCameraView,
    /// Set the scene camera from the view camera (one undo step), and look through it.
    SetSceneCameraFromView,
    /// Change what the ray-path overlay draws, and the pinned pixels.
    SetRayPaths(crate::ui::state::RayPathSettings),
    /// Mute, solo or hide (editor state, not undoable, not a scene edit).
    Isolate(crate::ui::state::IsolationToggle),
    /// Show the Compare with Image window.
    ShowCompare,
    /// Compare the scene with another renderer's picture in this file (in the background).
    CompareWith(PathBuf),
    /// Show the Bug gallery window (rendering the gallery of the scene in the background).
    ShowBugGallery,
    /// Compare the scene with picture `n` of the Bug gallery (0: raylab's own).
    CompareWithGalleryPicture(usize),
}
