//! Compare raylab's picture of a scene with another renderer's picture of it, and say
//! which light, object and term explain the difference (see docs/COMPARE.md).
//!
//! In folders by stage, in the order a comparison walks them; each depends only on the
//! ones before it (and on the inputs, `error` and `other_image`):
//!
//! | stage | folder | takes | gives |
//! |---|---|---|---|
//! | 1 | `catalogue` | the scene, its world | tree nodes, known bugs, nodes tried as missing, the channel numbering |
//! | 2 | `split` | the world, the catalogue | raylab's picture in channels per pixel (`Components`) |
//! | 3 | `fit` | the other picture, the channels | its encoding, better conventions, the search's steps |
//! | 4 | `extras` | the channels, the fitted model | objects the other picture draws and raylab does not |
//! | 5 | `verdict` | steps, extra objects, what is left | explanations, each with a sentence |
//! | 6 | `report` | both pictures, the explanations | the [`Comparison`]: JSON, text, report PNG |
//! | 7 | `plant` | the scene, bugs of the catalogue | pictures with those bugs (`raylab render --bug`, the gallery), and which explanation names each |
//!
//! This face runs them: [`prepare`] splits raylab's picture once per scene
//! ([`PreparedScene`]); [`compare_prepared`] reads each other picture under
//! the right encoding (and, where they fit it better, the course's other conventions,
//! comparing again under those), explains what is left and builds the [`Comparison`].
//!
//! No egui here: the command line and the editor show the same [`Comparison`].

mod catalogue;
mod error;
mod extras;
mod fit;
mod other_image;
pub mod perceptual;
pub mod plant;
mod prepared;
pub mod report;
mod split;
mod verdict;

pub use catalogue::{ClampBug, Kind, NormalBug, Part, ShadowBug, SpawnBug, SpecularBug, SpotBug};
pub use error::CompareError;
pub use extras::{PixelBox, ShapeGuess};
pub use fit::{Encoding, MIN_ERROR, MIN_STEP_SHARE, NOISE_SHARE};
pub use other_image::OtherImage;
pub use prepared::PreparedScene;
pub use report::{
    Comparison, PSNR_IDENTICAL_DB, PixelValues, difference_heatmap, report_png, write_report_png,
};
pub use split::{Components, render_components};
pub use verdict::{Cause, ExplainedTerm, Explanation, HIGH_CONFIDENCE, summary};

use crate::scene::{Quantise, Scene};
use crate::trace::{MeshStore, RenderProgress};

use fit::{
    BetterConventions, FitState, Floor, SamplingSpread, Target, better_conventions,
    detect_encoding, samples_otherwise,
};
use verdict::{Explained, explain};

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

/// As [`compare`], with the scene's mesh objects' triangles from `meshes`: the scene
/// prepared ([`PreparedScene::new`]) and compared ([`compare_prepared`]).
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
    check_size(scene, other)?;
    let prepared = prepare(scene, meshes, options, progress)?;
    compare_prepared(&prepared, other, progress)
}

/// Prepares `scene` for comparisons with any number of pictures ([`compare_prepared`]):
/// raylab's picture split into channels at the options' samples per pixel.
///
/// # Errors
/// [`CompareError::Scene`] when the scene cannot be compiled, and
/// [`CompareError::Cancelled`].
pub fn prepare(
    scene: &Scene,
    meshes: &MeshStore,
    options: &CompareOptions,
    progress: &RenderProgress,
) -> Result<PreparedScene, CompareError> {
    let spp = options
        .samples_per_pixel
        .unwrap_or(scene.render.samples_per_pixel)
        .max(1);
    PreparedScene::new(scene, meshes, spp, progress)
}

/// [`CompareError::SizeMismatch`] when `other` is not `scene`'s size.
///
/// # Errors
/// As said.
pub fn check_size(scene: &Scene, other: &OtherImage) -> Result<(), CompareError> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    if (other.width, other.height) != (width, height) {
        return Err(CompareError::SizeMismatch {
            other_width: other.width,
            other_height: other.height,
            scene_width: width,
            scene_height: height,
        });
    }
    Ok(())
}

/// Compares `other` with raylab's picture of a prepared scene: the same [`Comparison`]
/// as [`compare_with_meshes`] of that scene. What it prepares on the way (the
/// conventions' trial renders, a split under adopted conventions) is kept in `prepared`
/// for the next picture.
///
/// # Errors
/// [`CompareError::SizeMismatch`] when `other` is not the scene's size,
/// [`CompareError::Scene`] and [`CompareError::Cancelled`] from what it prepares.
pub fn compare_prepared(
    prepared: &PreparedScene,
    other: &OtherImage,
    progress: &RenderProgress,
) -> Result<Comparison, CompareError> {
    check_size(&prepared.scene, other)?;
    compare_scene(prepared, other, progress, true)
}

/// [`compare_prepared`]; first trying the course's other conventions where
/// `try_conventions` says so.
fn compare_scene(
    prepared: &PreparedScene,
    other: &OtherImage,
    progress: &RenderProgress,
    try_conventions: bool,
) -> Result<Comparison, CompareError> {
    let scene = &prepared.scene;
    let (width, height) = (scene.camera.width, scene.camera.height);
    let spp = prepared.spp;
    let components = &prepared.components;
    let world = &prepared.world;

    // The scene's own encoding first: its error is the whole difference.
    let expected = match scene.render.conventions.quantise {
        Quantise::Round => Encoding::LinearRound,
        Quantise::Truncate => Encoding::LinearTruncate,
    };
    let raylab_rgb = &prepared.raylab_rgb;
    // Where the other picture samples pixels otherwise than raylab, its edges may be
    // any blend of their sides (`fit::SamplingSpread`); elsewhere pixel for pixel.
    let none;
    let spread = if spp > 1 || samples_otherwise(raylab_rgb, &other.rgb, &prepared.outline, width) {
        prepared.spread()
    } else {
        none = SamplingSpread::none(components.beauty.len());
        &none
    };
    let rounded = Target::new(other, expected, spread);
    let mut state = FitState::new(components.beauty.clone(), &rounded);
    let total = state.total;
    let exact_floor = MIN_ERROR.max(NOISE_SHARE * rounded.sampling_noise(&state.error));
    let floor = (MIN_STEP_SHARE * total).max(exact_floor);
    let mut explanations = Vec::new();
    let encoding = detect_encoding(&components.beauty, &other.rgb);
    let target = if encoding == expected {
        rounded
    } else {
        let target = Target::new(other, encoding, spread);
        let decoded = FitState::new(components.beauty.clone(), &target);
        if state.total - decoded.total >= floor {
            explanations.push(encoding_explanation(
                &state, &decoded, encoding, scene, total,
            ));
        }
        state = decoded;
        target
    };
    let better = if try_conventions && total >= MIN_ERROR {
        better_conventions(&components.beauty, &target, || prepared.trials(progress))
    } else {
        None
    };
    let found = better.as_ref().map(|_| Found {
        total,
        explanations: explanations.clone(),
    });
    let explained = if total >= MIN_ERROR {
        let floors = Floor {
            any: floor,
            exact: exact_floor,
        };
        explain(components, scene, world, &target, &state, (total, floors))
    } else {
        Explained {
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

    let own = Comparison {
        width,
        height,
        samples_per_pixel: spp,
        psnr_db: report::psnr_db(raylab_rgb, &other.rgb),
        difference: report::difference(raylab_rgb, &other.rgb),
        raylab: prepared.raylab.clone(),
        raylab_rgb: raylab_rgb.clone(),
        other: other.clone(),
        encoding,
        objects: prepared.objects.clone(),
        object_names: scene.objects.iter().map(|o| o.name.clone()).collect(),
        explanations,
        unexplained_share,
        perceptual: std::sync::OnceLock::new(),
    };
    // The conventions and everything else are chosen together: a convention is the
    // reading only where, with the rest fitted under it too, it leaves less unexplained
    // than the scene's own conventions do with their fit (a missing light is a missing
    // light, whatever mirrors the scene holds).
    if let (Some(better), Some(found)) = (better, found) {
        let adopted = with_conventions(prepared, other, progress, &better, found)?;
        if unexplained_cost(&adopted, floor / total) < unexplained_cost(&own, floor / total) {
            return Ok(adopted);
        }
    }
    Ok(own)
}

/// What a reading leaves unexplained, as a share of the whole difference: what no
/// cause explains (the rest, and the places: silhouettes and shading), plus `per_step`
/// for each cause it names, so that of two readings leaving the same, the one with
/// fewer causes wins.
fn unexplained_cost(comparison: &Comparison, per_step: f64) -> f64 {
    let places: f64 = comparison
        .explanations
        .iter()
        .filter(|e| matches!(e.cause, Cause::Silhouette | Cause::Shading))
        .map(|e| e.share)
        .sum();
    let causes = comparison
        .explanations
        .iter()
        .filter(|e| {
            !matches!(
                e.cause,
                Cause::Silhouette | Cause::Shading | Cause::Sampling
            )
        })
        .count();
    comparison.unexplained_share + places + per_step * causes as f64
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
    prepared: &PreparedScene,
    other: &OtherImage,
    progress: &RenderProgress,
    better: &BetterConventions,
    found: Found,
) -> Result<Comparison, CompareError> {
    let scene = &prepared.scene;
    let adopted = prepared.adopted(better.conventions, better.max_depth, progress)?;
    let mut comparison = compare_scene(&adopted, other, progress, false)?;
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
