//! Whether a pixel of the other picture could be raylab's surface there, lit otherwise:
//! some non-negative mix of the pixel's own term colours (its ambient, each light's
//! diffuse and specular, what each light would add where it is shadowed, its mirror
//! and glass images, the background) and of its material's colours under each light
//! and of the surfaces just around it (`ka` ambient, `kd` and `ks` times each light's
//! colour: a light raylab's surface does not get there may reach it in the other
//! picture, and an outline a pixel or two off shows a neighbour), and what raylab shows there
//! without each object the pixel sees (what lies behind). Any lighting bug, a light missing
//! or too strong, a shadow gained or lost, a highlight elsewhere, only mixes those, so
//! its pixels pass; an object raylab does not draw shows colours of its own, which
//! usually do not.
//!
//! In colour space the mix is a cone spanned by a handful of vectors; the nearest point
//! of a cone in three dimensions lies on a face spanned by at most three of them
//! (Carathéodory), so every set of one to three vectors is tried.

use glam::{DMat3, DVec3};

use crate::compare::catalogue::Kind;
use crate::compare::catalogue::MISS;
use crate::compare::fit::Target;
use crate::compare::split::Components;
use crate::scene::Material;
use crate::trace::World;

/// Two colours this close in direction (the cosine of their angle) are one for the
/// cone.
const SAME_DIRECTION: f64 = 0.9995;

/// The palettes of the surfaces this many pixels around a pixel count as its own.
const NEIGHBOURS: i64 = 3;

/// The colours each scene object's materials take under each light, as directions.
#[derive(Clone, Debug)]
pub struct Palette {
    per_object: Vec<Vec<DVec3>>,
}

impl Palette {
    /// The palette of the first `objects` scene objects of `world` (a group's or a CSG
    /// node's materials all count).
    #[must_use]
    pub fn new(world: &World, objects: usize) -> Self {
        let mut per_object = vec![Vec::new(); objects];
        let strengths: Vec<DVec3> = world.lights.iter().map(|l| l.strength()).collect();
        let mut add = |o: usize, material: &Material| {
            let colours: &mut Vec<DVec3> = &mut per_object[o];
            colours.push(material.ambient * world.ambient);
            for &strength in &strengths {
                colours.push(material.diffuse * strength);
                colours.push(material.specular * strength);
            }
        };
        for (index, object) in world.objects.iter().enumerate() {
            let o = world.scene_object(index);
            if o >= objects {
                continue;
            }
            add(o, &world.materials[object.material]);
            if let Some(tree) = &object.csg {
                for leaf in &tree.leaves {
                    add(o, &world.materials[leaf.material]);
                }
            }
        }
        Self { per_object }
    }
}

/// The colours of the cone at pixel `p`: first its term colours, summed over objects
/// (ambient, reflection, transmission, background, then per light its diffuse, specular
/// and shadowed light) and its own surface's palette; then what lies behind each object
/// it sees (as raylab shows it without, and the palette of the surface behind the
/// first) and the palettes of the surfaces within [`NEIGHBOURS`] pixels.
fn cone_colours(components: &Components, palette: &Palette, p: usize) -> (Vec<DVec3>, Vec<DVec3>) {
    let lights = components.space.lights;
    let mut own = vec![DVec3::ZERO; 4 + 3 * lights];
    // What lies behind each object the pixel sees, as raylab would show it without.
    let mut missing: MissingByObject = Vec::new();
    for entry in components.pixel(p) {
        let value = DVec3::from_array(entry.value.map(f64::from));
        let slot = match components.space.decode(entry.channel) {
            (Kind::Ambient, _) => 0,
            (Kind::Reflection, _) => 1,
            (Kind::Transmission, _) => 2,
            (Kind::Background, _) => 3,
            (Kind::Diffuse(l), _) => 4 + l,
            (Kind::Specular(l), _) => 4 + lights + l,
            (Kind::Shadow(l), _) => 4 + 2 * lights + l,
            (kind @ (Kind::Missing(_) | Kind::NodeMissing), Some(object)) => {
                add_missing(&mut missing, kind, object, value);
                continue;
            }
            _ => continue,
        };
        own[slot] += value;
    }
    let label = components.object_label(p);
    if label != MISS {
        own.extend(&palette.per_object[label as usize]);
    }
    let beauty = DVec3::from_array(components.beauty[p]);
    let mut more: Vec<DVec3> = missing
        .into_iter()
        .map(|(_, change)| beauty + change)
        .collect();
    let behind = components.behind[p];
    if behind != MISS {
        more.extend(&palette.per_object[behind as usize]);
    }
    // The surfaces around the pixel, too: where an outline moved a little, or an
    // object is gone, the other picture shows one of those.
    let (w, h) = (i64::from(components.width), i64::from(components.height));
    let (x, y) = ((p as i64) % w, (p as i64) / w);
    let mut labels: Vec<u32> = vec![label];
    for ny in (y - NEIGHBOURS).max(0)..=(y + NEIGHBOURS).min(h - 1) {
        for nx in (x - NEIGHBOURS).max(0)..=(x + NEIGHBOURS).min(w - 1) {
            let label = components.object_label((ny * w + nx) as usize);
            if label != MISS && !labels.contains(&label) {
                labels.push(label);
                more.extend(&palette.per_object[label as usize]);
            }
        }
    }
    (own, more)
}

/// What raylab's picture changes by at a pixel without each object it sees, summed by
/// object: a leaf's and an inner node's slots are numbered apart.
type MissingByObject = Vec<((usize, bool), DVec3)>;

/// Adds a missing-part channel's `value` (of `kind`, on slot `object`) to its object's
/// sum in `missing`.
fn add_missing(missing: &mut MissingByObject, kind: Kind, object: usize, value: DVec3) {
    let object = (object, kind == Kind::NodeMissing);
    match missing.iter_mut().find(|(o, _)| *o == object) {
        Some((_, sum)) => *sum += value,
        None => missing.push((object, value)),
    }
}

/// One unit vector per direction of `colours` (none for black).
fn directions(colours: impl IntoIterator<Item = DVec3>) -> Vec<DVec3> {
    let mut directions: Vec<DVec3> = Vec::new();
    for c in colours.into_iter().filter(|c| c.length_squared() > 1e-12) {
        let d = c.normalize();
        if directions.iter().all(|o| o.dot(d) < SAME_DIRECTION) {
            directions.push(d);
        }
    }
    directions
}

/// The least-squares non-negative weights of `vectors` (one to three) for `target`
/// over the channels `channels` weighs (1: used, 0: clipped, any value fits), or
/// `None` where they are dependent there or a weight would be negative.
fn non_negative_fit(vectors: &[DVec3], target: DVec3, channels: DVec3) -> Option<DVec3> {
    // Normal equations G w = b with G the (weighted) Gram matrix of the vectors.
    let n = vectors.len();
    let dot = |a: DVec3, b: DVec3| (a * channels).dot(b);
    let mut gram = DMat3::IDENTITY;
    let mut b = DVec3::ZERO;
    for i in 0..n {
        b[i] = dot(vectors[i], target);
        for j in 0..n {
            gram.col_mut(j)[i] = dot(vectors[i], vectors[j]);
        }
    }
    if gram.determinant().abs() < 1e-14 {
        return None;
    }
    let w = gram.inverse() * b;
    (0..n).all(|i| w[i] >= 0.0).then_some(w)
}

/// The squared distance of `colour` outside the pixel's intervals.
fn outside(target: &Target, p: usize, colour: DVec3) -> f64 {
    target.pixel_error(p, &colour.to_array())
}

/// Whether the other picture at `p` is within `tolerance` (a squared interval error)
/// of some lighting of raylab's surface there.
#[must_use]
pub fn is_relit(
    components: &Components,
    palette: &Palette,
    target: &Target,
    p: usize,
    tolerance: f64,
) -> bool {
    // The pixel's own surface first: most pixels a lighting bug changes pass there.
    let (own, more) = cone_colours(components, palette, p);
    let own = directions(own);
    in_cone(&own, target, p, tolerance)
        || (!more.is_empty()
            && in_cone(
                &directions(own.into_iter().chain(more)),
                target,
                p,
                tolerance,
            ))
}

/// Lights beyond this many are tried one at a time in [`lit_as_raylab`].
const ALL_STATES_UP_TO: usize = 4;

/// Whether the other picture at `p` is within `tolerance` of raylab's own surface there
/// with each light at raylab's strength, switched off, as shadowed, or unshadowed (a
/// shadow gained or lost), or of raylab's picture without one of the objects the pixel
/// sees. Stricter than [`is_relit`], which lets every light take any strength: in a
/// scene of several coloured lights that cone holds nearly every colour, an object
/// raylab does not draw included.
#[must_use]
pub fn lit_as_raylab(components: &Components, target: &Target, p: usize, tolerance: f64) -> bool {
    let space = components.space;
    let beauty = DVec3::from_array(components.beauty[p]);
    let mut shadowed = vec![DVec3::ZERO; space.lights];
    let mut unshadowed_extra = vec![DVec3::ZERO; space.lights];
    let mut missing: MissingByObject = Vec::new();
    for entry in components.pixel(p) {
        let value = DVec3::from_array(entry.value.map(f64::from));
        match space.decode(entry.channel) {
            (Kind::Diffuse(l) | Kind::Specular(l), _) => shadowed[l] += value,
            (Kind::Shadow(l), _) => unshadowed_extra[l] += value,
            (kind @ (Kind::Missing(_) | Kind::NodeMissing), Some(object)) => {
                add_missing(&mut missing, kind, object, value);
            }
            _ => {}
        }
    }
    if missing
        .iter()
        .any(|&(_, change)| outside(target, p, beauty + change) < tolerance)
    {
        return true;
    }
    let base = beauty - shadowed.iter().copied().sum::<DVec3>();
    // Each light's three states: off, as raylab shadows it, unshadowed.
    let state = |l: usize, s: usize| match s {
        0 => DVec3::ZERO,
        1 => shadowed[l],
        _ => shadowed[l] + unshadowed_extra[l],
    };
    let lights = space.lights;
    if lights <= ALL_STATES_UP_TO {
        (0..3usize.pow(lights as u32)).any(|code| {
            let colour = (0..lights).fold(base, |sum, l| {
                sum + state(l, code / 3usize.pow(l as u32) % 3)
            });
            outside(target, p, colour) < tolerance
        })
    } else {
        (0..lights).any(|l| {
            (0..3).any(|s| outside(target, p, beauty - shadowed[l] + state(l, s)) < tolerance)
        })
    }
}

impl Palette {
    /// Whether the other picture at `p` is within `tolerance` of some lighting of scene
    /// object `object`'s materials.
    #[must_use]
    pub fn lights_like(&self, object: usize, target: &Target, p: usize, tolerance: f64) -> bool {
        let colours = directions(self.per_object[object].iter().copied());
        in_cone(&colours, target, p, tolerance)
    }
}

/// Whether the other picture at `p` is within `tolerance` of a non-negative mix of
/// `colours` (unit vectors).
fn in_cone(colours: &[DVec3], target: &Target, p: usize, tolerance: f64) -> bool {
    if outside(target, p, DVec3::ZERO) < tolerance {
        return true; // black: every light off
    }
    let goal = DVec3::from_array(target.middle[p]);
    let channels = DVec3::from_array(target.weight[p]);
    if channels == DVec3::ZERO {
        // White, clipped: any colour with all three parts, made bright enough.
        return colours.iter().any(|c| c.min_element() > 0.0);
    }
    let n = colours.len();
    let fits = |set: &[DVec3]| {
        non_negative_fit(set, goal, channels).is_some_and(|w| {
            let mix: DVec3 = set.iter().enumerate().map(|(i, v)| w[i] * *v).sum();
            outside(target, p, mix) < tolerance
        })
    };
    // One colour, then two, then three: the cheaper faces first.
    (0..n).any(|i| fits(&[colours[i]]))
        || (0..n).any(|i| (i + 1..n).any(|j| fits(&[colours[i], colours[j]])))
        || (0..n).any(|i| {
            (i + 1..n).any(|j| (j + 1..n).any(|k| fits(&[colours[i], colours[j], colours[k]])))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grey_cone_holds_greys_not_gold() {
        let grey = [DVec3::splat(0.2), DVec3::splat(0.5)];
        let all = DVec3::ONE;
        assert!(non_negative_fit(&grey[..1], DVec3::splat(0.7), all).is_some());
        let w = non_negative_fit(&grey[..1], DVec3::new(0.6, 0.45, 0.1), all).unwrap();
        let gold = DVec3::new(0.6, 0.45, 0.1);
        assert!((w[0] * grey[0] - gold).abs().max_element() > 0.1);
        // Two dependent vectors are no face of the cone.
        assert!(non_negative_fit(&grey, DVec3::splat(0.7), all).is_none());
    }

    #[test]
    fn red_and_white_mix_into_pink_but_not_into_blue() {
        let (red, white) = (DVec3::new(0.7, 0.1, 0.1), DVec3::ONE);
        let pink = 0.5 * red + 0.3 * white;
        let w = non_negative_fit(&[red, white], pink, DVec3::ONE).unwrap();
        assert!((w[0] - 0.5).abs() < 1e-9 && (w[1] - 0.3).abs() < 1e-9);
        // Blue needs a negative weight of red.
        let blue = DVec3::new(0.1, 0.3, 0.9);
        assert!(non_negative_fit(&[red, white], blue, DVec3::ONE).is_none());
        // With red clipped, gold light on a gold surface fits by green and blue alone.
        let gold = DVec3::new(0.6, 0.45, 0.1);
        let clipped = DVec3::new(0.0, 1.0, 1.0);
        let w = non_negative_fit(&[gold], DVec3::new(1.0, 0.9, 0.2), clipped).unwrap();
        assert!((w[0] - 2.0).abs() < 1e-9);
    }
}
