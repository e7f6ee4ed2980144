//! Everything the panels can ask for, as values. Panels push commands while laying out;
//! the app applies them once per frame (`app.rs`), which also feeds undo and restarts the
//! preview. Scene edits are plain functions here, testable without a window.

mod placement;
mod scene_edit;
mod tree_edit;
mod tree_move;
mod tree_wrap;

use std::path::PathBuf;

use crate::scene::{Camera, Light, Material, Object, RenderSettings, Shape};

/// What the inspector shows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Selection {
    /// Nothing selected.
    #[default]
    None,
    /// The camera.
    Camera,
    /// The render settings.
    Render,
    /// A top-level object, by index.
    Object(usize),
    /// A node inside an object tree (a CSG operand, a group's child), by its path of
    /// indices from the top-level object down (two or more; see `Selection::node`).
    Part(Vec<usize>),
    /// Two or more objects or parts (Ctrl+click in the outliner), by path, in the
    /// order picked (see `Selection::several`).
    Several(Vec<Vec<usize>>),
    /// A material, by name.
    Material(String),
    /// A light, by index.
    Light(usize),
}

pub use crate::scene::LightKind;
pub use scene_edit::{material_users, repair_selection, unique_name};
pub use tree_edit::{CSG_OPS, part_exists};

/// A change to the scene (and the selection that follows it).
#[derive(Clone, Debug, PartialEq)]
pub enum SceneEdit {
    /// Adds a unit shape where the camera looks, upright and standing on the floor if
    /// there is one, with the first material (creating one if there is none).
    AddObject(Shape),
    /// Adds a Mesh object for the OBJ file at this path (as the scene writes it), named
    /// after the file.
    AddMesh(String),
    /// Adds a light of a kind.
    AddLight(LightKind),
    /// Adds a grey material with a fresh name.
    AddMaterial,
    /// Duplicates the selected object or light (moved aside, so both are seen) or
    /// material, and selects the copy.
    DuplicateSelected,
    /// Deletes the selected object, light or (unused) material.
    DeleteSelected,
    /// Replaces an object.
    SetObject(usize, Object),
    /// Replaces a node inside an object tree, by path.
    SetPart(Vec<usize>, Object),
    /// Puts the selected object or part into a new group in its place (Ctrl+G).
    GroupSelected,
    /// Puts the selected object or part, as the first operand, into a new CSG node of
    /// this operator in its place (add the other operands next).
    CsgSelected(crate::scene::CsgOp),
    /// Puts the selected group's children in its place, placed as they were.
    UngroupSelected,
    /// Moves a node (by path) into a tree node, as its last child or operand, or beside
    /// a leaf, right after it; it stays where it is in the world (outliner drag).
    MoveNode {
        /// The node moved.
        from: Vec<usize>,
        /// Where it was dropped.
        onto: Vec<usize>,
    },
    /// Adds a unit shape as the last operand or child of the selected tree node.
    AddOperand(Shape),
    /// Replaces a light.
    SetLight(usize, Light),
    /// Replaces the camera.
    SetCamera(Camera),
    /// Replaces the render settings.
    SetRender(RenderSettings),
    /// Replaces a material's values.
    SetMaterial(String, Material),
    /// Gives an object its own copy of the material it shares with others, named after
    /// both ("gold (flat ring)"), so editing it changes only that object.
    MakeMaterialUnique(usize),
    /// Renames a material and every reference to it.
    RenameMaterial {
        /// The current name.
        from: String,
        /// The new name.
        to: String,
    },
}

impl SceneEdit {
    /// Whether the edit names an object or light by its index.
    #[must_use]
    pub fn is_by_index(&self) -> bool {
        matches!(
            self,
            SceneEdit::SetObject(..)
                | SceneEdit::SetPart(..)
                | SceneEdit::SetLight(..)
                | SceneEdit::MakeMaterialUnique(_)
        )
    }
}

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
