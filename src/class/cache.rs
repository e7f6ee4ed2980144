//! The cache that makes a rerun cost only new pairs: each finished pair's result and
//! images in `REPORT/cache/KEY/`, where KEY hashes the scene file's bytes (and its mesh
//! files'), the picture's bytes, the comparison's options and this raylab's build. A
//! late submission, a changed picture or a new raylab makes a new key; an old entry is
//! never read again.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use xxhash_rust::xxh3::Xxh3;

use super::pair::PairResult;

/// The cache's folder in a report folder.
pub const CACHE_FOLDER: &str = "cache";

/// The result file in a pair's cache folder, written last: a pair whose folder lacks it
/// (a run stopped while writing) counts as not done.
const RESULT_FILE: &str = "result.json";

/// Which raylab made a result: its version and a hash of the running executable, so a
/// rebuild from changed code (same version number) does not reuse results the old code
/// made. The limit: a rebuild of the same code (another profile, another linker) also
/// counts as new, and computes every pair again.
#[must_use]
pub fn build_identity() -> &'static str {
    static IDENTITY: OnceLock<String> = OnceLock::new();
    IDENTITY.get_or_init(|| {
        let executable = std::env::current_exe()
            .and_then(std::fs::read)
            .map(|bytes| xxhash_rust::xxh3::xxh3_64(&bytes))
            .unwrap_or(0);
        format!("{}+{executable:016x}", env!("CARGO_PKG_VERSION"))
    })
}

/// The key of one pair: a 128-bit hash of everything its result depends on.
#[must_use]
pub fn pair_key(scene_bytes: &[u8], picture_bytes: &[u8], options: &str) -> String {
    let mut hasher = Xxh3::new();
    for part in [
        build_identity().as_bytes(),
        options.as_bytes(),
        scene_bytes,
        picture_bytes,
    ] {
        // Each part's length first, so that no two splits of the same bytes collide.
        hasher.update(&(part.len() as u64).to_le_bytes());
        hasher.update(part);
    }
    format!("{:032x}", hasher.digest128())
}

/// The folder of a pair's cached result and images, relative to the report folder.
#[must_use]
pub fn pair_folder(key: &str) -> PathBuf {
    Path::new(CACHE_FOLDER).join(key)
}

/// The cached result of `key` in `report`, if a finished one is there.
#[must_use]
pub fn cached(report: &Path, key: &str) -> Option<PairResult> {
    let text = std::fs::read_to_string(report.join(pair_folder(key)).join(RESULT_FILE)).ok()?;
    serde_json::from_str(&text).ok()
}

/// Stores `result` for `key` (its images are already in the pair's folder).
///
/// # Errors
/// The write's error, naming the file.
pub fn store(report: &Path, key: &str, result: &PairResult) -> Result<(), String> {
    let path = report.join(pair_folder(key)).join(RESULT_FILE);
    let text = serde_json::to_string_pretty(result).map_err(|e| e.to_string())?;
    crate::scene::write_atomically(&path, text.as_bytes())
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_key_changes_with_each_input() {
        let key = pair_key(b"scene", b"picture", "spp=1");
        assert_eq!(key, pair_key(b"scene", b"picture", "spp=1"));
        assert_ne!(key, pair_key(b"scene!", b"picture", "spp=1"));
        assert_ne!(key, pair_key(b"scene", b"picture!", "spp=1"));
        assert_ne!(key, pair_key(b"scene", b"picture", "spp=4"));
        assert_ne!(key, pair_key(b"scen", b"epicture", "spp=1"));
    }
}
