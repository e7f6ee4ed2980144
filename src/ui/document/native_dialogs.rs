//! Whether the desktop can show a native file dialog at all. On Linux and the BSDs rfd
//! asks the xdg desktop portal and falls back to zenity; with neither it returns "no
//! file", which looks exactly like a cancel. So the editor looks first, and uses its
//! own in-app dialog where no native one can appear.

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::file_dialog::{NativeDialog, rfd_dialog};

/// Whether the editor may use native file dialogs.
#[derive(Clone, Default)]
pub enum NativeDialogs {
    /// Look at the desktop when the editor starts.
    #[default]
    Detect,
    /// Never: always the in-app dialog (as on a desktop without portal or zenity).
    Unavailable,
    /// This stand-in for the desktop's dialog (tests use one that answers when told).
    Given(NativeDialog),
}

impl std::fmt::Debug for NativeDialogs {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            NativeDialogs::Detect => "Detect",
            NativeDialogs::Unavailable => "Unavailable",
            NativeDialogs::Given(_) => "Given",
        })
    }
}

impl NativeDialogs {
    /// The native dialog to use, if there is one on this desktop.
    #[must_use]
    pub fn resolve(&self) -> Option<NativeDialog> {
        match self {
            NativeDialogs::Detect => {
                native_dialogs_available().then(|| Arc::new(rfd_dialog) as NativeDialog)
            }
            NativeDialogs::Unavailable => None,
            NativeDialogs::Given(dialog) => Some(dialog.clone()),
        }
    }
}

/// Whether a native file dialog can be shown on this desktop.
#[must_use]
pub fn native_dialogs_available() -> bool {
    if cfg!(any(
        target_os = "linux",
        target_os = "freebsd",
        target_os = "dragonfly",
        target_os = "netbsd",
        target_os = "openbsd"
    )) {
        let desktop = Desktop {
            path: std::env::var_os("PATH"),
            session_bus: session_bus_reachable(),
            data_dirs: xdg_data_dirs(),
        };
        desktop.can_show_native_dialogs()
    } else {
        // Windows and macOS always have their own dialogs.
        true
    }
}

/// What the probe looks at, gathered so that tests can make one up.
#[derive(Clone, Debug, Default)]
pub struct Desktop {
    /// The `PATH` searched for zenity.
    pub path: Option<std::ffi::OsString>,
    /// Whether a D-Bus session bus is there to reach the portal through.
    pub session_bus: bool,
    /// `XDG_DATA_DIRS`: where the portal's D-Bus service and its backends are declared.
    pub data_dirs: Vec<PathBuf>,
}

impl Desktop {
    /// zenity on `PATH`, or a session bus with the portal and a file-chooser backend.
    #[must_use]
    pub fn can_show_native_dialogs(&self) -> bool {
        self.has_zenity() || (self.session_bus && self.has_portal_file_chooser())
    }

    fn has_zenity(&self) -> bool {
        self.path.as_deref().is_some_and(|path| {
            std::env::split_paths(path).any(|dir| is_executable(&dir.join("zenity")))
        })
    }

    fn has_portal_file_chooser(&self) -> bool {
        let service = Path::new("dbus-1/services/org.freedesktop.portal.Desktop.service");
        let declared = self.data_dirs.iter().any(|d| d.join(service).is_file());
        declared && self.data_dirs.iter().any(|d| has_file_chooser_backend(d))
    }
}

/// Whether `<data dir>/xdg-desktop-portal/portals/*.portal` names a file chooser.
fn has_file_chooser_backend(data_dir: &Path) -> bool {
    let Ok(entries) = std::fs::read_dir(data_dir.join("xdg-desktop-portal/portals")) else {
        return false;
    };
    entries.filter_map(Result::ok).any(|entry| {
        entry.path().extension() == Some(OsStr::new("portal"))
            && std::fs::read_to_string(entry.path())
                .is_ok_and(|text| text.contains("org.freedesktop.impl.portal.FileChooser"))
    })
}

fn is_executable(path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::metadata(path).is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
    }
    #[cfg(not(unix))]
    {
        path.is_file()
    }
}

/// `DBUS_SESSION_BUS_ADDRESS`, or the default socket in `XDG_RUNTIME_DIR`.
fn session_bus_reachable() -> bool {
    let address = std::env::var_os("DBUS_SESSION_BUS_ADDRESS").filter(|a| !a.is_empty());
    if address.is_some() {
        return true;
    }
    std::env::var_os("XDG_RUNTIME_DIR").is_some_and(|dir| Path::new(&dir).join("bus").exists())
}

fn xdg_data_dirs() -> Vec<PathBuf> {
    let dirs = std::env::var_os("XDG_DATA_DIRS").filter(|d| !d.is_empty());
    let dirs = dirs.unwrap_or_else(|| "/usr/local/share:/usr/share".into());
    std::env::split_paths(&dirs).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("raylab-probe-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn no_zenity_and_no_portal_means_no_native_dialog() {
        let empty = dir("empty");
        let desktop = Desktop {
            path: Some(empty.clone().into_os_string()),
            session_bus: true,
            data_dirs: vec![empty],
        };
        assert!(!desktop.can_show_native_dialogs());
    }

    #[cfg(unix)]
    #[test]
    fn zenity_on_the_path_or_a_portal_with_a_file_chooser_is_enough() {
        use std::os::unix::fs::PermissionsExt;
        let bin = dir("bin");
        let zenity = bin.join("zenity");
        std::fs::write(&zenity, "#!/bin/sh\n").unwrap();
        std::fs::set_permissions(&zenity, std::fs::Permissions::from_mode(0o755)).unwrap();
        let with_zenity = Desktop {
            path: Some(bin.into_os_string()),
            ..Desktop::default()
        };
        assert!(with_zenity.can_show_native_dialogs());

        let share = dir("share");
        std::fs::create_dir_all(share.join("dbus-1/services")).unwrap();
        std::fs::write(
            share.join("dbus-1/services/org.freedesktop.portal.Desktop.service"),
            "[D-BUS Service]\n",
        )
        .unwrap();
        let portal = Desktop {
            session_bus: true,
            data_dirs: vec![share.clone()],
            ..Desktop::default()
        };
        assert!(!portal.can_show_native_dialogs(), "no file chooser backend");
        std::fs::create_dir_all(share.join("xdg-desktop-portal/portals")).unwrap();
        std::fs::write(
            share.join("xdg-desktop-portal/portals/gtk.portal"),
            "[portal]\nInterfaces=org.freedesktop.impl.portal.FileChooser;\n",
        )
        .unwrap();
        assert!(portal.can_show_native_dialogs());
        let no_bus = Desktop {
            session_bus: false,
            ..portal
        };
        assert!(!no_bus.can_show_native_dialogs());
    }
}
