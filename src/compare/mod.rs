//! Compare raylab's picture of a scene with another renderer's picture of it, and say
//! which light, object and term explain the difference (see docs/COMPARE.md).
//!
//! 1. [`components`]: raylab's picture split into channels (each term of each light on
//!    each object, and what each known bug or missing part would change), traced once
//!    through the tracer's own shading code.
//! 2. [`encoding`]: the other picture's 8-bit encoding is found, and each byte read as
//!    the interval of values it stands for, so rounding never counts as a difference.
//! 3. [`search`]: a greedy least-squares fit over groups of channels; each accepted
//!    group is an explanation with its share of the squared difference.
//! 4. [`verdicts`] and [`localise`]: steps become sentences; what nothing explains is
//!    localised as geometry (outlines) or shading (inside objects).
//!
//! No egui here: the command line and the editor show the same [`Comparison`].

pub mod bugs;
pub mod channels;
pub mod components;
pub mod conventions_fit;
pub mod different_scene;
pub mod encoding;
pub mod error;
pub mod explain;
pub mod explanation;
pub mod extra_object;
pub mod extra_shadow;
pub mod groups;
pub mod localise;
pub mod missing_nodes;
pub mod nodes;
pub mod other_image;
pub mod perceptual;
pub mod record_context;
pub mod recorder;
pub mod regions;
pub mod relit;
pub mod report;
pub mod report_image;
pub mod rivals;
pub mod search;
pub mod shape_guess;
pub mod spot_bugs;
pub mod summary;
pub mod target;
pub mod verdicts;

pub use encoding::Encoding;
pub use error::CompareError;
pub use explanation::{Cause, ExplainedTerm, Explanation};
pub use other_image::OtherImage;
pub use report::{Comparison, PSNR_IDENTICAL_DB, PixelValues};
pub use report_image::{difference_heatmap, report_png, write_report_png};

use crate::scene::{Quantise, Scene};
use crate::trace::{MeshStore, RenderProgress, World};

use components::{MISS, render_components};
use explanation::summary;
use target::{FitState, Target};

/// A step must lower the error by at least this share of the whole difference...
pub const MIN_STEP_SHARE: f64 = 0.005;

/// ...and by at least this much: four channels a full 8-bit level outside their bytes.
/// A difference smaller than this is no difference.
pub const MIN_ERROR: f64 = 4.0 / (255.0 * 255.0);

/// How to compare.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CompareOptions {
    /// Samples per pixel of raylab's picture; `None` for the scene's own.
    pub samples_per_pixel: Option<u32>,
}

/// Compares raylab's picture of `scene` (at the scene's size) with `other`.
/// `progress` reports rows traced and can cancel.
///
/// # Errors
/// [`CompareError::SizeMismatch`] when `other` is not the scene's size,
/// [`CompareError::Scene`] when the scene cannot be compiled, and
/// [`CompareError::Cancelled`].
pub fn compare(
    scene: &Scene,
    other: &OtherImage,
    options: &CompareOptions,
    progress: &RenderProgress,
) -> Result<Comparison, CompareError> {
    compare_with_meshes(scene, &MeshStore::default(), other, options, progress)
}

/// As [`compare`], with the scene's mesh objects' triangles from `meshes`.
///
/// # Errors
/// As [`compare`]; a mesh object whose file is not in `meshes` is a
/// [`CompareError::Scene`].
pub fn compare_with_meshes(
    scene: &Scene,
    meshes: &MeshStore,
    other: &OtherImage,
    options: &CompareOptions,
    progress: &RenderProgress,
) -> Result<Comparison, CompareError> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    if (other.width, other.height) != (width, height) {
        return Err(CompareError::SizeMismatch {
            other_width: other.width,
            other_height: other.height,
            scene_width: width,
            scene_height: height,
        });
    }
    let spp = options
        .samples_per_pixel
        .unwrap_or(scene.render.samples_per_pixel)
        .max(1);
    compare_scene(scene, meshes, other, spp, progress, true)
}

/// [`compare_with_meshes`] at `spp` samples; first trying the course's other
/// conventions where `try_conventions` says so.
fn compare_scene(
    scene: &Scene,
    meshes: &MeshStore,
    other: &OtherImage,
    spp: u32,
    progress: &RenderProgress,
    try_conventions: bool,
) -> Result<Comparison, CompareError> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    let world =
        World::with_meshes(scene, meshes).map_err(|e| CompareError::Scene(e.to_string()))?;
    let components = render_components(scene, &world, (width, height), spp, progress)
        .ok_or(CompareError::Cancelled)?;

    // The scene's own encoding first: its error is the whole difference.
    let expected = match scene.render.conventions.quantise {
        Quantise::Round => Encoding::LinearRound,
        Quantise::Truncate => Encoding::LinearTruncate,
    };
    let rounded = Target::new(other, expected);
    let mut state = FitState::new(components.beauty.clone(), &rounded);
    let total = state.total;
    let floor = (MIN_STEP_SHARE * total).max(MIN_ERROR);
    let mut explanations = Vec::new();
    let encoding = encoding::detect(&components.beauty, &other.rgb);
    let target = if encoding == expected {
        rounded
    } else {
        let target = Target::new(other, encoding);
        let decoded = FitState::new(components.beauty.clone(), &target);
        if state.total - decoded.total >= floor {
            explanations.push(encoding_explanation(
                &state, &decoded, encoding, scene, total,
            ));
        }
        state = decoded;
        target
    };
    if try_conventions
        && total >= MIN_ERROR
        && let Some(better) =
            conventions_fit::better_conventions(scene, meshes, &target, spp, progress)
    {
        let found = Found {
            total,
            explanations,
        };
        return with_conventions(scene, meshes, other, spp, progress, &better, found);
    }
    let explained = if total >= MIN_ERROR {
        explain::explain(&components, scene, &world, &target, &state, (total, floor))
    } else {
        explain::Explained {
            explanations: Vec::new(),
            unexplained_share: 0.0,
        }
    };
    explanations.extend(explained.explanations);
    // Largest share first, after a different-scene verdict, which frames the rest.
    explanations.sort_by(|a, b| {
        let framing = |e: &Explanation| e.term == ExplainedTerm::Scene;
        framing(b)
            .cmp(&framing(a))
            .then(b.share.total_cmp(&a.share))
    });
    let unexplained_share = explained.unexplained_share;

    let raylab = components.image();
    let raylab_rgb = report::rgb_of(&raylab);
    Ok(Comparison {
        width,
        height,
        samples_per_pixel: spp,
        psnr_db: report::psnr_db(&raylab_rgb, &other.rgb),
        difference: report::difference(&raylab_rgb, &other.rgb),
        raylab,
        raylab_rgb,
        other: other.clone(),
        encoding,
        objects: (0..components.labels.len())
            .map(|p| components.object_label(p))
            .map(|l| (l != MISS).then_some(l as usize))
            .collect(),
        object_names: scene.objects.iter().map(|o| o.name.clone()).collect(),
        explanations,
        unexplained_share,
    })
}

/// What the comparison under the scene's conventions found before trying others: the
/// whole difference, and the encoding's verdict (if any, as a share of it).
struct Found {
    total: f64,
    explanations: Vec<Explanation>,
}

/// The comparison made under the conventions the other picture follows, with the
/// convention as its first explanation. Shares stay parts of the whole difference: the
/// encoding's as found, the convention's what it took away, and the rest (found again
/// under the convention, its own encoding verdict dropped) scaled to what remained.
fn with_conventions(
    scene: &Scene,
    meshes: &MeshStore,
    other: &OtherImage,
    spp: u32,
    progress: &RenderProgress,
    better: &conventions_fit::BetterConventions,
    found: Found,
) -> Result<Comparison, CompareError> {
    let mut adopted = scene.clone();
    adopted.render.conventions = better.conventions;
    adopted.render.max_depth = better.max_depth;
    let mut comparison = compare_scene(&adopted, meshes, other, spp, progress, false)?;
    let (before, after) = better.errors;
    let is_encoding = |e: &Explanation| e.term == ExplainedTerm::Encoding;
    let inner_encoding: f64 = comparison
        .explanations
        .iter()
        .filter(|e| is_encoding(e))
        .map(|e| e.share)
        .sum();
    comparison.explanations.retain(|e| !is_encoding(e));
    let scale = (after / found.total) / (1.0 - inner_encoding).max(f64::MIN_POSITIVE);
    for e in &mut comparison.explanations {
        e.share *= scale;
    }
    comparison.unexplained_share *= scale;
    let mut convention = Explanation {
        term: ExplainedTerm::Conventions,
        light: None,
        object: None,
        object_name: None,
        node: Vec::new(),
        factor: 1.0,
        share: (before - after) / found.total,
        pixels: better.pixels.clone(),
        bbox: None,
        fits_as_well: Vec::new(),
        cause: Cause::Conventions {
            scene: scene.render.conventions,
            other: better.conventions,
            depth: (better.max_depth != scene.render.max_depth).then_some(better.max_depth),
        },
        confidence: 1.0 - after / before,
        summary: String::new(),
    };
    convention.summary = summary(&convention, scene);
    let mut explanations = vec![convention];
    explanations.extend(found.explanations);
    explanations.append(&mut comparison.explanations);
    comparison.explanations = explanations;
    Ok(comparison)
}

/// The explanation of reading the other picture with another encoding.
fn encoding_explanation(
    before: &FitState,
    after: &FitState,
    encoding: Encoding,
    scene: &Scene,
    total: f64,
) -> Explanation {
    let pixels = (0..before.error.len() as u32)
        .filter(|&p| after.error[p as usize] < before.error[p as usize])
        .collect();
    let mut e = Explanation {
        term: ExplainedTerm::Encoding,
        light: None,
        object: None,
        object_name: None,
        node: Vec::new(),
        factor: 1.0,
        share: (before.total - after.total) / total,
        pixels,
        cause: Cause::Encoding(encoding),
        bbox: None,
        fits_as_well: Vec::new(),
        confidence: 1.0 - after.total / before.total.max(f64::MIN_POSITIVE),
        summary: String::new(),
    };
    e.summary = summary(&e, scene);
    e
}
