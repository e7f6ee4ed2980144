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

/// raylab's pictures of a scene under the course's other conventions (and without a
/// depth limit), made once per scene whatever picture it is compared with: the
/// candidates [`better_conventions`] chooses from.
#[derive(Clone, Debug, Default)]
pub struct ConventionTrials {
    /// Each candidate's conventions and ray depth, and its picture (linear, unclamped,
    /// each pixel as `render` writes it, in f32).
    candidates: Vec<(Candidate, Vec<[f64; 3]>)>,
}

/// A candidate reading: conventions and a ray depth.
type Candidate = (Conventions, u32);

/// The pictures of `scene` under each other choice of mirror and clamp convention (the
/// quantisation is the encoding's business and stays the scene's), and at
/// [`NO_LIMIT_DEPTH`] where mirrors and no glass make that differ. `None` when cancelled.
///
/// The candidates share one trace: each camera sample's ray tree, traced to the deepest
/// candidate's depth, folded under each (the pictures [`render`] would make of each).
#[must_use]
pub fn convention_trials(
    scene: &Scene,
    meshes: &MeshStore,
    spp: u32,
    progress: &RenderProgress,
) -> Option<ConventionTrials> {
    let own = scene.render.conventions;
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
    let mut candidates: Vec<Candidate> = Vec::new();
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
    // A scene that does not compile this deep has no candidates (none is better).
    let Ok(world) = World::with_meshes(&traced, meshes) else {
        return Some(ConventionTrials::default());
    };
    let variants: Vec<Variant> = candidates
        .iter()
        .map(|&(conventions, max_depth)| Variant {
            conventions,
            max_depth,
        })
        .collect();
    let size = (scene.camera.width, scene.camera.height);
    let pictures = render_variants(&world, size, spp, &variants, progress)?;
    let pictures = pictures.into_iter().map(|image| {
        image
            .pixels
            .iter()
            .map(|p| p.as_dvec3().to_array())
            .collect()
    });
    Some(ConventionTrials {
        candidates: candidates.into_iter().zip(pictures).collect(),
    })
}

/// Which mirror and clamp conventions explain `target` best, if better than the scene's
/// by [`MIN_CONVENTION_SHARE`] of the difference (and by more than a step's floor). `own`
/// is raylab's picture under the scene's conventions (the split's, linear, unclamped).
/// `trials` gives the candidates' pictures ([`convention_trials`]); it is asked only
/// when the scene's own conventions leave a difference, and `None` from it (cancelled)
/// is `None` here.
#[must_use]
pub fn better_conventions<'a>(
    own_picture: &[[f64; 3]],
    target: &Target,
    trials: impl FnOnce() -> Option<&'a ConventionTrials>,
) -> Option<BetterConventions> {
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
    let mut best: Option<(Candidate, FitState)> = None;
    for (candidate, model) in &trials()?.candidates {
        let state = rendered(model.clone());
        if best.as_ref().is_none_or(|(_, b)| state.total < b.total) {
            best = Some((*candidate, state));
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
