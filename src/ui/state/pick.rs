//! A click on the picture as a request: the ray under the cursor and what the answer is
//! for (select the object, or inspect the pixel that sees the point).

use crate::trace::Ray;

/// What a click asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PickPurpose {
    /// Select the object under the cursor, the leaf of a tree (nothing: clear the
    /// selection).
    Select,
    /// Select the node holding the leaf under the cursor (Shift+click): its CSG node or
    /// group, or the object itself at the top level.
    SelectParent,
    /// Inspect the scene camera's pixel that sees the point under the cursor.
    Inspect,
}

/// A click to answer: the ray under the cursor, and what for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PickRequest {
    /// The ray through the clicked pixel of the shown camera.
    pub ray: Ray,
    /// What the answer does.
    pub purpose: PickPurpose,
}
