//! The names the editor gives things that have none in the scene, shared by the
//! outliner, the viewport, the pixel inspector and Compare.

use crate::scene::Light;
use crate::trace::View;

/// The outliner's name of a light: "Point light 2" (its place in the list, from 1).
#[must_use]
pub fn light_label(light: &Light, index: usize) -> String {
    format!("{} light {}", light.kind_name(), index + 1)
}

/// The view's name in the editor: "beauty", "normal", "depth", "object id", "shadow mask".
#[must_use]
pub fn view_label(view: View) -> &'static str {
    match view {
        View::Beauty => "beauty",
        View::Normal => "normal",
        View::Depth => "depth",
        View::ObjectId => "object id",
        View::ShadowMask => "shadow mask",
    }
}
