//! The most a ray's whole subtree can add to the colour of its camera ray: the bound that
//! lets a render leave out a ray that cannot change a written byte (issue 50;
//! `render/pruned.rs` keeps the promise by tracing again every pixel it might have
//! changed).
//!
//! # The bound, and why it holds
//!
//! Every number here is per channel; every inequality below is channel by channel.
//!
//! **One hit's own colour.** At a hit on material m the shader adds (`lighting.rs`)
//! `ka * A + sum over lights l of vis_l * L_l(p) * (kd * n.l + ks * lobe)`, where A is the
//! sum of the ambient lights, vis_l in [0, 1], n.l <= 1 (only lights with n.l > 0 are
//! added), `lobe = max(0, r.v)^s <= 1` for unit r and v and s >= 0. L_l(p) is the light's
//! strength for a directional light, and strength / |p - centre|^2 for a point or spot
//! light (a sphere light is strength and direction of its centre). Every hit point p lies
//! on an object, inside its world box, so |p - centre| >= the distance from the centre to
//! the nearest box, d_l, and L_l(p) <= strength / d_l^2 (no bound where d_l is 0). With
//! every colour of the scene non-negative (the scene validation refuses negative colours
//! and intensities, and [`SubtreeBound::new`] checks again), `0 <= local_m <= Lm_m`,
//! where `Lm_m = ka A + sum_l Lmax_l (kd + ks)`. A miss adds the background, `0 <= bg`.
//!
//! **A ray's colour.** A ray that may still start k generations of rays below it
//! returns (`bounce_tree.rs`) `local + km * reflected + kt * transmitted` under `Add`, or
//! `(1 - km) * local + km * reflected + kt * transmitted` under `Blend` (km <= 1 there, so
//! the first term is in [0, local]); with `EachRay` that is clamped to [0, 1]. By
//! induction on k, its colour c satisfies `0 <= c <= R_k`, where
//!
//! ```text
//! R_0 = max(bg, max_m Lm'_m)
//! R_k = max(bg, max_m (Lm'_m + (km_m + kt_m) R_(k-1)))      (then min(1, .) with EachRay)
//! ```
//!
//! with `Lm'_m = Lm_m` (`Add`) or `(1 - km_m) Lm_m` (`Blend`). A ray at depth d of a
//! world of `max_depth` D may start D - d generations, so R_(D - d) bounds it.
//!
//! **What leaving a ray out changes.** A ray left out is folded back as if it had
//! returned black (its parent still blends with it: `Some(0)`, not "not cast"). Each fold
//! step `parent = f(local + km * reflected + kt * transmitted)`, with f the identity
//! (`Pixel`) or the clamp to [0, 1] (`EachRay`), is non-decreasing in each child's colour
//! and grows by at most `k * (change of the child)` when one child grows (f is monotone
//! and 1-Lipschitz). So raising a left-out ray from 0 to its true colour c in [0, R]
//! raises its camera ray's colour by between 0 and `w * R`, where w is the product of
//! the km and kt factors on the path from the camera ray down to it (its own included);
//! several rays left out add at most the sum of their bounds (raise them one at a time).
//! A pixel is the mean of its samples, so a sample's share of the pixel is 1/spp of
//! that. Hence: the full trace's pixel lies in `[pruned, pruned + sum of the bounds]`.
//!
//! **Rounding.** The tracer's arithmetic is the same in both traces but for the left-out
//! terms; its rounding is a relative 1e-12 at most for the depths allowed (every term is
//! non-negative, so nothing cancels). The bounds are inflated by a relative 1e-9 for the
//! lobe and n.l of directions that are unit only to rounding (the lobe takes that to the
//! power s), and the interval test in `render/pruned.rs` widens its ends by 1e-9 of the
//! values. A subtree that would have come out non-finite is assumed away, as everywhere
//! (the guard counts such samples, and a render with any is traced again in full).

use glam::DVec3;

use crate::scene::{ClampConvention, MirrorConvention};
use crate::trace::world::{World, WorldLight};

/// How far above 1 a dot product of directions that are unit only to rounding may come.
const UNIT_SLACK: f64 = 1e-9;

/// The most the subtree of a ray at each depth can return, for one world.
#[derive(Clone, Debug)]
pub struct SubtreeBound {
    /// `by_generations[k]`: the most a ray that may start k more generations returns.
    by_generations: Vec<DVec3>,
    max_depth: u32,
}

impl SubtreeBound {
    /// The bound for `world`'s beauty render, or `None` where none is proven: a negative
    /// colour (refused by the scene validation, but a world can be built without it), a
    /// `Blend` mirror above 1 (it would subtract from the local colour), or a bound that
    /// comes out infinite (a point light on an object's box, without the each-ray clamp).
    #[must_use]
    pub fn new(world: &World) -> Option<Self> {
        let non_negative = |c: DVec3| c.is_finite() && c.min_element() >= 0.0;
        let materials_ok = world.materials.iter().all(|m| {
            [m.ambient, m.diffuse, m.specular, m.mirror, m.transmission]
                .into_iter()
                .all(non_negative)
                && m.shininess >= 0.0
        });
        let lights_ok = world.lights.iter().all(|l| non_negative(l.strength()));
        if !(materials_ok
            && lights_ok
            && non_negative(world.ambient)
            && non_negative(world.background))
        {
            return None;
        }
        let conventions = world.conventions;
        let blend = conventions.mirror == MirrorConvention::Blend;
        if blend && world.materials.iter().any(|m| m.mirror.max_element() > 1.0) {
            return None;
        }
        let clamped = conventions.clamp == ClampConvention::EachRay;
        let lights: Vec<DVec3> = world
            .lights
            .iter()
            .map(|light| strongest_arrival(world, light))
            .collect();
        let n_dot_l = 1.0 + UNIT_SLACK;
        // (own colour bound, km + kt) per material.
        let materials: Vec<(DVec3, DVec3)> = world
            .materials
            .iter()
            .map(|m| {
                let lobe = (1.0 + UNIT_SLACK).powf(m.shininess);
                let per_light = m.diffuse * n_dot_l + m.specular * lobe;
                // A light without a bound lights nothing with kd = ks = 0 (no inf * 0).
                let lit: DVec3 = lights
                    .iter()
                    .map(|&l| {
                        DVec3::select(per_light.cmpeq(DVec3::ZERO), DVec3::ZERO, l * per_light)
                    })
                    .sum();
                let own = m.ambient * world.ambient + lit;
                let own = if blend {
                    (DVec3::ONE - m.mirror) * own
                } else {
                    own
                };
                (own, m.mirror + m.transmission)
            })
            .collect();
        // Each ray clamped returns at most 1, whatever its terms (an unbounded light too).
        let limit = |c: DVec3| {
            let c = c * (1.0 + UNIT_SLACK);
            if clamped {
                DVec3::select(c.cmplt(DVec3::ONE), c, DVec3::ONE)
            } else {
                c
            }
        };
        let mut by_generations = Vec::with_capacity(world.max_depth as usize + 1);
        let mut below = None;
        for _ in 0..=world.max_depth {
            let mut most = world.background;
            for &(own, weights) in &materials {
                let deeper = below.map_or(DVec3::ZERO, |r: DVec3| weights * r);
                most = most.max(own + deeper);
            }
            let most = limit(most);
            if !most.is_finite() {
                return None;
            }
            by_generations.push(most);
            below = Some(most);
        }
        Some(Self {
            by_generations,
            max_depth: world.max_depth,
        })
    }

    /// The most the ray at `depth` (0 = the camera ray) whose path weighs `weight` (the
    /// product of the km and kt factors from the camera ray down to it, its own
    /// included) can add to its camera ray's colour, with everything below it.
    #[inline]
    #[must_use]
    pub fn of(&self, weight: DVec3, depth: u32) -> DVec3 {
        let generations = self.max_depth.saturating_sub(depth) as usize;
        weight * self.by_generations[generations]
    }
}

/// The most light `light` can deliver to any point of `world`'s objects.
fn strongest_arrival(world: &World, light: &WorldLight) -> DVec3 {
    let strength = light.strength();
    let centre = match *light {
        WorldLight::Directional { .. } => return strength,
        WorldLight::Point { position, .. } | WorldLight::Spot { position, .. } => position,
    };
    if strength == DVec3::ZERO {
        return strength;
    }
    let nearest = world
        .objects
        .iter()
        .map(|object| {
            let (min, max) = (object.bounds.min, object.bounds.max);
            let outside = (min - centre).max(centre - max).max(DVec3::ZERO);
            // A box that came out NaN bounds nothing: as if the light were in it.
            let distance = outside.length();
            if distance.is_nan() { 0.0 } else { distance }
        })
        .fold(f64::INFINITY, f64::min);
    // Shrunk by a relative 1e-6 for the rounding of hit points near a box's face.
    let nearest = nearest * (1.0 - 1e-6);
    if nearest > 0.0 {
        strength / (nearest * nearest)
    } else {
        DVec3::INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Conventions, parse_scene};

    fn world(text: &str) -> World {
        World::new(&parse_scene(text).unwrap()).unwrap()
    }

    const MIRROR_PAIR: &str = r#"Scene(
        render: (max_depth: 3, background: (0.1, 0.2, 0.3)),
        materials: {
            "m": (ambient: (0.5, 0.5, 0.5), diffuse: (0.5, 0.0, 0.0), specular: (0.25, 0.0, 0.0),
                  mirror: (0.5, 0.5, 0.5), transmission: (0.25, 0.0, 0.0)),
        },
        lights: [
            Ambient(colour: (1.0, 1.0, 1.0)),
            Point(position: (0.0, 5.0, 0.0), colour: (1.0, 1.0, 1.0), intensity: 16.0),
        ],
        objects: [(shape: Sphere, material: "m")],
    )"#;

    #[test]
    fn the_bound_sums_the_generations_left_and_the_each_ray_clamp_caps_it() {
        let w = world(MIRROR_PAIR);
        let bound = SubtreeBound::new(&w).unwrap();
        // The sphere's box reaches y = 1 (padded a hair): the light is 4 away, so it
        // delivers at most 16 / 16 = 1. Own colour: red 0.5 + 0.75, green and blue 0.5.
        let r0 = bound.of(DVec3::ONE, 3);
        assert!(
            (r0 - DVec3::new(1.25, 0.5, 0.5)).abs().max_element() < 1e-3,
            "{r0}"
        );
        // One generation more: red 1.25 + 0.75 * 1.25, green 0.5 + 0.5 * 0.5.
        let r1 = bound.of(DVec3::ONE, 2);
        assert!(
            (r1 - DVec3::new(2.1875, 0.75, 0.75)).abs().max_element() < 1e-3,
            "{r1}"
        );
        assert!(r1.cmpge(r0).all(), "deeper rays can return no less");
        assert_eq!(
            bound.of(DVec3::splat(0.5), 2),
            r1 * 0.5,
            "scaled by the weight"
        );
        let mut clamped = w.clone();
        clamped.conventions = Conventions::COURSE;
        let capped = SubtreeBound::new(&clamped).unwrap();
        // Red is capped at 1 from the last generation on; green sums 0.5 (1 + 0.5 + ...).
        assert_eq!(capped.of(DVec3::ONE, 3).x, 1.0);
        let green = capped.of(DVec3::ONE, 0).y;
        assert!((green - 0.9375).abs() < 1e-6, "{green}");
    }

    #[test]
    fn no_bound_without_a_proof() {
        let mut w = world(MIRROR_PAIR);
        w.conventions.mirror = MirrorConvention::Blend;
        w.materials[0].mirror = DVec3::new(1.5, 0.5, 0.5);
        assert!(SubtreeBound::new(&w).is_none(), "a blend above 1 subtracts");
        let mut on_the_box = world(MIRROR_PAIR);
        on_the_box.lights[0] = WorldLight::Point {
            position: DVec3::new(0.0, 0.5, 0.0),
            strength: DVec3::ONE,
        };
        assert!(SubtreeBound::new(&on_the_box).is_none(), "unbounded 1/d^2");
        on_the_box.conventions.clamp = ClampConvention::EachRay;
        let clamped = SubtreeBound::new(&on_the_box).expect("each ray returns at most 1");
        assert_eq!(
            clamped.of(DVec3::splat(0.5), 1).x,
            0.5,
            "red: lit without bound"
        );
    }
}
