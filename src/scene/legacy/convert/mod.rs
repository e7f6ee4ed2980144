//! Typed legacy blocks to a [`Scene`]: materials resolved in file order, transforms
//! composed, lights and the camera converted, and the result checked against the scene
//! rules so an import always loads again.
//!
//! This file is the whole-file driver: it reads the dialect off the blocks and walks them in
//! file order through a `converter`, which keeps the Scene block's settings and assembles
//! the scene at the end, with the course's conventions (`Conventions::COURSE`); `pending`
//! holds what it keeps between blocks. Each concern has its own file:
//! `dialect` (2016 or 2020 framework), `materials` (material blocks and lookups),
//! `objects` (objects and trees), `naming` (names of objects and materials), `lights`,
//! `camera`, and `transform` (composing transform steps into a scene transform).

mod camera;
mod converter;
mod dialect;
mod lights;
mod materials;
mod naming;
mod objects;
mod pending;
mod transform;

use std::path::PathBuf;

use super::error::Diagnostics;
use super::syntax::ParsedBlock;
pub use converter::Converted;
use converter::Converter;
pub use dialect::{Detected, Dialect};
pub(super) use objects::LEGACY_TORUS_MINOR;
pub(super) use transform::as_trs;

/// Converts parsed blocks, pushing every semantic error and warning. `folder` is the
/// scene file's folder, where `Mesh` files are looked for (none for text alone).
pub fn convert(
    blocks: &[ParsedBlock],
    folder: Option<PathBuf>,
    errors: &mut Diagnostics,
) -> Converted {
    let dialect = dialect::detect(blocks);
    if dialect.dialect == Dialect::Framework2020
        && let Some((line, what)) = dialect.signs_2016.first()
    {
        errors.warn(
            *line,
            format!(
                "{what} belongs to the 2016 framework, but the file also has {} (line {}): \
                 read as the 2020 framework's dialect (magenta default material)",
                dialect.signs_2020[0].1, dialect.signs_2020[0].0
            ),
        );
    }
    let mut converter = Converter::new(blocks, dialect, folder, errors);
    for block in blocks {
        converter.block(block);
    }
    converter.finish()
}
