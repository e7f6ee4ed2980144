//! The shadow an extra object casts, and its reflections, where they touch it: pixels
//! still off after the search whose colour is the model with some lights taken away,
//! or darker than it and a lighting of the surfaces there (or that lie on a mirror),
//! reached from the object through such pixels.
//!
//! Claimed in two steps, because the model they are compared with is not yet right when
//! they are found: first generously (against the model of the first search, which the
//! extra object bent, or raylab's own picture), then, after the fit ran again without
//! the object and those pixels, only the ones the new model does not explain (a second
//! bug, such as a light that never lights, darkens everything; the new model has it).

use super::channels::Kind;
use super::components::Components;
use super::extra_object::{ExtraObject, RELIT_TOLERANCE, on_mirror};
use super::localise::OFF_LEVELS;
use super::regions::{Grid, PixelBox};
use super::relit::{Palette, is_relit};
use super::target::Target;

/// Whether the other picture at `p` is `model`'s colour there with the light of one or
/// more lights taken away: a shadow.
pub(super) fn shadow_like(
    components: &Components,
    target: &Target,
    model: [f64; 3],
    p: usize,
) -> bool {
    let lights = components.space.lights;
    let mut lit = vec![[0.0f64; 3]; lights];
    for entry in components.pixel(p) {
        if let Kind::Diffuse(l) | Kind::Specular(l) = components.space.decode(entry.channel).0 {
            (0..3).for_each(|c| lit[l][c] += f64::from(entry.value[c]));
        }
    }
    // Every set of lights up to four; beyond, each light alone.
    let sets: Vec<u32> = if lights <= 4 {
        (1..1u32 << lights).collect()
    } else {
        (0..lights).map(|l| 1 << l).collect()
    };
    sets.into_iter().any(|set| {
        let mut shadowed = model;
        for (_, colour) in lit.iter().enumerate().filter(|(l, _)| set & (1 << l) != 0) {
            (0..3).for_each(|c| shadowed[c] -= colour[c]);
        }
        target.pixel_error(p, &shadowed) < RELIT_TOLERANCE
    })
}

/// Whether the other picture at `p` may be a shadow on `model`: darker than it in every
/// channel and some lighting of the surfaces there ([`is_relit`]: where an object is
/// missing too, the surface behind it, whose lights the model's channels do not hold),
/// or exactly the model with some lights taken away, or on a mirror.
fn dark(
    components: &Components,
    palette: &Palette,
    target: &Target,
    model: [f64; 3],
    p: usize,
) -> bool {
    let darker =
        (0..3).all(|c| target.middle[p][c] <= model[c].clamp(0.0, 1.0) + OFF_LEVELS / 255.0);
    on_mirror(components, p)
        || shadow_like(components, target, model, p)
        || (darker && is_relit(components, palette, target, p, RELIT_TOLERANCE))
}

/// Whether the model `model` leaves pixel `p` off.
fn is_off(target: &Target, model: &[[f64; 3]], p: usize) -> bool {
    target.pixel_error(p, &model[p]) >= (OFF_LEVELS / 255.0).powi(2)
}

/// Sets each extra object's shadow: the pixels off under `model` (the first search's)
/// that may be a shadow on it ([`dark`]) or are one of raylab's own picture, reached
/// from the object's pixels, within the object's size of its box.
pub fn find_shadows(
    extras: &mut [ExtraObject],
    components: &Components,
    palette: &Palette,
    target: &Target,
    model: &[[f64; 3]],
) {
    let grid = Grid {
        width: components.width,
        height: components.height,
    };
    for extra in extras.iter_mut() {
        let shadow = |p: usize| {
            is_off(target, model, p)
                && (dark(components, palette, target, model[p], p)
                    || shadow_like(components, target, components.beauty[p], p))
        };
        extra.shadow = reached(grid, &extra.pixels, extra.bbox, shadow);
    }
}

/// Keeps of each extra object's shadow the pixels that `model` (fitted without the
/// objects and their shadows) leaves off and that may be a shadow on it ([`dark`]).
pub fn confirm_shadows(
    extras: &mut [ExtraObject],
    components: &Components,
    palette: &Palette,
    target: &Target,
    model: &[[f64; 3]],
) {
    for extra in extras.iter_mut() {
        extra.shadow.retain(|&p| {
            let p = p as usize;
            is_off(target, model, p) && dark(components, palette, target, model[p], p)
        });
    }
}

/// The pixels for which `dark` holds, reached from `own` through such pixels, within
/// the size of `bbox` (the object's box) of it; ascending.
fn reached(grid: Grid, own: &[u32], bbox: PixelBox, dark: impl Fn(usize) -> bool) -> Vec<u32> {
    let reach = i64::from((bbox.x1 - bbox.x0).max(bbox.y1 - bbox.y0) + 1);
    let near = |p: usize| {
        let (x, y) = grid.xy(p);
        x >= i64::from(bbox.x0) - reach
            && x <= i64::from(bbox.x1) + reach
            && y >= i64::from(bbox.y0) - reach
            && y <= i64::from(bbox.y1) + reach
    };
    let mut seen = vec![false; (grid.width * grid.height) as usize];
    for &p in own {
        seen[p as usize] = true;
    }
    let mut work = own.to_vec();
    let mut shadow = Vec::new();
    while let Some(p) = work.pop() {
        for q in grid.around(p as usize) {
            if !seen[q] && near(q) && dark(q) {
                seen[q] = true;
                work.push(q as u32);
                shadow.push(q as u32);
            }
        }
    }
    shadow.sort_unstable();
    shadow
}
