//! The Bug gallery window: the open scene as raylab renders it and under each bug of the
//! catalogue that shows in it (`crate::compare::plant::gallery`), as thumbnails; clicking
//! one compares the scene with that picture, so the diff's explanations of each planted
//! bug can be read. [`BugGallery`] holds the state (the job that makes the gallery off
//! the UI thread, the gallery and the scene it shows); [`bug_gallery_window`] shows it.

mod meshes;
mod state;
mod window;

pub use meshes::read_meshes;
pub use state::{BugGallery, GALLERY_SAMPLES, Thumbnail};
pub use window::{OWN_PICTURE_LABEL, bug_gallery_window, thumbnail_label};
