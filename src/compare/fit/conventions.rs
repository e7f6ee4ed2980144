//! The course's conventions as explanations: a picture made by the course skeleton blends
//! mirrors as `(1 - km) local + km reflected` and clamps every ray's colour, which raylab
//! would otherwise report as a scatter of per-object factors. Before the fit, raylab's
//! picture is rendered under each other choice of mirror and clamp convention; where one
//! matches the other picture clearly better than the scene's own, the comparison is made
//! under it, and its first explanation names the convention (`mirror-blend`,
//! `clamp-each-ray`, ...) with the share of the difference it explains. A tracer without
//! a depth limit is tried the same way: raylab's picture with rays bouncing to
//! [`NO_LIMIT_DEPTH`] (`no-depth-limit`; in scenes with mirrors and no glass).

use super::search::{MIN_ERROR, MIN_STEP_SHARE};
use super::target::NOISE_SHARE;
use super::target::{FitState, Target};
use crate::scene::{ClampConvention, Conventions, MirrorConvention, Scene};
use crate::trace::{MeshStore, RenderOptions, RenderProgress, World, render};

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
/// quantisation is the encoding's business and stays the scene's. `None` also when
/// cancelled.
#[must_use]
pub fn better_conventions(
    scene: &Scene,
    meshes: &MeshStore,
    target: &Target,
    spp: u32,
    progress: &RenderProgress,
) -> Option<BetterConventions> {
    let own = scene.render.conventions;
    let error_under = |conventions: Conventions, max_depth: u32| -> Option<FitState> {
        let mut varied = scene.clone();
        varied.render.conventions = conventions;
        varied.render.max_depth = max_depth;
        let world = World::with_meshes(&varied, meshes).ok()?;
        let options = RenderOptions {
            samples_per_pixel: spp,
            ..RenderOptions::from_scene(&varied)
        };
        let (image, _) = render(&world, &options, progress)?;
        let model = image
            .pixels
            .iter()
            .map(|p| p.as_dvec3().to_array())
            .collect();
        Some(FitState::new(model, target))
    };
    let depth = scene.render.max_depth;
    let baseline = error_under(own, depth)?;
    if baseline.total < MIN_ERROR {
        return None;
    }
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
    let mut best: Option<((Conventions, u32), FitState)> = None;
    for candidate in candidates {
        let state = error_under(candidate.0, candidate.1)?;
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
