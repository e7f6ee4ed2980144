//! The egui adapter of the viewport gizmos: reading drags, turning them into edits,
//! building and painting the handles (lights, the scene camera, the selection's), and the
//! mode buttons. The math lives in [`crate::gizmo`].

pub mod camera;
pub mod drag;
pub mod edit;
pub mod element;
pub mod hit;
pub mod lights;
pub mod overlay;
pub mod paint;
pub mod projection;
pub mod toolbar;
