//! The object inspector: name, shape, material, transform, and the material's values
//! right below (what one tunes next).

use egui::Ui;
use glam::DVec3;

use super::fields::vec3_row_ui;
use super::limits::Limits;
use super::material::material_rows_ui;
use super::{grid_ui, heading_ui};
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn object_ui(
    ui: &mut Ui,
    scene: &Scene,
    index: usize,
    object: &Object,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    heading_ui(ui, "OBJECT", &object.name);
    let mut edited = object.clone();
    grid_ui(ui, "object", |ui| {
        ui.label("Name");
        let response = ui
            .add(egui::TextEdit::singleline(&mut edited.name).desired_width(f32::INFINITY))
            .accessible_name("object name");
        if std::mem::take(focus_name) {
            response.request_focus();
        }
        ui.end_row();

        ui.label("Shape");
        egui::ComboBox::from_id_salt("shape")
            .selected_text(edited.shape.name())
            .show_ui(ui, |ui| {
                for shape in Shape::ALL {
                    let name = shape.name();
                    ui.selectable_value(&mut edited.shape, shape, name);
                }
            })
            .response
            .accessible_name("shape");
        ui.end_row();

        ui.label("Material");
        egui::ComboBox::from_id_salt("material")
            .selected_text(edited.material.as_str())
            .show_ui(ui, |ui| {
                for name in scene.materials.keys() {
                    ui.selectable_value(&mut edited.material, name.clone(), name);
                }
            })
            .response
            .accessible_name("material");
        ui.end_row();
    });
    ui.add_space(6.0);
    ui.label(egui::RichText::new("Transform").strong());
    transform_ui(ui, &mut edited.transform);
    if edited != *object {
        commands.push(Command::Edit(SceneEdit::SetObject(index, edited)));
    }
    // The material's values right here, since that is what one tunes next.
    if let Some(material) = scene.materials.get(&object.material) {
        ui.add_space(6.0);
        egui::CollapsingHeader::new(
            egui::RichText::new(format!("Material \u{201c}{}\u{201d}", object.material)).strong(),
        )
        .id_salt("object material")
        .default_open(true)
        .show(ui, |ui| {
            let mut edited = material.clone();
            grid_ui(ui, "object material", |ui| {
                material_rows_ui(ui, &mut edited)
            });
            if edited != *material {
                commands.push(Command::Edit(SceneEdit::SetMaterial(
                    object.material.clone(),
                    edited,
                )));
            }
        });
    }
}

pub(super) fn transform_ui(ui: &mut Ui, transform: &mut Transform) {
    match transform {
        Transform::Trs(trs) => {
            grid_ui(ui, "trs", |ui| {
                vec3_row_ui(ui, "translate", &mut trs.translate, 0.01, Limits::ANY);
                vec3_row_ui(ui, "rotate", &mut trs.rotate_deg, 0.5, Limits::ANY);
                vec3_row_ui(ui, "scale", &mut trs.scale, 0.01, Limits::NONZERO);
            });
        }
        Transform::Matrix(rows) => {
            ui.weak("A general matrix (read-only): rows of the object-to-world transform.");
            egui::Grid::new("matrix")
                .spacing([10.0, 4.0])
                .show(ui, |ui| {
                    for row in rows.iter() {
                        for value in row {
                            ui.monospace(format!("{value:>8.3}"));
                        }
                        ui.end_row();
                    }
                });
            if ui
                .button("Reset to translate/rotate/scale")
                .on_hover_text("Keeps position, rotation and scale; drops any shear")
                .clicked()
            {
                *transform = Transform::Trs(trs_from_matrix(&transform.world_from_object()));
            }
        }
    }
}

/// The nearest translate / rotate / scale to an affine matrix (exact without shear).
#[must_use]
pub fn trs_from_matrix(affine: &glam::DAffine3) -> Trs {
    let (scale, rotation, translate) = affine.to_scale_rotation_translation();
    // Trs applies Rz * Ry * Rx: glam's ZYX order returns (z, y, x).
    let (z, y, x) = rotation.to_euler(glam::EulerRot::ZYX);
    let trs = Trs {
        translate,
        rotate_deg: DVec3::new(x.to_degrees(), y.to_degrees(), z.to_degrees()),
        scale,
    };
    if trs.scale.is_finite() && trs.rotate_deg.is_finite() && trs.scale.min_element().abs() > 0.0 {
        trs
    } else {
        Trs {
            translate,
            ..Trs::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_reset_keeps_a_shear_free_placement() {
        let trs = Trs {
            translate: DVec3::new(1.0, -2.0, 0.5),
            rotate_deg: DVec3::new(20.0, -35.0, 70.0),
            scale: DVec3::new(2.0, 0.5, 1.5),
        };
        let back = trs_from_matrix(&trs.world_from_object());
        let a = trs.world_from_object();
        let b = back.world_from_object();
        assert!(a.abs_diff_eq(b, 1e-9), "{a:?} vs {b:?}");
    }
}
