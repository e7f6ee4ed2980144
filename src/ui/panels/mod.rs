//! The panels around the viewport: the menu bar, the error and warning banners, the
//! outliner, the inspector and the status bar, each with one `*_ui` entry point that pushes commands.

pub mod inspector;
pub mod menu;
pub mod notices;
pub mod outliner;
pub mod status_bar;
