//! The isolation flags shared by `raylab render` and `raylab inspect`: lights muted or
//! solo by their index in the scene's list, objects hidden by name. They turn into the
//! library's [`Isolation`], so the command line shows what the editor shows.

use clap::Args;

use crate::scene::{Object, Scene, Shape};
use crate::trace::Isolation;
use crate::trace::check_indices;

/// `--mute-light`, `--solo-light`, `--hide` (flatten into a command's arguments).
#[derive(Clone, Debug, Default, Args)]
pub struct IsolationArgs {
    /// Lights to switch off, by index in the scene's `lights` list (from 0; the editor's
    /// "Point light 2" is index 1), comma-separated.
    #[arg(long, value_delimiter = ',', value_name = "I")]
    pub mute_light: Vec<usize>,
    /// Render as if only this light shone (through mirrors too; term switches still
    /// apply). Several, comma-separated, shine together. The first Ambient light's solo
    /// (or the first light's, without one) also shows the background.
    #[arg(long, value_delimiter = ',', value_name = "I")]
    pub solo_light: Vec<usize>,
    /// Objects to leave out of the render (no shadow, no reflection), by name,
    /// comma-separated; a name shared by several objects hides them all. A tree path
    /// (`snowman/body`) hides a group's child or a CSG operand.
    #[arg(long, value_delimiter = ',', value_name = "NAME")]
    pub hide: Vec<String>,
}

impl IsolationArgs {
    /// The library's switches for `scene`.
    ///
    /// # Errors
    /// A light index the scene does not have, or an object name it does not have.
    pub fn isolation(&self, scene: &Scene) -> Result<Isolation, String> {
        let mut isolation = Isolation {
            muted_lights: self.mute_light.iter().copied().collect(),
            solo_lights: self.solo_light.iter().copied().collect(),
            ..Isolation::NONE
        };
        for name in self.hide.iter().filter(|name| !is_tree_path(scene, name)) {
            let named: Vec<usize> = (0..scene.objects.len())
                .filter(|&i| scene.objects[i].name == name.as_str())
                .collect();
            if named.is_empty() {
                return Err(unknown_object(name, scene));
            }
            isolation.hidden_objects.extend(named);
        }
        // Objects come from names, so only a light index can be out of range here.
        check_indices(&isolation, scene).map_err(|e| format!("--mute-light/--solo-light: {e}"))?;
        Ok(isolation)
    }
}

/// Whether `--hide` names a node below the top level: a path with a `/` that is not
/// also a top-level object's name.
fn is_tree_path(scene: &Scene, name: &str) -> bool {
    name.contains('/') && !scene.objects.iter().any(|o| o.name == name)
}

impl IsolationArgs {
    /// `scene` without the nodes `--hide` names by tree path (a group's child, or a CSG
    /// operand, which leaves the node's solid without it); the top-level objects keep
    /// their indices, so the other flags mean the same. Every node a path names goes.
    ///
    /// # Errors
    /// A path that names no node, with the children its parent has.
    pub fn without_hidden_children(&self, scene: &Scene) -> Result<Scene, String> {
        let mut pruned = scene.clone();
        for path in self.hide.iter().filter(|name| is_tree_path(scene, name)) {
            let (parent, child) = path.rsplit_once('/').expect("a tree path has a '/'");
            let mut found = false;
            let mut level: Vec<&mut Vec<Object>> = vec![&mut pruned.objects];
            for part in parent.split('/') {
                level = level
                    .into_iter()
                    .flat_map(|list| list.iter_mut().filter(|o| o.name == part))
                    .filter_map(|o| match &mut o.shape {
                        Shape::Group { children } => Some(children),
                        Shape::Csg { operands, .. } => Some(operands),
                        _ => None,
                    })
                    .collect();
            }
            for list in level {
                let before = list.len();
                list.retain(|o| o.name != child);
                found |= list.len() != before;
            }
            if !found {
                return Err(format!("--hide: no object at the tree path \"{path}\""));
            }
        }
        Ok(pruned)
    }
}

/// "--hide: no object named "lamp" (objects: "floor", "red ball")".
fn unknown_object(name: &str, scene: &Scene) -> String {
    let names: Vec<String> = scene
        .objects
        .iter()
        .map(|o| format!("\"{}\"", o.name))
        .collect();
    let listed = if names.is_empty() {
        "the scene has none".to_owned()
    } else {
        format!("objects: {}", names.join(", "))
    };
    format!("--hide: no object named \"{name}\" ({listed})")
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Flags {
        #[command(flatten)]
        isolation: IsolationArgs,
    }

    fn parse(args: &[&str]) -> IsolationArgs {
        Flags::parse_from(std::iter::once("raylab").chain(args.iter().copied())).isolation
    }

    #[test]
    fn flags_become_the_library_switches() {
        let scene = crate::scene::examples::default_scene();
        let args = parse(&[
            "--mute-light",
            "1,3",
            "--solo-light",
            "2",
            "--hide",
            "red ball,floor",
        ]);
        let isolation = args.isolation(&scene).unwrap();
        assert_eq!(
            isolation.muted_lights.iter().copied().collect::<Vec<_>>(),
            [1, 3]
        );
        assert_eq!(
            isolation.solo_lights.iter().copied().collect::<Vec<_>>(),
            [2]
        );
        assert_eq!(
            isolation.hidden_objects.iter().copied().collect::<Vec<_>>(),
            [0, 1]
        );
        assert_eq!(parse(&[]).isolation(&scene).unwrap(), Isolation::NONE);
    }

    #[test]
    fn a_bad_index_or_name_is_a_clear_error() {
        let scene = crate::scene::examples::default_scene();
        let error = parse(&["--solo-light", "4"]).isolation(&scene).unwrap_err();
        assert_eq!(
            error,
            "--mute-light/--solo-light: there is no light 4: the scene has 4 lights (indices 0 to 3)"
        );
        let error = parse(&["--hide", "lamp"]).isolation(&scene).unwrap_err();
        assert!(
            error.starts_with("--hide: no object named \"lamp\" (objects: \"floor\""),
            "{error}"
        );
    }

    #[test]
    fn a_tree_path_hides_a_child_and_keeps_the_top_level_indices() {
        let scene = crate::scene::load_scene(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenes/csg.ron"
        )))
        .unwrap();
        let args = parse(&["--hide", "die/pip 1.1,floor"]);
        let pruned = args.without_hidden_children(&scene).unwrap();
        let operands = |s: &Scene| match &s.objects[2].shape {
            Shape::Csg { operands, .. } => operands.len(),
            _ => panic!("the die is a CSG node"),
        };
        assert_eq!(operands(&pruned), operands(&scene) - 1);
        assert_eq!(pruned.objects.len(), scene.objects.len());
        let isolation = args.isolation(&pruned).unwrap();
        assert_eq!(
            isolation.hidden_objects.iter().copied().collect::<Vec<_>>(),
            [0]
        );
        let error = parse(&["--hide", "die/pip 9"])
            .without_hidden_children(&scene)
            .unwrap_err();
        assert_eq!(error, "--hide: no object at the tree path \"die/pip 9\"");
    }
}
