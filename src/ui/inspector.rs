//! The inspector: every field of the selected item (object, light, material, camera,
//! render settings). It edits a copy and pushes a command when the copy changed.

use egui::{DragValue, Ui};
use glam::DVec3;

use super::commands::{Command, SceneEdit, Selection};
use crate::scene::{
    Camera, Light, MAX_IMAGE_SIDE, Material, Object, RenderSettings, Scene, Shape, Transform, Trs,
};

/// The deepest mirror recursion the scene validation accepts.
const MAX_DEPTH: u32 = 64;

/// Shows the inspector for `selection`.
/// `focus_name` asks to put the keyboard in the name field (it is reset once done).
pub fn inspector_ui(
    ui: &mut Ui,
    scene: &Scene,
    selection: &Selection,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| match selection {
            Selection::None => {
                ui.add_space(8.0);
                ui.weak("Select an object, light or material in the outliner or the viewport.");
            }
            Selection::Camera => camera_ui(ui, &scene.camera, commands),
            Selection::Render => render_ui(ui, &scene.render, commands),
            Selection::Object(index) => {
                if let Some(object) = scene.objects.get(*index) {
                    object_ui(ui, scene, *index, object, focus_name, commands);
                }
            }
            Selection::Light(index) => {
                if let Some(light) = scene.lights.get(*index) {
                    light_ui(ui, *index, light, commands);
                }
            }
            Selection::Material(name) => {
                if let Some(material) = scene.materials.get(name) {
                    material_ui(ui, name, material, focus_name, commands);
                }
            }
        });
}

fn heading_ui(ui: &mut Ui, kind: &str, title: &str) {
    ui.add_space(4.0);
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new(kind).small().weak());
        ui.heading(title);
    });
    ui.separator();
}

/// A two-column grid of labelled rows.
fn grid_ui(ui: &mut Ui, id: &str, rows: impl FnOnce(&mut Ui)) {
    egui::Grid::new(id)
        .num_columns(2)
        .spacing([12.0, 6.0])
        .min_col_width(72.0)
        .show(ui, rows);
}

fn object_ui(
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
                    ui.selectable_value(&mut edited.shape, shape, shape.name());
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

fn transform_ui(ui: &mut Ui, transform: &mut Transform) {
    match transform {
        Transform::Trs(trs) => {
            grid_ui(ui, "trs", |ui| {
                vec3_row_ui(
                    ui,
                    "translate",
                    &mut trs.translate,
                    0.01,
                    f64::NEG_INFINITY..=f64::INFINITY,
                );
                vec3_row_ui(ui, "rotate", &mut trs.rotate_deg, 0.5, -360.0..=360.0);
                vec3_row_ui(ui, "scale", &mut trs.scale, 0.01, 1e-4..=f64::INFINITY);
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

/// Three drag values named "`label` x/y/z".
fn vec3_row_ui(
    ui: &mut Ui,
    label: &str,
    value: &mut DVec3,
    speed: f64,
    range: std::ops::RangeInclusive<f64>,
) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(ui, 3, 0.0);
        for (axis, component) in
            ["x", "y", "z"]
                .into_iter()
                .zip([&mut value.x, &mut value.y, &mut value.z])
        {
            ui.add_sized(
                [width, ui.spacing().interact_size.y],
                DragValue::new(component)
                    .speed(speed)
                    .range(range.clone())
                    .max_decimals(3)
                    .prefix(format!("{axis} "))
                    .suffix(if label == "rotate" { "°" } else { "" }),
            )
            .accessible_name(format!("{label} {axis}"));
        }
    });
    ui.end_row();
}

/// The width of one of `count` fields sharing a row after `reserved` points.
fn field_width(ui: &Ui, count: usize, reserved: f32) -> f32 {
    let spacing = ui.spacing().item_spacing.x * (count as f32 - 1.0);
    ((ui.available_width() - reserved - spacing) / count as f32).clamp(44.0, 96.0)
}

/// A linear-RGB colour: a picker plus the three numbers (lights may exceed 1).
fn colour_row_ui(ui: &mut Ui, label: &str, colour: &mut DVec3) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(
            ui,
            3,
            ui.spacing().interact_size.x + ui.spacing().item_spacing.x,
        );
        // The picker works in f32 through HSV and may hand back a value that moved by
        // rounding alone: only a real change from the user is taken.
        let clamped = colour.as_vec3().to_array().map(|c| c.clamp(0.0, 1.0));
        let mut picked = clamped;
        let response = ui
            .color_edit_button_rgb(&mut picked)
            .accessible_name(format!("{label} colour"));
        let moved = picked
            .iter()
            .zip(clamped)
            .any(|(a, b)| (a - b).abs() > 1e-4);
        if response.changed() && moved {
            *colour = glam::Vec3::from_array(picked).as_dvec3();
        }
        for (channel, component) in
            ["r", "g", "b"]
                .into_iter()
                .zip([&mut colour.x, &mut colour.y, &mut colour.z])
        {
            ui.add_sized(
                [width, ui.spacing().interact_size.y],
                DragValue::new(component)
                    .speed(0.005)
                    .range(0.0..=f64::INFINITY)
                    .max_decimals(3)
                    .prefix(format!("{channel} ")),
            )
            .accessible_name(format!("{label} {channel}"));
        }
    });
    ui.end_row();
}

/// One labelled drag value.
fn number_row_ui<N: egui::emath::Numeric>(
    ui: &mut Ui,
    label: &str,
    value: &mut N,
    speed: f64,
    range: std::ops::RangeInclusive<N>,
) {
    let mut drag = DragValue::new(value).speed(speed).range(range);
    if !N::INTEGRAL {
        drag = drag.max_decimals(3);
    }
    if matches!(label, "angle" | "fov") {
        drag = drag.suffix("°");
    }
    let label = ui.label(label);
    ui.add(drag).labelled_by(label.id);
    ui.end_row();
}

fn light_ui(ui: &mut Ui, index: usize, light: &Light, commands: &mut Vec<Command>) {
    heading_ui(ui, "LIGHT", &format!("{} light", light.kind_name()));
    let mut edited = light.clone();
    grid_ui(ui, "light", |ui| match &mut edited {
        Light::Ambient { colour, intensity } => {
            colour_row_ui(ui, "colour", colour);
            number_row_ui(ui, "intensity", intensity, 0.01, 0.0..=f64::INFINITY);
        }
        Light::Point {
            position,
            colour,
            intensity,
        } => {
            vec3_row_ui(
                ui,
                "position",
                position,
                0.02,
                f64::NEG_INFINITY..=f64::INFINITY,
            );
            colour_row_ui(ui, "colour", colour);
            number_row_ui(ui, "intensity", intensity, 0.1, 0.0..=f64::INFINITY);
        }
        Light::Directional {
            direction,
            colour,
            intensity,
        } => {
            vec3_row_ui(
                ui,
                "direction",
                direction,
                0.01,
                f64::NEG_INFINITY..=f64::INFINITY,
            );
            colour_row_ui(ui, "colour", colour);
            number_row_ui(ui, "intensity", intensity, 0.01, 0.0..=f64::INFINITY);
        }
        Light::Spot {
            position,
            direction,
            angle_deg,
            colour,
            intensity,
        } => {
            vec3_row_ui(
                ui,
                "position",
                position,
                0.02,
                f64::NEG_INFINITY..=f64::INFINITY,
            );
            vec3_row_ui(
                ui,
                "direction",
                direction,
                0.01,
                f64::NEG_INFINITY..=f64::INFINITY,
            );
            number_row_ui(ui, "angle", angle_deg, 0.2, 0.1..=90.0);
            colour_row_ui(ui, "colour", colour);
            number_row_ui(ui, "intensity", intensity, 0.1, 0.0..=f64::INFINITY);
        }
    });
    if edited != *light {
        commands.push(Command::Edit(SceneEdit::SetLight(index, edited)));
    }
}

fn material_ui(
    ui: &mut Ui,
    name: &str,
    material: &Material,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    heading_ui(ui, "MATERIAL", name);
    let mut edited = material.clone();
    grid_ui(ui, "material", |ui| {
        ui.label("Name");
        // The name is a key: edit a buffer, rename when the field is left.
        let id = ui.make_persistent_id(("material name", name));
        let mut buffer = ui
            .data_mut(|d| d.get_temp::<String>(id))
            .unwrap_or_else(|| name.to_owned());
        let response = ui
            .add(egui::TextEdit::singleline(&mut buffer).desired_width(f32::INFINITY))
            .accessible_name("material name");
        if std::mem::take(focus_name) {
            response.request_focus();
        }
        if response.lost_focus() {
            ui.data_mut(|d| d.remove::<String>(id));
            if buffer != name {
                commands.push(Command::Edit(SceneEdit::RenameMaterial {
                    from: name.to_owned(),
                    to: buffer,
                }));
            }
        } else if response.has_focus() {
            ui.data_mut(|d| d.insert_temp(id, buffer));
        }
        ui.end_row();
        material_rows_ui(ui, &mut edited);
    });
    if edited != *material {
        commands.push(Command::Edit(SceneEdit::SetMaterial(
            name.to_owned(),
            edited,
        )));
    }
}

/// The rows of a material's values.
fn material_rows_ui(ui: &mut Ui, material: &mut Material) {
    colour_row_ui(ui, "ambient", &mut material.ambient);
    colour_row_ui(ui, "diffuse", &mut material.diffuse);
    colour_row_ui(ui, "specular", &mut material.specular);
    number_row_ui(
        ui,
        "shininess",
        &mut material.shininess,
        0.5,
        1e-3..=10_000.0,
    );
    colour_row_ui(ui, "mirror", &mut material.mirror);
}

fn camera_ui(ui: &mut Ui, camera: &Camera, commands: &mut Vec<Command>) {
    heading_ui(ui, "CAMERA", "Camera");
    let mut edited = camera.clone();
    grid_ui(ui, "camera", |ui| {
        vec3_row_ui(
            ui,
            "position",
            &mut edited.position,
            0.02,
            f64::NEG_INFINITY..=f64::INFINITY,
        );
        vec3_row_ui(
            ui,
            "look at",
            &mut edited.look_at,
            0.02,
            f64::NEG_INFINITY..=f64::INFINITY,
        );
        vec3_row_ui(
            ui,
            "up",
            &mut edited.up,
            0.01,
            f64::NEG_INFINITY..=f64::INFINITY,
        );
        number_row_ui(ui, "fov", &mut edited.fov_deg, 0.2, 1.0..=179.0);
        number_row_ui(ui, "width", &mut edited.width, 1.0, 1..=MAX_IMAGE_SIDE);
        number_row_ui(ui, "height", &mut edited.height, 1.0, 1..=MAX_IMAGE_SIDE);
    });
    ui.weak("fov is the vertical field of view, in degrees. Width and height are the output size.");
    if edited != *camera {
        commands.push(Command::Edit(SceneEdit::SetCamera(edited)));
    }
}

fn render_ui(ui: &mut Ui, render: &RenderSettings, commands: &mut Vec<Command>) {
    heading_ui(ui, "RENDER", "Render settings");
    let mut edited = render.clone();
    grid_ui(ui, "render", |ui| {
        number_row_ui(ui, "max depth", &mut edited.max_depth, 0.1, 0..=MAX_DEPTH);
        colour_row_ui(ui, "background", &mut edited.background);
        number_row_ui(ui, "samples", &mut edited.samples_per_pixel, 0.2, 1..=1024);
    });
    ui.weak(
        "max depth: mirror bounces. samples: anti-aliasing samples per pixel; \
         the preview refines up to this and Export PNG uses it.",
    );
    if edited != *render {
        commands.push(Command::Edit(SceneEdit::SetRender(edited)));
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
