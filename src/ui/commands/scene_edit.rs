//! Scene edits as plain functions: add, duplicate, delete, rename and replace, with the
//! selection following what was added or removed. Testable without a window.

use glam::DVec3;

use super::{SceneEdit, Selection, placement, tree_edit, tree_move, tree_wrap};
use crate::scene::{Light, LightKind, Material, Object, Scene, Shape};

impl SceneEdit {
    /// Applies the edit; the selection follows added, duplicated and deleted items.
    ///
    /// # Errors
    /// A message for the user when the edit cannot be done (e.g. deleting a material that
    /// objects still use); the scene is then unchanged.
    pub fn apply(self, scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
        match self {
            SceneEdit::AddObject(shape) => {
                let base = shape.name().to_owned();
                add_object(scene, selection, shape, &base);
            }
            SceneEdit::AddMesh(path) => {
                let stem = std::path::Path::new(&path)
                    .file_stem()
                    .and_then(|s| s.to_str())
                    .filter(|s| !s.trim().is_empty())
                    .unwrap_or("mesh")
                    .to_owned();
                add_object(scene, selection, Shape::Mesh { path }, &stem);
                // A material of its own: recolouring the mesh must not recolour whatever
                // shares the first material (a floor of many tiles).
                let material = unique_name(&stem, scene.materials.keys());
                scene.materials.insert(material.clone(), Material::grey());
                if let Some(mesh) = scene.objects.last_mut() {
                    mesh.material = material;
                }
            }
            SceneEdit::AddLight(kind) => {
                scene.lights.push(new_light(kind));
                *selection = Selection::Light(scene.lights.len() - 1);
            }
            SceneEdit::AddMaterial => {
                let name = unique_name("material", scene.materials.keys());
                scene.materials.insert(name.clone(), Material::grey());
                *selection = Selection::Material(name);
            }
            SceneEdit::DuplicateSelected => duplicate(scene, selection)?,
            SceneEdit::DeleteSelected => delete(scene, selection)?,
            SceneEdit::SetObject(index, object) => {
                *scene.objects.get_mut(index).ok_or("no such object")? = object;
            }
            SceneEdit::SetPart(path, object) => tree_edit::set_node(scene, &path, object)?,
            SceneEdit::GroupSelected => tree_wrap::wrap_selected(scene, selection, None)?,
            SceneEdit::CsgSelected(op) => tree_wrap::wrap_selected(scene, selection, Some(op))?,
            SceneEdit::UngroupSelected => tree_wrap::ungroup_selected(scene, selection)?,
            SceneEdit::MoveNode { from, onto } => {
                tree_move::move_node(scene, selection, &from, &onto)?;
            }
            SceneEdit::AddOperand(shape) => tree_edit::add_operand(scene, selection, shape)?,
            SceneEdit::SetLight(index, light) => {
                *scene.lights.get_mut(index).ok_or("no such light")? = light;
            }
            SceneEdit::SetCamera(camera) => scene.camera = camera,
            SceneEdit::SetRender(render) => scene.render = render,
            SceneEdit::SetMaterial(name, material) => {
                *scene.materials.get_mut(&name).ok_or("no such material")? = material;
            }
            SceneEdit::MakeMaterialUnique(index) => {
                let object = scene.objects.get(index).ok_or("no such object")?;
                let material = scene
                    .materials
                    .get(&object.material)
                    .ok_or("the object has no material of its own to copy")?
                    .clone();
                let wanted = format!("{} ({})", object.material, object.name);
                let name = unique_name(&wanted, scene.materials.keys());
                scene.materials.insert(name.clone(), material);
                scene.objects[index].material = name;
            }
            SceneEdit::RenameMaterial { from, to } => {
                rename_material(scene, &from, &to)?;
                *selection = Selection::Material(to);
            }
        }
        Ok(())
    }
}

/// How many leaves (children and operands included) show `material`: their own, or the
/// one they inherit. A group or CSG node is not counted itself; its material shows only
/// on the leaves that inherit it.
#[must_use]
pub fn material_users(scene: &Scene, material: &str) -> usize {
    let mut count = 0;
    let mut work: Vec<(&Object, &str)> = scene
        .objects
        .iter()
        .map(|o| (o, o.material.as_str()))
        .collect();
    while let Some((object, shown)) = work.pop() {
        let children = object.shape.children();
        if children.is_empty() {
            count += usize::from(shown == material);
        }
        for child in children {
            let inherits = if child.material.is_empty() {
                shown
            } else {
                child.material.as_str()
            };
            work.push((child, inherits));
        }
    }
    count
}

/// Drops a selection that no longer points at anything (after undo, open, delete).
pub fn repair_selection(scene: &Scene, selection: &mut Selection) {
    let valid = match selection {
        Selection::Object(i) => *i < scene.objects.len(),
        Selection::Part(path) => tree_edit::part_exists(scene, path),
        Selection::Several(paths) => paths.iter().all(|p| tree_edit::part_exists(scene, p)),
        Selection::Light(i) => *i < scene.lights.len(),
        Selection::Material(name) => scene.materials.contains_key(name),
        Selection::None | Selection::Camera | Selection::Render => true,
    };
    if !valid {
        *selection = Selection::None;
    }
}

/// Adds an object of `shape` named `base` (or `base 2`, ... where taken), with the first
/// material and the placement of a new object, and selects it.
fn add_object(scene: &mut Scene, selection: &mut Selection, shape: Shape, base: &str) {
    let material = first_material(scene);
    let name = unique_name(base, scene.objects.iter().map(|o| &o.name));
    let transform = placement::new_object_transform(scene, &shape);
    scene.objects.push(Object {
        name,
        shape,
        transform,
        material,
    });
    *selection = Selection::Object(scene.objects.len() - 1);
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

/// A light of `kind` with sensible values for the default scene's scale.
fn new_light(kind: LightKind) -> Light {
    let colour = DVec3::ONE;
    match kind {
        LightKind::Ambient => Light::Ambient {
            colour: DVec3::splat(0.1),
            intensity: 1.0,
        },
        LightKind::Point => Light::Point {
            position: DVec3::new(2.0, 5.0, 3.0),
            colour,
            intensity: 20.0,
            radius: 0.0,
            samples: 1,
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
            radius: 0.0,
            samples: 1,
        },
    }
}

/// The first material's name; adds a grey "default" material to an empty table.
fn first_material(scene: &mut Scene) -> String {
    if let Some(name) = scene.materials.keys().next() {
        return name.clone();
    }
    scene
        .materials
        .insert("default".to_owned(), Material::grey());
    "default".to_owned()
}

fn duplicate(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    match selection.clone() {
        Selection::Object(i) => {
            let mut copy = scene.objects.get(i).ok_or("no such object")?.clone();
            copy.name = unique_name(&copy.name, scene.objects.iter().map(|o| &o.name));
            let offset = placement::duplicate_offset(scene, &copy.shape, &copy.transform);
            copy.transform = placement::moved(&copy.transform, offset);
            scene.objects.insert(i + 1, copy);
            *selection = Selection::Object(i + 1);
        }
        Selection::Light(i) => {
            let mut copy = scene.lights.get(i).ok_or("no such light")?.clone();
            if let Light::Point { position, .. } | Light::Spot { position, .. } = &mut copy {
                *position += placement::duplicate_light_offset(scene);
            }
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
        Selection::Part(path) => tree_edit::duplicate_part(scene, &path, selection)?,
        // Nothing duplicable selected: the shortcut does nothing.
        Selection::None | Selection::Camera | Selection::Render | Selection::Several(_) => {}
    }
    Ok(())
}

fn delete(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    match selection.clone() {
        Selection::Object(i) if i < scene.objects.len() => {
            scene.objects.remove(i);
            *selection = neighbour(i, scene.objects.len(), Selection::Object);
        }
        Selection::Part(path) => tree_edit::delete_part(scene, &path, selection)?,
        Selection::Several(paths) => {
            // Last first, so the paths before stay right; all or nothing.
            let mut edited = scene.clone();
            let mut sorted = paths;
            sorted.sort_unstable_by(|a, b| b.cmp(a));
            for path in &sorted {
                let mut one = Selection::node(path.clone());
                if path.len() == 1 {
                    edited.objects.remove(path[0]);
                } else {
                    tree_edit::delete_part(&mut edited, path, &mut one)?;
                }
            }
            *scene = edited;
            *selection = Selection::None;
        }
        Selection::Light(i) if i < scene.lights.len() => {
            scene.lights.remove(i);
            *selection = neighbour(i, scene.lights.len(), Selection::Light);
        }
        Selection::Material(name) => {
            let mut users: Vec<&str> = Vec::new();
            let mut work: Vec<&Object> = scene.objects.iter().collect();
            while let Some(object) = work.pop() {
                if object.material == name {
                    users.push(object.name.as_str());
                }
                work.extend(object.shape.children());
            }
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
    // Children and operands name materials too.
    let mut work: Vec<&mut Object> = scene.objects.iter_mut().collect();
    while let Some(object) = work.pop() {
        if object.material == from {
            object.material = to.to_owned();
        }
        if let Some(children) = object.shape.children_mut() {
            work.extend(children.iter_mut());
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Shape;

    fn scene() -> Scene {
        crate::scene::examples::default_scene()
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
        assert_eq!(selection, Selection::Object(7), "the copy is selected");
        assert_ne!(
            scene.objects[7].transform, scene.objects[6].transform,
            "the copy moved aside"
        );
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
