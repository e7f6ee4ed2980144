//! Reading a text file with a size cap, shared by the RON loader and the legacy importer:
//! nothing a user opens can make the program allocate without bound.

use std::io::Read;
use std::path::Path;

/// The largest scene file accepted (RON or legacy text), in bytes: 64 MiB, some thousand
/// times the size of a large hand-made scene.
pub const MAX_SCENE_FILE_BYTES: u64 = 64 << 20;

/// Why a text file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum TextFileError {
    /// The operating system's error.
    #[error("{0}")]
    Read(#[from] std::io::Error),
    /// The file is over [`MAX_SCENE_FILE_BYTES`].
    #[error("the file is larger than {} MiB, the limit for scene files", MAX_SCENE_FILE_BYTES >> 20)]
    TooLarge,
    /// The bytes are not UTF-8; `line` is where the first bad byte is.
    #[error("line {line}: the file is not UTF-8 text")]
    NotUtf8 {
        /// 1-based line of the first invalid byte.
        line: usize,
    },
}

/// Reads at most [`MAX_SCENE_FILE_BYTES`] of `path` as UTF-8. The cap is enforced while
/// reading, so a file that grows, or a device that never ends, is still refused.
///
/// # Errors
/// See [`TextFileError`].
pub fn read_text_file(path: &Path) -> Result<String, TextFileError> {
    let file = std::fs::File::open(path)?;
    let mut bytes = Vec::new();
    file.take(MAX_SCENE_FILE_BYTES + 1)
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_SCENE_FILE_BYTES {
        return Err(TextFileError::TooLarge);
    }
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let line = 1 + e.as_bytes()[..valid]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        TextFileError::NotUtf8 { line }
    })
}
