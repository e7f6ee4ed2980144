//! The scene: data model, validation, RON load and save.
//!
//! Nothing here knows about rendering or the editor; `trace` compiles a [`Scene`] into a
//! render-ready world.

mod any_file;
mod conventions;
mod error;
pub mod examples;
mod file;
pub mod legacy;
mod light;
mod light_file;
pub mod mesh_file;
mod model;
mod obj_reader;
mod scene_or_course;
mod shape;
mod text_file;
pub mod transform;
pub mod tree;
mod validate;

pub use any_file::{load_any_scene, read_meshes_beside};
pub use conventions::{ClampConvention, Conventions, MirrorConvention, Quantise};
pub use error::SceneError;
pub use file::{
    load_scene, parse_scene, save_scene, scene_to_ron, write_atomically, write_atomically_with,
};
pub use light::{Light, LightKind, LightSource};
pub use mesh_file::{MeshData, load_obj, load_obj_watched, mesh_objects, read_scene_meshes};
pub use model::{Camera, FORMAT_VERSION, Material, Object, RenderSettings, Scene};
pub use obj_reader::LoadWatch;
pub use scene_or_course::{SceneOrCourse, SceneOrCourseError, load_scene_or_course};
pub use shape::{CsgOp, Shape};
pub use text_file::{MAX_SCENE_FILE_BYTES, TextFileError, read_text_file};
pub use transform::{MatrixRows, Transform, Trs, affine_from_rows, rows_from_affine};
pub use validate::{
    MAX_DEPTH, MAX_IMAGE_SIDE, MAX_IOR, MAX_LIGHT_SAMPLES, MAX_SAMPLES_PER_PIXEL,
    MAX_SPOT_ANGLE_DEG, MAX_TREE_DEPTH, validate,
};
