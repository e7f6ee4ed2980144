//! What the preview shows, as editor state (never part of the scene and not undoable):
//! the term switches and solo, the debug view, the NaN guard overlay, the inspect mode and
//! the convergence window. Persisted in eframe's storage.

use serde::{Deserialize, Serialize};

use crate::scene::Scene;
use crate::trace::{RenderOptions, Term, TermSwitches, View};

/// Storage key of the settings.
const KEY: &str = "raylab.preview_settings";

/// The toolbar's state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PreviewSettings {
    /// Term switches and solo, as `raylab render --off/--solo` has them.
    pub switches: TermSwitches,
    /// Beauty or a debug view.
    pub view: View,
    /// Paint pixels with a non-finite sample magenta and show the count.
    pub nan_guard: bool,
    /// A click on the picture inspects the pixel instead of selecting.
    pub inspect: bool,
    /// Show the convergence plot.
    pub show_convergence: bool,
}

impl Default for PreviewSettings {
    fn default() -> Self {
        Self {
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            nan_guard: false,
            inspect: false,
            show_convergence: false,
        }
    }
}

/// The stored form: names, as on the command line, so it survives enum changes.
#[derive(Debug, Default, Serialize, Deserialize)]
struct Stored {
    off: Vec<String>,
    solo: Option<String>,
    view: String,
    nan_guard: bool,
    show_convergence: bool,
}

impl PreviewSettings {
    /// The settings saved by an earlier run (unknown names are dropped), or the defaults.
    #[must_use]
    pub fn load(storage: Option<&dyn eframe::Storage>) -> Self {
        let Some(stored) = storage.and_then(|s| eframe::get_value::<Stored>(s, KEY)) else {
            return Self::default();
        };
        let mut switches = TermSwitches::ALL_ON;
        for term in stored.off.iter().filter_map(|t| t.parse::<Term>().ok()) {
            switches.set(term, false);
        }
        switches.solo = stored.solo.and_then(|t| t.parse().ok());
        Self {
            switches,
            view: stored.view.parse().unwrap_or_default(),
            nan_guard: stored.nan_guard,
            inspect: false,
            show_convergence: stored.show_convergence,
        }
    }

    /// Writes the settings to storage (the inspect mode starts off every run).
    pub fn save(&self, storage: &mut dyn eframe::Storage) {
        let stored = Stored {
            off: Term::ALL
                .into_iter()
                .filter(|t| !self.switches.is_on(*t))
                .map(|t| t.name().to_owned())
                .collect(),
            solo: self.switches.solo.map(|t| t.name().to_owned()),
            view: self.view.name().to_owned(),
            nan_guard: self.nan_guard,
            show_convergence: self.show_convergence,
        };
        eframe::set_value(storage, KEY, &stored);
    }

    /// The options for rendering `scene` at its own size and samples with these switches
    /// and view: what `raylab render --off .. --solo .. --view ..` renders.
    #[must_use]
    pub fn render_options(&self, scene: &Scene) -> RenderOptions {
        RenderOptions {
            switches: self.switches,
            view: self.view,
            ..RenderOptions::from_scene(scene)
        }
    }

    /// Whether anything differs from the full beauty picture.
    #[must_use]
    pub fn is_modified(&self) -> bool {
        self.switches != TermSwitches::ALL_ON || self.view != View::Beauty
    }

    /// Why the preview is not the full picture, one short phrase each ("diffuse off",
    /// "solo specular", "depth view"); empty when it is the full picture.
    #[must_use]
    pub fn not_full_picture_reasons(&self) -> Vec<String> {
        let mut reasons: Vec<String> = Term::ALL
            .into_iter()
            .filter(|t| !self.switches.is_on(*t))
            .map(|t| format!("{} off", t.name()))
            .collect();
        if let Some(term) = self.switches.solo {
            reasons.push(format!("solo {}", term.name()));
        }
        if self.view != View::Beauty {
            reasons.push(format!("{} view", super::labels::view_label(self.view)));
        }
        reasons
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::ui::test_storage::MapStorage;

    #[test]
    fn settings_survive_storage_except_the_inspect_mode() {
        let mut settings = PreviewSettings::default();
        settings.switches.set(Term::Diffuse, false);
        settings.switches.solo = Some(Term::Specular);
        settings.view = View::Depth;
        settings.nan_guard = true;
        settings.inspect = true;
        settings.show_convergence = true;
        let mut storage = MapStorage::default();
        settings.save(&mut storage);
        let loaded = PreviewSettings::load(Some(&storage));
        assert_eq!(
            loaded,
            PreviewSettings {
                inspect: false,
                ..settings
            }
        );
        assert_eq!(PreviewSettings::load(None), PreviewSettings::default());
        assert!(loaded.is_modified() && !PreviewSettings::default().is_modified());
        assert_eq!(
            loaded.not_full_picture_reasons(),
            ["diffuse off", "solo specular", "depth view"]
        );
        assert!(
            PreviewSettings::default()
                .not_full_picture_reasons()
                .is_empty()
        );
    }
}
