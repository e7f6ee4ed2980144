//! Editor state kept between runs in eframe's storage, one key per kind of state.

use serde::Serialize;
use serde::de::DeserializeOwned;

/// State the editor remembers between runs under its own storage key.
pub trait Stored: Serialize + DeserializeOwned + Default {
    /// The storage key.
    const KEY: &'static str;

    /// What an earlier run saved, or the default when nothing (or nothing readable) was.
    #[must_use]
    fn load(storage: Option<&dyn eframe::Storage>) -> Self {
        storage
            .and_then(|s| eframe::get_value(s, Self::KEY))
            .unwrap_or_default()
    }

    /// Writes this to storage.
    fn save(&self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, Self::KEY, self);
    }
}
