//! Stage 7: bugs planted. raylab's picture of a scene as a tracer with some of the
//! catalogue's bugs would make it (`raylab render --bug`), the gallery of a scene under
//! each bug (`raylab bugs`, the editor's Bug gallery), and whether an explanation names a
//! planted bug (the accuracy benchmark, the class report's generated classes).

mod gallery;
mod models;

pub use gallery::{Gallery, GalleryPicture, gallery, gallery_scene};
pub use models::{
    CAUSE_NAMES, LOOP_BUG_NAMES, Plant, PlantedBug, Site, gallery_bugs, has_glass, parse_bugs,
    plant, plant_each,
};
