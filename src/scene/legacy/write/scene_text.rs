//! The whole file: the Scene block, then the camera, lights, materials and objects, in
//! the order the readers need them; refusals collected on the way.

use super::super::convert::Dialect;
use super::lights::write_lights;
use super::materials::{material_block, material_names};
use super::numbers::triple;
use super::objects::year;
use super::objects::{ObjectWriter, used_materials};
use super::problem::Problems;
use super::problem::{CourseExportError, Problem, Subject};
use crate::scene::{Conventions, Scene, validate};

/// A scene written in the course format, and what it lost.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CourseScene {
    /// The file's text.
    pub text: String,
    /// What was written with a loss, each naming what it is about.
    pub warnings: Vec<Problem>,
}

/// Writes `scene` in `dialect`. Mesh paths are written as the scene has them (relative
/// to the scene's folder: rebase them first where the text goes elsewhere).
///
/// # Errors
/// Everything the dialect cannot say, each naming its object, light or material (and
/// the warnings found on the way).
pub fn write_course_scene(
    scene: &Scene,
    dialect: Dialect,
) -> Result<CourseScene, CourseExportError> {
    let mut problems = Problems::default();
    if let Err(error) = validate(scene) {
        problems.refuse(
            Subject::Scene,
            format!("it breaks the scene rules: {error}"),
        );
        return Err(refused(problems));
    }
    let lights = write_lights(&scene.lights, dialect, &mut problems);
    let mut text = format!(
        "# Written by raylab {} in the COSC342 course format, the {} framework's dialect.\n\n",
        env!("CARGO_PKG_VERSION"),
        year(dialect)
    );
    text.push_str(&scene_block(
        scene,
        dialect,
        lights.scene_ambient,
        &mut problems,
    ));
    text.push('\n');
    text.push_str(&super::camera::camera_block(&scene.camera));
    text.push('\n');
    if !lights.blocks.is_empty() {
        text.push_str(&lights.blocks);
        text.push('\n');
    }
    let names = material_names(&scene.materials, dialect, &mut problems);
    let used = used_materials(&scene.objects);
    for (name, material) in &scene.materials {
        text.push_str(&material_block(
            name,
            &names[name],
            material,
            used.contains(name),
            dialect,
            &mut problems,
        ));
    }
    text.push('\n');
    text.push_str(&ObjectWriter::new(dialect, &names, &mut problems).write_all(&scene.objects));
    if problems.refusals.is_empty() {
        Ok(CourseScene {
            text,
            warnings: problems.warnings,
        })
    } else {
        Err(refused(problems))
    }
}

fn refused(problems: Problems) -> CourseExportError {
    CourseExportError {
        refusals: problems.refusals,
        warnings: problems.warnings,
    }
}

/// The Scene block; defaults are written too, so the file says what it renders.
fn scene_block(
    scene: &Scene,
    dialect: Dialect,
    ambient: Option<glam::DVec3>,
    problems: &mut Problems,
) -> String {
    let render = &scene.render;
    let camera = &scene.camera;
    let mut text = String::from("Scene\n");
    text.push_str(&format!(
        "  renderSize {} {}\n",
        camera.width, camera.height
    ));
    text.push_str(&format!(
        "  backgroundColour {}\n",
        triple(render.background)
    ));
    text.push_str(&format!("  rayDepth {}\n", render.max_depth));
    if let Some(colour) = ambient {
        text.push_str(&format!("  ambientLight {}\n", triple(colour)));
    }
    let samples = render.samples_per_pixel;
    if samples > 1 {
        match dialect {
            Dialect::Framework2020 => {
                let per_axis = nearest_square_root(samples);
                if per_axis * per_axis != samples {
                    problems.warn(
                        Subject::Render,
                        format!(
                            "{samples} samples per pixel is not a square; the course's FSAA N \
                             takes N x N: written as FSAA {per_axis} ({} samples)",
                            per_axis * per_axis
                        ),
                    );
                }
                if per_axis > 1 {
                    text.push_str(&format!("  FSAA {per_axis}\n"));
                }
            }
            Dialect::Framework2016 => problems.warn(
                Subject::Render,
                format!(
                    "{samples} samples per pixel are not written: the 2016 dialect has no \
                     anti-aliasing (one sample per pixel)"
                ),
            ),
        }
    }
    if render.conventions != Conventions::COURSE {
        let c = render.conventions;
        let k = Conventions::COURSE;
        problems.warn(
            Subject::Render,
            format!(
                "the render conventions (mirror: {:?}, clamp: {:?}, quantise: {:?}) are not in \
                 the course format; its readers, and raylab's import, render with the course's \
                 (mirror: {:?}, clamp: {:?}, quantise: {:?})",
                c.mirror, c.clamp, c.quantise, k.mirror, k.clamp, k.quantise
            ),
        );
    }
    text.push_str("End\n");
    text
}

/// The whole number nearest to the square root of `n`, at least 1.
fn nearest_square_root(n: u32) -> u32 {
    let root = f64::from(n).sqrt().round();
    // A square root of a u32 is at most 65536, so the conversion is exact.
    (root as u32).max(1)
}
