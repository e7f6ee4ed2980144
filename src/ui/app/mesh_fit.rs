//! Fitting an imported OBJ to a unit box: a model arrives at its file's scale (a teapot
//! six units tall swallows the scene), so once the preview has read it, the editor scales
//! it so that its largest side is 1, as its own undo step, and says how large it was.
//! On by default (File > Fit Imported Meshes to a Unit Box); Undo gives back the file's
//! size.

use glam::DVec3;

use super::EditorApp;
use crate::preview::MeshFacts;
use crate::scene::{Object, Shape, Transform};
use crate::ui::commands::{Command, SceneEdit};
use crate::ui::panels::status_bar::StatusMessage;

/// A mesh just imported, waiting for the preview to read its box.
#[derive(Clone, Debug)]
pub(super) struct PendingFit {
    /// The object's index in the scene.
    pub index: usize,
    /// The object as it was added (the fit waits only while it is unchanged).
    pub added: Object,
}

/// `object` scaled uniformly so that the largest side of `facts`' box is 1, keeping its
/// place and rotation; `None` for a transform given as a matrix or an empty box.
#[must_use]
pub(super) fn fitted(object: &Object, facts: &MeshFacts) -> Option<Object> {
    let Transform::Trs(mut trs) = object.transform else {
        return None;
    };
    let largest = (facts.bounds.max - facts.bounds.min).max_element();
    if !(largest.is_finite() && largest > 0.0) {
        return None;
    }
    trs.scale = DVec3::splat(1.0 / largest);
    Some(Object {
        transform: Transform::Trs(trs),
        ..object.clone()
    })
}

/// A box's size as "6.00 × 3.10 × 4.00".
#[must_use]
pub(super) fn size_text(facts: &MeshFacts) -> String {
    let size = facts.bounds.max - facts.bounds.min;
    format!("{:.2} × {:.2} × {:.2}", size.x, size.y, size.z)
}

impl EditorApp {
    /// Fits the mesh imported last once the preview knows its box (a command for this
    /// frame), unless the object was edited or removed meanwhile.
    pub(super) fn fit_imported_mesh(&mut self) {
        let Some(pending) = &self.document.pending_fit else {
            return;
        };
        if self.document.scene.objects.get(pending.index) != Some(&pending.added) {
            self.document.pending_fit = None;
            return;
        }
        let Shape::Mesh { path } = &pending.added.shape else {
            self.document.pending_fit = None;
            return;
        };
        let Some(facts) = self
            .view
            .preview
            .as_ref()
            .and_then(|p| p.mesh_facts().get(path).copied())
        else {
            return;
        };
        let index = pending.index;
        if let Some(object) = fitted(&pending.added, &facts) {
            self.commands
                .push(Command::Edit(SceneEdit::SetObject(index, object)));
            self.message = Some(StatusMessage::done(format!(
                "Fitted {} into a unit box (it is {} in its file): Undo gives it back its file size",
                pending.added.name,
                size_text(&facts)
            )));
        }
        self.document.pending_fit = None;
    }
}
