//! eframe's storage interface over a map, as the native one is over a file: for the unit
//! tests of what the editor persists.

/// A `String` map standing in for eframe's file storage.
#[derive(Default)]
pub struct MapStorage(std::collections::HashMap<String, String>);

impl eframe::Storage for MapStorage {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_owned(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}
