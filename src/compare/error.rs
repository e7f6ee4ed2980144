//! What can go wrong when comparing: each a value with a message that names the file,
//! the sizes or the problem.

use std::path::PathBuf;

/// Why a comparison could not be made.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// The other image cannot be read from disk.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The file is not a PNG or PPM image the decoder understands.
    #[error("{} is not a readable PNG or PPM image: {message}", path.display())]
    NotAnImage {
        /// The file.
        path: PathBuf,
        /// The decoder's message.
        message: String,
    },
    /// The image has more than 8 bits per channel (or floating-point channels).
    #[error("{} has {detail}; diff reads 8-bit images (as renderers write them)", path.display())]
    NotEightBit {
        /// The file.
        path: PathBuf,
        /// What it has instead, e.g. "16-bit RGB channels".
        detail: String,
    },
    /// The other image and the scene's render differ in size.
    #[error(
        "the other image is {other_width}x{other_height} but the scene renders {scene_width}x{scene_height}; render it at the scene's size"
    )]
    SizeMismatch {
        /// Width of the other image.
        other_width: u32,
        /// Height of the other image.
        other_height: u32,
        /// Width of the scene's camera.
        scene_width: u32,
        /// Height of the scene's camera.
        scene_height: u32,
    },
    /// The scene does not compile into a world.
    #[error("the scene cannot be rendered: {0}")]
    Scene(String),
    /// The comparison was cancelled through its progress.
    #[error("the comparison was cancelled")]
    Cancelled,
}
