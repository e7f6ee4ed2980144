//! Everything the panels can ask for, as values. Panels push commands while laying out;
//! the app applies them once per frame (`app.rs`), which also feeds undo and restarts the
//! preview. Scene edits are plain functions here, testable without a window.

use std::path::PathBuf;

use glam::DVec3;

use crate::scene::{Camera, Light, Material, Object, RenderSettings, Scene, Shape, Transform};

/// What the inspector shows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Selection {
    /// Nothing selected.
    #[default]
    None,
    /// The camera.
    Camera,
    /// The render settings.
    Render,
    /// An object, by index.
    Object(usize),
    /// A material, by name.
    Material(String),
    /// A light, by index.
    Light(usize),
}

/// The four light kinds, for the "add light" menu.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    /// Ambient light.
    Ambient,
    /// Point light.
    Point,
    /// Directional light.
    Directional,
    /// Spot light.
    Spot,
}

impl LightKind {
    /// Every kind, in menu order.
    pub const ALL: [LightKind; 4] = [
        LightKind::Ambient,
        LightKind::Point,
        LightKind::Directional,
        LightKind::Spot,
    ];

    /// The kind's name, as in files.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LightKind::Ambient => "Ambient",
            LightKind::Point => "Point",
            LightKind::Directional => "Directional",
            LightKind::Spot => "Spot",
        }
    }

    /// A light of this kind with sensible values for the default scene's scale.
    #[must_use]
    pub fn new_light(self) -> Light {
        let colour = DVec3::ONE;
        match self {
            LightKind::Ambient => Light::Ambient {
                colour: DVec3::splat(0.1),
                intensity: 1.0,
            },
            LightKind::Point => Light::Point {
                position: DVec3::new(2.0, 5.0, 3.0),
                colour,
                intensity: 20.0,
            },
            LightKind::Directional => Light::Directional {
                direction: DVec3::new(-1.0, -2.0, -1.0),
                colour,
                intensity: 0.8,
            },
            LightKind::Spot => Light::Spot {
                position: DVec3::new(0.0, 5.0, 0.0),
                direction: DVec3::new(0.0, -1.0, 0.0),
                angle_deg: 25.0,
                colour,
                intensity: 20.0,
            },
        }
    }
}

/// A change to the scene (and the selection that follows it).
#[derive(Clone, Debug, PartialEq)]
pub enum SceneEdit {
    /// Adds a unit shape with the first material (creating one if there is none).
    AddObject(Shape),
    /// Adds a light of a kind.
    AddLight(LightKind),
    /// Adds a grey material with a fresh name.
    AddMaterial,
    /// Duplicates the selected object, light or material.
    DuplicateSelected,
    /// Deletes the selected object, light or (unused) material.
    DeleteSelected,
    /// Replaces an object.
    SetObject(usize, Object),
    /// Replaces a light.
    SetLight(usize, Light),
    /// Replaces the camera.
    SetCamera(Camera),
    /// Replaces the render settings.
    SetRender(RenderSettings),
    /// Replaces a material's values.
    SetMaterial(String, Material),
    /// Renames a material and every reference to it.
    RenameMaterial {
        /// The current name.
        from: String,
        /// The new name.
        to: String,
    },
}

impl SceneEdit {
    /// Whether the edit names an object or light by its index.
    #[must_use]
    pub fn is_by_index(&self) -> bool {
        matches!(self, SceneEdit::SetObject(..) | SceneEdit::SetLight(..))
    }
}

/// Everything a panel, shortcut or dialog can ask the app to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Change what the inspector shows.
    Select(Selection),
    /// Edit the scene (one undo step, unless part of a drag).
    Edit(SceneEdit),
    /// Go back one undo step.
    Undo,
    /// Go forward one undo step.
    Redo,
    /// Replace the scene by a new one (asks first if there are unsaved changes).
    New,
    /// Show the Open dialog (asks first if there are unsaved changes).
    OpenDialog,
    /// Open a scene file (asks first if there are unsaved changes).
    Open(PathBuf),
    /// Save to the current file, or ask for one.
    Save,
    /// Show the Save As dialog.
    SaveAsDialog,
    /// Save to a file, which becomes the current file.
    SaveAs(PathBuf),
    /// Show the Import Legacy dialog (asks first if there are unsaved changes).
    ImportLegacyDialog,
    /// Import a legacy text scene (asks first if there are unsaved changes).
    ImportLegacy(PathBuf),
    /// Show the Export PNG window.
    ShowExport,
    /// Show the keyboard shortcuts.
    ShowHelp,
    /// Close the window (asks first if there are unsaved changes).
    Quit,
    /// Hide the error area.
    DismissError,
    /// Put the keyboard focus in the inspector's name field (outliner "Rename").
    FocusName,
    /// Change the preview's switches, view and debug overlays (editor state, not undoable).
    SetPreviewSettings(super::preview_settings::PreviewSettings),
    /// Inspect a pixel of the scene camera's image, or close the pixel inspector (`None`).
    InspectPixel(Option<(u32, u32)>),
}

impl SceneEdit {
    /// Applies the edit; the selection follows added, duplicated and deleted items.
    ///
    /// # Errors
    /// A message for the user when the edit cannot be done (e.g. deleting a material that
    /// objects still use); the scene is then unchanged.
    pub fn apply(self, scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
        match self {
            SceneEdit::AddObject(shape) => {
                let material = first_material(scene);
                let name = unique_name(shape.name(), scene.objects.iter().map(|o| &o.name));
                scene.objects.push(Object {
                    name,
                    shape,
                    transform: Transform::default(),
                    material,
                });
                *selection = Selection::Object(scene.objects.len() - 1);
            }
            SceneEdit::AddLight(kind) => {
                scene.lights.push(kind.new_light());
                *selection = Selection::Light(scene.lights.len() - 1);
            }
            SceneEdit::AddMaterial => {
                let name = unique_name("material", scene.materials.keys());
                scene.materials.insert(name.clone(), grey_material());
                *selection = Selection::Material(name);
            }
            SceneEdit::DuplicateSelected => duplicate(scene, selection)?,
            SceneEdit::DeleteSelected => delete(scene, selection)?,
            SceneEdit::SetObject(index, object) => {
                *scene.objects.get_mut(index).ok_or("no such object")? = object;
            }
            SceneEdit::SetLight(index, light) => {
                *scene.lights.get_mut(index).ok_or("no such light")? = light;
            }
            SceneEdit::SetCamera(camera) => scene.camera = camera,
            SceneEdit::SetRender(render) => scene.render = render,
            SceneEdit::SetMaterial(name, material) => {
                *scene.materials.get_mut(&name).ok_or("no such material")? = material;
            }
            SceneEdit::RenameMaterial { from, to } => {
                rename_material(scene, &from, &to)?;
                *selection = Selection::Material(to);
            }
        }
        Ok(())
    }
}

/// Drops a selection that no longer points at anything (after undo, open, delete).
pub fn repair_selection(scene: &Scene, selection: &mut Selection) {
    let valid = match selection {
        Selection::Object(i) => *i < scene.objects.len(),
        Selection::Light(i) => *i < scene.lights.len(),
        Selection::Material(name) => scene.materials.contains_key(name),
        Selection::None | Selection::Camera | Selection::Render => true,
    };
    if !valid {
        *selection = Selection::None;
    }
}

/// `base` if unused, else `base 2`, `base 3`...
#[must_use]
pub fn unique_name<'a>(base: &str, taken: impl Iterator<Item = &'a String>) -> String {
    let taken: Vec<&String> = taken.collect();
    let free = |name: &str| !taken.iter().any(|t| t.as_str() == name);
    if free(base) {
        return base.to_owned();
    }
    (2..)
        .map(|n| format!("{base} {n}"))
        .find(|name| free(name))
        .unwrap_or_else(|| base.to_owned())
}

fn grey_material() -> Material {
    Material {
        ambient: DVec3::splat(0.1),
        diffuse: DVec3::splat(0.6),
        specular: DVec3::splat(0.3),
        shininess: 32.0,
        mirror: DVec3::ZERO,
    }
}

/// The first material's name; adds a grey "default" material to an empty table.
fn first_material(scene: &mut Scene) -> String {
    if let Some(name) = scene.materials.keys().next() {
        return name.clone();
    }
    scene
        .materials
        .insert("default".to_owned(), grey_material());
    "default".to_owned()
}

fn duplicate(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    match selection.clone() {
        Selection::Object(i) => {
            let mut copy = scene.objects.get(i).ok_or("no such object")?.clone();
            copy.name = unique_name(&copy.name, scene.objects.iter().map(|o| &o.name));
            scene.objects.insert(i + 1, copy);
            *selection = Selection::Object(i + 1);
        }
        Selection::Light(i) => {
            let copy = scene.lights.get(i).ok_or("no such light")?.clone();
            scene.lights.insert(i + 1, copy);
            *selection = Selection::Light(i + 1);
        }
        Selection::Material(name) => {
            let copy = scene
                .materials
                .get(&name)
                .ok_or("no such material")?
                .clone();
            let new_name = unique_name(&name, scene.materials.keys());
            scene.materials.insert(new_name.clone(), copy);
            *selection = Selection::Material(new_name);
        }
        // Nothing duplicable selected: the shortcut does nothing.
        Selection::None | Selection::Camera | Selection::Render => {}
    }
    Ok(())
}

fn delete(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    match selection.clone() {
        Selection::Object(i) if i < scene.objects.len() => {
            scene.objects.remove(i);
            *selection = neighbour(i, scene.objects.len(), Selection::Object);
        }
        Selection::Light(i) if i < scene.lights.len() => {
            scene.lights.remove(i);
            *selection = neighbour(i, scene.lights.len(), Selection::Light);
        }
        Selection::Material(name) => {
            let users: Vec<&str> = scene
                .objects
                .iter()
                .filter(|o| o.material == name)
                .map(|o| o.name.as_str())
                .collect();
            if !users.is_empty() {
                return Err(format!(
                    "material \"{name}\" is used by {}; give them another material first",
                    users.join(", ")
                ));
            }
            scene.materials.remove(&name);
            *selection = Selection::None;
        }
        // Nothing deletable selected (or stale): the shortcut does nothing.
        _ => {}
    }
    Ok(())
}

/// The item that takes the place of a deleted one: the next, else the previous.
fn neighbour(index: usize, len: usize, make: fn(usize) -> Selection) -> Selection {
    if len == 0 {
        Selection::None
    } else {
        make(index.min(len - 1))
    }
}

fn rename_material(scene: &mut Scene, from: &str, to: &str) -> Result<(), String> {
    let to = to.trim();
    if to.is_empty() {
        return Err("a material needs a name".to_owned());
    }
    if from == to {
        return Ok(());
    }
    if scene.materials.contains_key(to) {
        return Err(format!("there is already a material \"{to}\""));
    }
    let material = scene
        .materials
        .remove(from)
        .ok_or_else(|| format!("no material \"{from}\""))?;
    scene.materials.insert(to.to_owned(), material);
    for object in &mut scene.objects {
        if object.material == from {
            object.material = to.to_owned();
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Scene {
        crate::scene::parse_scene(include_str!("../../scenes/default.ron")).unwrap()
    }

    #[test]
    fn add_duplicate_delete_keep_names_unique_and_selection_valid() {
        let mut scene = scene();
        let mut selection = Selection::None;
        SceneEdit::AddObject(Shape::Cone)
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(selection, Selection::Object(6));
        SceneEdit::DuplicateSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(scene.objects[7].name, "Cone 2");
        SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(selection, Selection::Object(6));
        assert_eq!(scene.objects.len(), 7);
        crate::scene::validate(&scene).unwrap();
    }

    #[test]
    fn a_used_material_is_not_deleted_and_renames_follow_references() {
        let mut scene = scene();
        let mut selection = Selection::Material("gold".to_owned());
        let error = SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap_err();
        assert!(error.contains("gold cone"), "{error}");
        SceneEdit::RenameMaterial {
            from: "gold".to_owned(),
            to: "brass".to_owned(),
        }
        .apply(&mut scene, &mut selection)
        .unwrap();
        assert_eq!(scene.objects[5].material, "brass");
        assert_eq!(selection, Selection::Material("brass".to_owned()));
        crate::scene::validate(&scene).unwrap();
    }
}
