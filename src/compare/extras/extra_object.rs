//! An object the other picture draws and raylab does not (a shape the student's scene
//! has one more of, or one raylab skipped). Left to the fit, its pixels are spread over
//! factors of whatever lies behind it; found here after a first search, they are taken
//! out of the fit (which then runs again) and named as one `extra-object` verdict with
//! its bounding box and a guess of its shape.
//!
//! The evidence, pixel by pixel and at its outline:
//! - the pixel is still off after the search, and no lighting of raylab's surface there,
//!   or of what lies behind it, gives its colour ([`super::relit`]: a missing object is
//!   not an extra one), nor the fitted model with some lights taken away (a shadow);
//! - along the region's outline, where raylab sees one surface on both sides, the other
//!   picture has an edge raylab's does not: a sharp outline, not a shading that fades;
//! - and it is not one of raylab's surfaces reaching further: where the region's
//!   outline crosses raylab's, the other picture mostly has an edge there too (a moved
//!   outline, as in a picture of another version of the scene, continues smoothly).
//!
//! A region on a mirror, other than the strongest region, is the extra object's
//! reflection: it joins the strongest region.
//!
//! Its shadow, and its reflections, where they touch it: pixels still off after the
//! search whose colour is the model with some lights taken away, or darker than it and a
//! lighting of the surfaces there (or that lie on a mirror), reached from the object
//! through such pixels. Claimed in two steps, because the model they are compared with
//! is not yet right when they are found: first generously ([`find`], against the model
//! of the first search, which the extra object bent, or raylab's own picture), then
//! ([`confirm_shadows`]), after the fit ran again without the object and those pixels,
//! only the ones the new model does not explain (a second bug, such as a light that
//! never lights, darkens everything; the new model has it).

use rayon::prelude::*;

use super::regions::{Grid, PixelBox};
use super::relit::{Palette, is_relit, lit_as_raylab};
use super::shape_guess::{ShapeGuess, guess};
use crate::compare::catalogue::Kind;
use crate::compare::catalogue::MISS;
use crate::compare::fit::{FitState, OFF_LEVELS, Target};
use crate::compare::split::Components;

/// Regions smaller than this are no object.
const MIN_PIXELS: usize = 12;

/// An object found the stricter way ([`find`] with `start`) is at least this many
/// pixels across either way.
const MIN_ACROSS: u32 = 4;

/// An object raylab does not draw stands out: half its pixels differ by at least this
/// many 8-bit levels (a moved shadow or a reflection on a dull mirror differs less).
const OBJECT_LEVELS: f64 = 24.0;

/// An extra object looks like a scene object near it when that object's materials
/// give this share of its colours.
const LOOKS_LIKE_SHARE: f64 = 0.8;

/// Off pixels this close to an extra object are its own: its rim and dark side.
const RIM: usize = 3;

/// An edge the other picture has and raylab's lacks: this many 8-bit levels more.
const EDGE_LEVELS: f64 = 8.0;

/// At least this share of the outline (where raylab sees one surface across) must be
/// such an edge...
const MIN_EDGE_SHARE: f64 = 0.5;

/// ...over at least this many pixel pairs.
const MIN_EDGE_PAIRS: usize = 6;

/// Across raylab's outline, the other picture has no edge where its two pixels differ
/// by less than this many levels...
const CONTINUED_LEVELS: f64 = 4.0;

/// ...and a region where this share of the places its outline crosses raylab's are
/// such a continuation is a surface of raylab's reaching further (an outline moved),
/// not an object of its own.
const MAX_CONTINUED: f64 = 0.25;

/// A pixel's colour is a lighting of raylab's surface within this squared interval
/// error (three 8-bit levels).
const RELIT_TOLERANCE: f64 = (3.0 / 255.0) * (3.0 / 255.0);

/// An object the other picture draws where raylab sees something else.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtraObject {
    /// The pixels it takes out of the fit: its own, the pixels around them, and its
    /// reflections on mirrors elsewhere; ascending.
    pub pixels: Vec<u32>,
    /// The pixels of the shadow it casts (and its reflections) where they touch it
    /// ([`confirm_shadows`]); ascending.
    pub shadow: Vec<u32>,
    /// The bounding box of its own pixels.
    pub bbox: PixelBox,
    /// What its outline looks like.
    pub shape: ShapeGuess,
    /// The scene objects raylab sees where it is (`None`: the background), ascending.
    pub behind: Vec<Option<usize>>,
    /// The share of its outline that is an edge raylab's picture lacks.
    pub edge_share: f64,
    /// A scene object near it whose materials, lit, give its colours: it may be that
    /// object drawn larger or elsewhere.
    pub looks_like: Option<usize>,
}

/// The scene object within the size of `own`'s box of it whose materials, lit, give the
/// colours of most of `own` (at least [`LOOKS_LIKE_SHARE`]), if one does.
fn looks_like(
    components: &Components,
    palette: &Palette,
    target: &Target,
    own: &[u32],
) -> Option<usize> {
    let grid = Grid {
        width: components.width,
        height: components.height,
    };
    let bbox = PixelBox::of(own, grid.width)?;
    let reach = i64::from((bbox.x1 - bbox.x0).max(bbox.y1 - bbox.y0) + 1);
    let mut near: Vec<usize> = Vec::new();
    for y in i64::from(bbox.y0) - reach..=i64::from(bbox.y1) + reach {
        for x in i64::from(bbox.x0) - reach..=i64::from(bbox.x1) + reach {
            let label = grid.at(x, y).map_or(MISS, |p| components.object_label(p));
            if label != MISS && !near.contains(&(label as usize)) {
                near.push(label as usize);
            }
        }
    }
    // A few hundred pixels tell as well as all of them.
    let step = own.len().div_ceil(256);
    let sample: Vec<usize> = own.iter().step_by(step).map(|&p| p as usize).collect();
    near.into_iter()
        .map(|object| {
            let alike = sample
                .iter()
                .filter(|&&p| palette.lights_like(object, target, p, RELIT_TOLERANCE))
                .count();
            (object, alike as f64 / sample.len() as f64)
        })
        .filter(|&(_, share)| share >= LOOKS_LIKE_SHARE)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(object, _)| object)
}

/// The median difference of the pixels of `region` in 8-bit levels (the length of the
/// three channels' distances from their bytes).
fn median_levels(region: &[u32], state: &FitState) -> f64 {
    let mut levels: Vec<f64> = region
        .iter()
        .map(|&p| state.error[p as usize].sqrt() * 255.0)
        .collect();
    levels.sort_by(f64::total_cmp);
    levels[levels.len() / 2]
}

/// Whether raylab's surface at `p` is a mirror: most of the pixel is its reflection.
fn on_mirror(components: &Components, p: usize) -> bool {
    let reflected: f64 = components
        .pixel(p)
        .iter()
        .filter(|e| components.space.decode(e.channel).0 == Kind::Reflection)
        .map(|e| e.value.iter().map(|&v| f64::from(v)).sum::<f64>())
        .sum();
    reflected > 0.5 * components.beauty[p].iter().sum::<f64>()
}

/// Whether a spot light's cone bugs change pixel `p`: the cone's edge may lie elsewhere
/// in the other picture.
fn in_spot_reach(components: &Components, p: usize) -> bool {
    components
        .pixel(p)
        .iter()
        .any(|e| matches!(components.space.decode(e.channel).0, Kind::Spot(..)))
}

/// What the other picture does along a region's outline.
struct Outline {
    /// Pixel pairs across it where raylab sees one surface on both sides.
    one_surface: usize,
    /// Of those, where the other picture has an edge raylab's lacks.
    new_edges: usize,
    /// Pixel pairs across it where raylab's picture has an outline (two surfaces).
    crossing: usize,
    /// Of those, where the other picture has none: a surface of raylab's continues
    /// into the region.
    continued: usize,
}

impl Outline {
    /// The share of the outline (where raylab sees one surface) that is a new edge.
    fn edge_share(&self) -> f64 {
        self.new_edges as f64 / self.one_surface.max(1) as f64
    }

    /// Whether the region looks like an object's: sharp where raylab's picture is
    /// smooth, and not a surface of raylab's reaching further (an outline moved).
    fn is_an_object(&self) -> bool {
        // A moved outline's sliver crosses raylab's outline along about half of its
        // own; an object lying across a few pixels of another's edge does not.
        let crosses_much = self.crossing >= MIN_EDGE_PAIRS
            && self.crossing as f64 >= MAX_CONTINUED * self.one_surface as f64;
        self.one_surface >= MIN_EDGE_PAIRS
            && self.edge_share() >= MIN_EDGE_SHARE
            && (!crosses_much || (self.continued as f64) < MAX_CONTINUED * self.crossing as f64)
    }
}

/// The pixel pairs across the outline of `region` (ascending).
fn outline(components: &Components, target: &Target, grid: Grid, region: &[u32]) -> Outline {
    let inside = |p: usize| region.binary_search(&(p as u32)).is_ok();
    let levels = |a: [f64; 3], b: [f64; 3]| {
        (0..3)
            .map(|c| (a[c].clamp(0.0, 1.0) - b[c].clamp(0.0, 1.0)).abs())
            .fold(0.0, f64::max)
            * 255.0
    };
    let mut outline = Outline {
        one_surface: 0,
        new_edges: 0,
        crossing: 0,
        continued: 0,
    };
    for p in region.iter().map(|&p| p as usize) {
        for n in grid.beside(p).filter(|&n| !inside(n)) {
            if components.mixed[p] || components.mixed[n] {
                continue;
            }
            let theirs = levels(target.middle[p], target.middle[n]);
            let ours = levels(components.beauty[p], components.beauty[n]);
            if components.object_label(p) == components.object_label(n) {
                outline.one_surface += 1;
                outline.new_edges += usize::from(theirs - ours >= EDGE_LEVELS);
            } else {
                outline.crossing += 1;
                outline.continued += usize::from(theirs < CONTINUED_LEVELS);
            }
        }
    }
    outline
}

/// The objects the other picture draws and raylab does not, after a search left
/// `state`; the strongest first.
///
/// With `start` (raylab's own picture against the target), the evidence is read the
/// stricter way instead: a pixel off both after the search and in raylab's own picture,
/// that no switching of raylab's lights gives ([`lit_as_raylab`]) and that is not
/// raylab's own colour with lights taken away. For scenes of several coloured lights,
/// where every colour is some lighting, and where the first search bent a factor of
/// the whole picture towards the object (leaving every pixel a little off).
#[must_use]
pub fn find(
    components: &Components,
    palette: &Palette,
    target: &Target,
    state: &FitState,
    start: Option<&FitState>,
) -> Vec<ExtraObject> {
    let grid = Grid {
        width: components.width,
        height: components.height,
    };
    let off = (OFF_LEVELS / 255.0).powi(2);
    let evidence: Vec<bool> = (0..state.error.len())
        .into_par_iter()
        .map(|p| match start {
            None => {
                state.error[p] >= off
                    && !is_relit(components, palette, target, p, RELIT_TOLERANCE)
                    && !shadow_like(components, target, state.model[p], p)
            }
            Some(start) => {
                state.error[p] >= off
                    && start.error[p] >= off
                    && !lit_as_raylab(components, target, p, RELIT_TOLERANCE)
                    && !shadow_like(components, target, start.model[p], p)
                    // Where a spot's cone reaches, a wider cone lights the surface
                    // brighter, with any strength: the wider test there.
                    && !(in_spot_reach(components, p)
                        && (0..3).all(|c| target.middle[p][c] >= start.model[p][c])
                        && is_relit(components, palette, target, p, RELIT_TOLERANCE))
            }
        })
        .collect();
    let measured = start.unwrap_or(state);
    // (region, edge share, on a mirror, its error)
    let mut candidates = Vec::new();
    for region in grid.regions(&evidence) {
        if region.len() < MIN_PIXELS {
            continue;
        }
        let outline = outline(components, target, grid, &region);
        if !outline.is_an_object() || median_levels(&region, measured) < OBJECT_LEVELS {
            continue;
        }
        // Read the stricter way, a region must also be an object's size across: a
        // sliver along an outline is that outline drawn elsewhere.
        if start.is_some()
            && PixelBox::of(&region, grid.width)
                .is_none_or(|b| b.x1 - b.x0 + 1 < MIN_ACROSS || b.y1 - b.y0 + 1 < MIN_ACROSS)
        {
            continue;
        }
        let mirrored = region
            .iter()
            .filter(|&&p| on_mirror(components, p as usize))
            .count();
        let error: f64 = region.iter().map(|&p| state.error[p as usize]).sum();
        candidates.push((
            region.clone(),
            outline.edge_share(),
            2 * mirrored > region.len(),
            error,
        ));
    }
    // The strongest is seen directly (a reflection is dimmed by its mirror); other
    // regions on mirrors are its reflections, not objects of their own.
    candidates.sort_by(|a, b| b.3.total_cmp(&a.3));
    let mut reflections = Vec::new();
    let mut direct = Vec::new();
    for (index, (region, share, mirrored, _)) in candidates.into_iter().enumerate() {
        if index > 0 && mirrored {
            reflections.extend(region);
        } else {
            direct.push((region, share));
        }
    }
    let mut found: Vec<ExtraObject> = direct
        .into_iter()
        .map(|(region, edge_share)| {
            let own = grid.filled(&region);
            let xy: Vec<(i64, i64)> = own.iter().map(|&p| grid.xy(p as usize)).collect();
            let mut behind: Vec<Option<usize>> = own
                .iter()
                .map(|&p| components.object_label(p as usize))
                .map(|l| (l != MISS).then_some(l as usize))
                .collect();
            behind.sort_unstable();
            behind.dedup();
            // The pixels around it: where its edge and raylab's picture mix, and its
            // dark side, which a lighting of what lies behind can mimic.
            let mut pixels = own.clone();
            for _ in 0..RIM {
                pixels = grid.grown(&pixels);
            }
            pixels.retain(|&p| state.error[p as usize] >= off || own.binary_search(&p).is_ok());
            ExtraObject {
                looks_like: looks_like(components, palette, target, &own),
                shadow: Vec::new(),
                pixels,
                bbox: PixelBox::of(&own, grid.width).expect("a region has pixels"),
                shape: guess(&xy),
                behind,
                edge_share,
            }
        })
        .collect();
    if let Some(strongest) = found.first_mut() {
        strongest.pixels.extend(reflections);
        strongest.pixels.sort_unstable();
        strongest.pixels.dedup();
    }
    find_shadows(&mut found, components, palette, target, &state.model);
    found
}

impl ExtraObject {
    /// All the pixels it takes out of the fit: its own and its shadow's.
    #[must_use]
    pub fn claimed(&self) -> Vec<u32> {
        let mut all = [self.pixels.as_slice(), &self.shadow].concat();
        all.sort_unstable();
        all.dedup();
        all
    }
}

/// Whether the other picture at `p` is `model`'s colour there with the light of one or
/// more lights taken away: a shadow.
fn shadow_like(components: &Components, target: &Target, model: [f64; 3], p: usize) -> bool {
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
fn find_shadows(
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
