//! Scene edits as values and as plain functions: add, duplicate, delete, rename and
//! replace, with the selection following what was added or removed. Edits of the object
//! trees go through `scene::tree`. Testable without a window.

use glam::DVec3;

use super::placement;
use super::selection::Selection;
use crate::scene::tree::{
    add_child, delete_node, insert_node, move_node, object_at, object_at_mut, unique_name,
    unwrap_group, wrap_node, wrap_nodes,
};
use crate::scene::{
    Camera, CsgOp, Light, LightKind, LightSource, Material, Object, RenderSettings, Scene, Shape,
};

/// A change to the scene (and the selection that follows it).
#[derive(Clone, Debug, PartialEq)]
pub enum SceneEdit {
    /// Adds a unit shape where the camera looks, upright and standing on the floor if
    /// there is one, with the first material (creating one if there is none).
    AddObject(Shape),
    /// Adds a Mesh object for the OBJ file at this path (as the scene writes it), named
    /// after the file.
    AddMesh(String),
    /// Adds a light of a kind.
    AddLight(LightKind),
    /// Adds a grey material with a fresh name.
    AddMaterial,
    /// Duplicates the selected object or light (moved aside, so both are seen) or
    /// material, and selects the copy.
    DuplicateSelected,
    /// Deletes the selected object, light or (unused) material.
    DeleteSelected,
    /// Replaces an object.
    SetObject(usize, Object),
    /// Replaces a node inside an object tree, by path.
    SetPart(Vec<usize>, Object),
    /// Puts the selected object or part into a new group in its place (Ctrl+G).
    GroupSelected,
    /// Puts the selected object or part, as the first operand, into a new CSG node of
    /// this operator in its place (add the other operands next).
    CsgSelected(CsgOp),
    /// Puts the selected group's children in its place, placed as they were.
    UngroupSelected,
    /// Moves a node (by path) into a tree node, as its last child or operand, or beside
    /// a leaf, right after it; it stays where it is in the world (outliner drag).
    MoveNode {
        /// The node moved.
        from: Vec<usize>,
        /// Where it was dropped.
        onto: Vec<usize>,
    },
    /// Adds a unit shape as the last operand or child of the selected tree node.
    AddOperand(Shape),
    /// Replaces a light.
    SetLight(usize, Light),
    /// Replaces the camera.
    SetCamera(Camera),
    /// Replaces the render settings.
    SetRender(RenderSettings),
    /// Replaces a material's values.
    SetMaterial(String, Material),
    /// Gives an object its own copy of the material it shares with others, named after
    /// both ("gold (flat ring)"), so editing it changes only that object.
    MakeMaterialUnique(usize),
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
        matches!(
            self,
            SceneEdit::SetObject(..)
                | SceneEdit::SetPart(..)
                | SceneEdit::SetLight(..)
                | SceneEdit::MakeMaterialUnique(_)
        )
    }
}

/// The operators offered for a CSG node, with a line on what each keeps.
pub const CSG_OPS: [(CsgOp, &str); 3] = [
    (CsgOp::Union, "inside any operand"),
    (CsgOp::Intersection, "inside every operand"),
    (
        CsgOp::Difference,
        "inside the first operand and none of the others",
    ),
];

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
            SceneEdit::SetPart(path, object) => {
                *object_at_mut(&mut scene.objects, &path).ok_or("no such object")? = object;
            }
            SceneEdit::GroupSelected => wrap_selected(scene, selection, None)?,
            SceneEdit::CsgSelected(op) => wrap_selected(scene, selection, Some(op))?,
            SceneEdit::UngroupSelected => {
                let path = selection.node_path().ok_or("select a group to ungroup")?;
                *selection = Selection::node(unwrap_group(&mut scene.objects, &path)?);
            }
            SceneEdit::MoveNode { from, onto } => {
                *selection = Selection::node(move_node(&mut scene.objects, &from, &onto)?);
            }
            SceneEdit::AddOperand(shape) => add_operand(scene, selection, shape)?,
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
    scene
        .nodes()
        .filter(|node| node.is_leaf() && node.shown_material == material)
        .count()
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
            source: LightSource::point(colour, 20.0),
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
            source: LightSource::point(colour, 20.0),
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
        Selection::Part(path) => duplicate_part(scene, &path, selection)?,
        // Nothing duplicable selected: the shortcut does nothing.
        Selection::None | Selection::Camera | Selection::Render | Selection::Several(_) => {}
    }
    Ok(())
}

fn delete(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    match selection.clone() {
        Selection::Object(i) if i < scene.objects.len() => {
            let next = delete_node(&mut scene.objects, &[i])?;
            *selection = next.map_or(Selection::None, Selection::node);
        }
        Selection::Part(path) => {
            let next = delete_node(&mut scene.objects, &path)?;
            *selection = next.map_or(Selection::None, Selection::node);
        }
        Selection::Several(paths) => {
            // Last first, so the paths before stay right; all or nothing.
            let mut edited = scene.objects.clone();
            let mut sorted = paths;
            sorted.sort_unstable_by(|a, b| b.cmp(a));
            for path in &sorted {
                delete_node(&mut edited, path)?;
            }
            scene.objects = edited;
            *selection = Selection::None;
        }
        Selection::Light(i) if i < scene.lights.len() => {
            scene.lights.remove(i);
            *selection = neighbour(i, scene.lights.len(), Selection::Light);
        }
        Selection::Material(name) => {
            let users: Vec<&str> = scene
                .nodes()
                .filter(|node| node.object.material == name)
                .map(|node| node.object.name.as_str())
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

/// Wraps the selected node (or the several selected, of one list) into a new group
/// (`op` `None`) or CSG node, and selects the new node.
fn wrap_selected(
    scene: &mut Scene,
    selection: &mut Selection,
    op: Option<CsgOp>,
) -> Result<(), String> {
    let wrapped = if let Selection::Several(paths) = selection {
        wrap_nodes(&mut scene.objects, paths, op)?
    } else {
        let path = selection.node_path().ok_or("select an object first")?;
        wrap_node(&mut scene.objects, &path, op)?
    };
    *selection = Selection::node(wrapped);
    Ok(())
}

/// Adds a unit shape as the last operand (or child) of the selected tree node, placed
/// beside its first operand (see `placement::beside_first`), and selects it.
fn add_operand(scene: &mut Scene, selection: &mut Selection, shape: Shape) -> Result<(), String> {
    let path = selection
        .node_path()
        .ok_or("select a CSG node or a group")?;
    let node = object_at(&scene.objects, &path).ok_or("no such object")?;
    let children = node.shape.children();
    let operand = Object {
        name: unique_name(shape.name(), children.iter().map(|o| &o.name)),
        transform: placement::beside_first(children.first()),
        shape,
        // Inherits the node's material.
        material: String::new(),
    };
    *selection = Selection::Part(add_child(&mut scene.objects, &path, operand)?);
    Ok(())
}

/// Duplicates the selected part of a tree beside it (moved aside, so both are seen),
/// and selects the copy.
fn duplicate_part(
    scene: &mut Scene,
    path: &[usize],
    selection: &mut Selection,
) -> Result<(), String> {
    let (&at, parent) = path.split_last().ok_or("no such object")?;
    let original = object_at(&scene.objects, path).ok_or("no such object")?;
    let mut copy = original.clone();
    let offset = placement::duplicate_offset(scene, &copy.shape, &copy.transform);
    copy.transform = placement::moved(&copy.transform, offset);
    let siblings = object_at(&scene.objects, parent).ok_or("no such object")?;
    copy.name = unique_name(
        &copy.name,
        siblings.shape.children().iter().map(|o| &o.name),
    );
    let next = [parent, &[at + 1]].concat();
    insert_node(&mut scene.objects, &next, copy)?;
    *selection = Selection::Part(next);
    Ok(())
}

/// The light that takes the place of a deleted one: the next, else the previous.
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
    scene.edit_nodes(|object| {
        if object.material == from {
            object.material = to.to_owned();
        }
    });
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

#[cfg(test)]
mod tree_tests;
