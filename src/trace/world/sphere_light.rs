//! Sphere lights (SCENE_FORMAT.md, "Sphere lights"): a Point or Spot light with a radius
//! is seen from a shading point as a disc through its centre, facing the point; its
//! visibility is the fraction of `samples` shadow rays, aimed at stratified points of
//! that disc, that reach it. Strength and direction stay the centre's.
//!
//! The points are an Owen-scrambled Sobol sequence (`sobol_burley`, as the pixel samples)
//! mapped to the disc by Shirley and Chiu's concentric map, which keeps the strata's
//! areas. The scramble is seeded by the shading point itself, so each pixel sample (its
//! own point on the surface) uses other light points and the progressive preview
//! converges to the soft shadow, while the same point always gets the same answer.

use glam::{DVec2, DVec3};
use sobol_burley::parts::{
    Int4, hash, hash_int4, owen_scramble_int4_rev, owen_scramble_rev, sobol_int4_rev,
};

/// A light's sphere: its radius and how many shadow rays each shading point casts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereLight {
    /// The sphere's radius (> 0).
    pub radius: f64,
    /// Shadow rays per shading point (1 to `MAX_LIGHT_SAMPLES`).
    pub samples: u32,
}

impl SphereLight {
    /// The disc this light shows a shading point at `p`: of radius `radius` through
    /// `centre`, perpendicular to the line from `p`. Worked out once for all of the
    /// point's shadow rays ([`LightDisc::point`]).
    #[must_use]
    pub fn disc_seen_from(&self, centre: DVec3, p: DVec3) -> LightDisc {
        let axis = (centre - p).normalize_or_zero();
        let (u, v) = if axis == DVec3::ZERO {
            (DVec3::X, DVec3::Y)
        } else {
            axis.any_orthonormal_pair()
        };
        LightDisc {
            centre,
            radius: self.radius,
            u,
            v,
        }
    }
}

/// What [`sobol_burley::sample_4d`]`(index, 0, seed)` works out from the seed alone,
/// worked out once for all of a shading point's shadow rays; the rest is that function's
/// own code, so the points are its points bit for bit (tested below).
#[derive(Clone, Copy, Debug)]
pub struct SobolScramble {
    /// The hash that shuffles the sample index.
    index: u32,
    /// The hashes that Owen-scramble each of the four dimensions of set 0.
    dimensions: Int4,
}

impl SobolScramble {
    /// The scramble of one shading point (its `seed`: [`shading_seed`]).
    #[must_use]
    pub fn new(seed: u32) -> Self {
        // As `sample_4d` with dimension set 0 (which XORs in 0).
        let seeds: Int4 = [seed.wrapping_mul(0x9c8f_2d3b); 4].into();
        let lanes: Int4 = [0x912f_69ba, 0x174f_18ab, 0x691e_72ca, 0xb40c_c1b8].into();
        Self {
            index: hash(seed ^ 0x79c6_8e4a),
            dimensions: hash_int4(seeds ^ lanes),
        }
    }

    /// The first two dimensions of sample `index`, in [0, 1).
    #[must_use]
    pub fn square_point(&self, index: u32) -> DVec2 {
        let shuffled = owen_scramble_rev(index.reverse_bits(), self.index);
        let sobol = sobol_int4_rev(shuffled, 0);
        let [x, y, _, _] = owen_scramble_int4_rev(sobol, self.dimensions)
            .reverse_bits()
            .to_f32_norm();
        DVec2::new(f64::from(x), f64::from(y))
    }
}

/// A sphere light's disc as one shading point sees it ([`SphereLight::disc_seen_from`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightDisc {
    centre: DVec3,
    radius: f64,
    /// Two unit vectors spanning the disc's plane, perpendicular to each other.
    u: DVec3,
    v: DVec3,
}

impl LightDisc {
    /// The point that shadow ray `index` of the shading point (its `scramble`:
    /// [`SobolScramble::new`] of its [`shading_seed`]) aims at.
    #[must_use]
    pub fn point(&self, index: u32, scramble: &SobolScramble) -> DVec3 {
        let on_disc = concentric_disc(scramble.square_point(index));
        self.centre + self.radius * (on_disc.x * self.u + on_disc.y * self.v)
    }
}

/// The scramble seed of the shadow rays from `p` to light `light`: from the point's bits,
/// so every shading point (and so every pixel sample) has its own strata.
#[must_use]
pub fn shading_seed(p: DVec3, light: usize) -> u32 {
    // FNV-1a over the coordinates' bits and the light's index.
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for word in p
        .to_array()
        .map(f64::to_bits)
        .into_iter()
        .chain([light as u64])
    {
        hash ^= word;
        hash = hash.wrapping_mul(0x0100_0000_01b3);
    }
    (hash ^ (hash >> 32)) as u32
}

/// Shirley and Chiu's concentric map of the unit square onto the unit disc: equal areas
/// go to equal areas, so stratified square points stay stratified on the disc.
#[must_use]
fn concentric_disc(square: DVec2) -> DVec2 {
    let a = 2.0 * square - DVec2::ONE;
    if a == DVec2::ZERO {
        return DVec2::ZERO;
    }
    let (r, theta) = if a.x.abs() > a.y.abs() {
        (a.x, std::f64::consts::FRAC_PI_4 * (a.y / a.x))
    } else {
        (
            a.y,
            std::f64::consts::FRAC_PI_2 - std::f64::consts::FRAC_PI_4 * (a.x / a.y),
        )
    };
    let (sin, cos) = theta.sin_cos();
    DVec2::new(r * cos, r * sin)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn disc_points_lie_on_the_disc_facing_the_point_and_cover_it_evenly() {
        let light = SphereLight {
            radius: 0.5,
            samples: 64,
        };
        let (centre, p) = (DVec3::new(1.0, 4.0, -2.0), DVec3::new(0.0, 0.0, 0.0));
        let axis = (centre - p).normalize();
        let seed = shading_seed(p, 0);
        let disc = light.disc_seen_from(centre, p);
        let scramble = SobolScramble::new(seed);
        let points: Vec<DVec3> = (0..64).map(|i| disc.point(i, &scramble)).collect();
        for q in &points {
            assert!((*q - centre).dot(axis).abs() < 1e-12, "in the disc's plane");
            assert!((*q - centre).length() <= 0.5 + 1e-12, "inside the disc");
        }
        // Stratified: each quarter of the disc (by angle) gets 16 of 64 points, and the
        // inner disc of half the area about half of them.
        let (u, _) = axis.any_orthonormal_pair();
        let v = axis.cross(u);
        let mut quarters = [0; 4];
        let mut inner = 0;
        for q in &points {
            let d = *q - centre;
            let angle = d.dot(v).atan2(d.dot(u)).rem_euclid(std::f64::consts::TAU);
            quarters[(angle / std::f64::consts::FRAC_PI_2) as usize % 4] += 1;
            inner += usize::from(d.length() < 0.5 / 2f64.sqrt());
        }
        assert!(
            quarters.iter().all(|&n| (12..=20).contains(&n)),
            "{quarters:?}"
        );
        assert!(
            (26..=38).contains(&inner),
            "{inner} of 64 in the inner half"
        );
    }

    #[test]
    fn the_scrambled_points_are_sobol_burleys_own() {
        let seeds = (0..4000u32)
            .map(|i| i.wrapping_mul(0x9e37_79b9))
            .chain([0, u32::MAX]);
        for seed in seeds {
            let scramble = SobolScramble::new(seed);
            for index in 0..64 {
                let [x, y, _, _] = sobol_burley::sample_4d(index, 0, seed);
                let expected = DVec2::new(f64::from(x), f64::from(y));
                assert_eq!(
                    scramble.square_point(index),
                    expected,
                    "seed {seed} index {index}"
                );
            }
        }
    }

    #[test]
    fn each_shading_point_has_its_own_seed() {
        let a = shading_seed(DVec3::new(0.1, 0.2, 0.3), 0);
        assert_ne!(
            a,
            shading_seed(DVec3::new(0.1, 0.2, 0.300_000_000_000_000_1), 0)
        );
        assert_ne!(a, shading_seed(DVec3::new(0.1, 0.2, 0.3), 1));
        assert_eq!(a, shading_seed(DVec3::new(0.1, 0.2, 0.3), 0));
    }

    #[test]
    fn the_concentric_map_keeps_the_square_centre_and_corners_on_the_disc() {
        assert_eq!(concentric_disc(DVec2::splat(0.5)), DVec2::ZERO);
        for corner in [DVec2::ZERO, DVec2::ONE, DVec2::new(0.0, 1.0)] {
            assert!((concentric_disc(corner).length() - 1.0).abs() < 1e-12);
        }
    }
}
