//! The course's conventions as explanations: a picture made by the course skeleton blends
//! mirrors as `(1 - km) local + km reflected` and clamps every ray's colour, which raylab
//! would otherwise report as a scatter of per-object factors. Before the fit, raylab's
//! picture is rendered under each other choice of mirror and clamp convention; where one
//! matches the other picture clearly better than the scene's own, the comparison is made
//! under it, and its first explanation names the convention (`mirror-blend`,
//! `clamp-each-ray`, ...) with the share of the difference it explains. A tracer without
//! a depth limit is tried the same way: raylab's picture with rays bouncing to
//! [`NO_LIMIT_DEPTH`] (`no-depth-limit`; in scenes with mirrors and no glass).

use glam::DVec3;

use super::search::{MIN_ERROR, MIN_STEP_SHARE};
use super::target::NOISE_SHARE;
use super::target::{FitState, Target};
use crate::scene::{ClampConvention, Conventions, MirrorConvention, Scene};

#[cfg(doc)]
use crate::trace::render;
use crate::trace::{MeshStore, RenderProgress, Variant, World, render_variants};

/// Another convention must take away at least this share of the difference the scene's
/// own leaves (a convention is the whole picture's habit: it explains much or nothing).
const MIN_CONVENTION_SHARE: f64 = 0.2;

/// How deep raylab's picture goes when trying a tracer without a depth limit: far past
/// any course scene's `max_depth`, where two mirrors' colour has long converged.
pub const NO_LIMIT_DEPTH: u32 = 48;

/// A convention that explains the other picture better than the scene's.
#[derive(Clone, Debug, PartialEq)]
pub struct BetterConventions {
    /// The conventions the other picture follows.
    pub conventions: Conventions,
    /// The ray depth it reaches (the scene's, or [`NO_LIMIT_DEPTH`]).
    pub max_depth: u32,
    /// The difference left under the scene's conventions, and under these.
    pub errors: (f64, f64),
    /// Pixels whose error fell, ascending.
    pub pixels: Vec<u32>,
}

/// Which mirror and clamp conventions explain `target` best, if better than the scene's
/// by [`MIN_CONVENTION_SHARE`] of the difference (and by more than a step's floor). The
/// quantisation is the encoding's business and stays the scene's. `own` is raylab's
/// picture under the scene's conventions (the split's, linear, unclamped). `None` also
/// when cancelled.
///
/// The candidates share one trace: each camera sample's ray tree, traced to the deepest
/// candidate's depth, folded under each (the pictures [`render`] would make of each).
#[must_use]
pub fn better_conventions(
    scene: &Scene,
    meshes: &MeshStore,
    own_picture: &[[f64; 3]],
    target: &Target,
    spp: u32,
    progress: &RenderProgress,
) -> Option<BetterConventions> {
    let own = scene.render.conventions;
    // The picture `render` writes holds each pixel in f32.
    let rendered = |pixels: Vec<[f64; 3]>| -> FitState { FitState::new(pixels, target) };
    let baseline = rendered(
        own_picture
            .iter()
            .map(|p| DVec3::from_array(*p).as_vec3().as_dvec3().to_array())
            .collect(),
    );
    if baseline.total < MIN_ERROR {
        return None;
    }
    let depth = scene.render.max_depth;
    // Without mirrors the mirror convention changes nothing: no render for it.
    let mirrors = scene
        .materials
        .values()
        .any(|m| m.mirror != glam::DVec3::ZERO);
    let mirror_choices: &[MirrorConvention] = if mirrors {
        &[MirrorConvention::Add, MirrorConvention::Blend]
    } else {
        std::slice::from_ref(&own.mirror)
    };
    let mut candidates: Vec<(Conventions, u32)> = Vec::new();
    for &mirror in mirror_choices {
        for clamp in [ClampConvention::Pixel, ClampConvention::EachRay] {
            let candidate = Conventions {
                mirror,
                clamp,
                quantise: own.quantise,
            };
            if candidate != own {
                candidates.push((candidate, depth));
            }
        }
    }
    // Rays past the depth limit need mirrors to bounce off. Not tried with glass: a
    // ray's tree splits at every glass surface, so its size grows as 2^depth.
    let glass = scene
        .materials
        .values()
        .any(|m| m.transmission != glam::DVec3::ZERO);
    if mirrors && !glass && depth < NO_LIMIT_DEPTH {
        candidates.push((own, NO_LIMIT_DEPTH));
    }
    let deepest = candidates.iter().map(|c| c.1).max().unwrap_or(depth);
    let mut traced = scene.clone();
    traced.render.max_depth = deepest;
    let world = World::with_meshes(&traced, meshes).ok()?;
    let variants: Vec<Variant> = candidates
        .iter()
        .map(|&(conventions, max_depth)| Variant {
            conventions,
            max_depth,
        })
        .collect();
    let size = (scene.camera.width, scene.camera.height);
    let pictures = render_variants(&world, size, spp, &variants, progress)?;
    let mut best: Option<((Conventions, u32), FitState)> = None;
    for (candidate, image) in candidates.into_iter().zip(pictures) {
        let model = image
            .pixels
            .iter()
            .map(|p| p.as_dvec3().to_array())
            .collect();
        let state = rendered(model);
        if best.as_ref().is_none_or(|(_, b)| state.total < b.total) {
            best = Some((candidate, state));
        }
    }
    let ((conventions, max_depth), state) = best?;
    let gain = baseline.total - state.total;
    let floor = (MIN_STEP_SHARE * baseline.total)
        .max(MIN_ERROR)
        .max(NOISE_SHARE * target.sampling_noise(&baseline.error));
    (gain >= MIN_CONVENTION_SHARE * baseline.total && gain >= floor).then(|| {
        let pixels = (0..baseline.error.len() as u32)
            .filter(|&p| state.error[p as usize] < baseline.error[p as usize])
            .collect();
        BetterConventions {
            conventions,
            max_depth,
            errors: (baseline.total, state.total),
            pixels,
        }
    })
}

/// The `cause` names of the conventions in which `to` differs from `from`:
/// `mirror-blend`, `mirror-add`, `clamp-each-ray`, `clamp-pixel`.
#[must_use]
pub fn convention_names(from: Conventions, to: Conventions) -> Vec<&'static str> {
    let mut names = Vec::new();
    if from.mirror != to.mirror {
        names.push(match to.mirror {
            MirrorConvention::Blend => "mirror-blend",
            MirrorConvention::Add => "mirror-add",
        });
    }
    if from.clamp != to.clamp {
        names.push(match to.clamp {
            ClampConvention::EachRay => "clamp-each-ray",
            ClampConvention::Pixel => "clamp-pixel",
        });
    }
    names
}
