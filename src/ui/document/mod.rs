//! The document around the scene: files and their dialogs, recent files, crash-recovery
//! autosave, PNG export and the "unsaved changes" question.

pub mod autosave;
pub mod confirm;
pub mod export;
pub mod files;
pub mod recent;
