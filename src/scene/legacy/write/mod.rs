//! Export of a [`Scene`] in the COSC342 course's text format (`shared/COSC342_FORMAT.md`),
//! in either framework's dialect: the inverse of the importer.
//!
//! The file is written in the order the readers need: the Scene block (size, background,
//! ray depth, anti-aliasing as `FSAA N` in 2020, the ambient colour in 2016), the camera
//! (`camera`), the lights (`lights`), every material (`materials`), then the objects
//! (`objects`), each named by a comment on the line before it as the importer reads
//! names. Transforms become `Scale3` / `Rotate` / `Translate` steps (`steps`), numbers
//! whole tokens that read back exactly (`numbers`).
//!
//! What a dialect cannot say is never dropped in silence ([`Problem`], naming the object,
//! light, material or setting): where the file would draw a different scene (a shape,
//! light or tree the dialect lacks, a coloured transmission, a sheared matrix) the export
//! is refused ([`CourseExportError`] lists every such thing); where it loses something
//! that does not change the geometry (the render conventions, which the course readers
//! fix; a name; a sample count; a sphere light's softness in 2016) it is written with a
//! warning.

mod camera;
mod file;
mod lights;
mod materials;
mod numbers;
mod objects;
mod problem;
mod scene_text;
mod steps;

pub use file::{CourseExportFileError, export_course_file};
pub use objects::year;
pub use problem::{CourseExportError, Problem, Subject};
pub use scene_text::{CourseScene, write_course_scene};
