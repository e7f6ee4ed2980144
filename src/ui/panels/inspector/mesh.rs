//! A mesh object's rows: its file, and what the preview found in it (triangles, whether
//! it is closed, its box), or that it has not been read yet.

use egui::Ui;

use crate::preview::MeshFacts;

/// The rows of a mesh read from `path` (as the scene writes it), in the object grid.
pub(super) fn mesh_rows_ui(ui: &mut Ui, path: &str, facts: Option<&MeshFacts>) {
    ui.label("Mesh");
    let name = crate::scene::mesh_file::mesh_file_name(path);
    ui.add(egui::Label::new(name).truncate())
        .on_hover_text(format!(
            "{path}\nThe scene refers to this file; saving never rewrites it"
        ));
    ui.end_row();
    ui.label("Triangles");
    match facts {
        Some(facts) => {
            let solid = if facts.closed {
                "closed (a solid)"
            } else {
                "open"
            };
            ui.label(format!("{} · {solid}", thousands(facts.triangles)))
                .on_hover_text(if facts.closed {
                    "Every edge is shared by two triangles: the mesh may be a CSG operand"
                } else {
                    "Some edge has one triangle only: it draws, but cannot be a CSG operand"
                });
            ui.end_row();
            ui.label("Size");
            let size = facts.bounds.max - facts.bounds.min;
            ui.label(format!("{:.3} × {:.3} × {:.3}", size.x, size.y, size.z))
                .on_hover_text("The mesh's size in its file's units, before the transform below");
            ui.end_row();
            ui.label("Bounds");
            let (min, max) = (facts.bounds.min, facts.bounds.max);
            ui.label(format!(
                "x {:.3}…{:.3}\ny {:.3}…{:.3}\nz {:.3}…{:.3}",
                min.x, max.x, min.y, max.y, min.z, max.z
            ))
            .on_hover_text("The mesh's box in its own space, before the transform below");
        }
        None => {
            ui.weak("not read yet")
                .on_hover_text("The preview reads the file; its progress is in the status bar");
        }
    }
    ui.end_row();
}

/// A count with thin spaces between thousands: 1 000 000.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn thousands_are_grouped() {
        assert_eq!(super::thousands(7), "7");
        assert_eq!(super::thousands(1234), "1\u{2009}234");
        assert_eq!(super::thousands(1_000_000), "1\u{2009}000\u{2009}000");
    }
}
