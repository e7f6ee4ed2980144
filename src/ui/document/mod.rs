//! The document around the scene: files and their dialogs (native or in-app), recent files, crash-recovery
//! autosave, PNG export and the "unsaved changes" question.

pub mod autosave;
pub mod confirm;
pub mod export;
pub mod export_window;
pub mod file_dialog;
pub mod files;
pub mod folder_scenes;
pub mod native_dialogs;
pub mod recent;
