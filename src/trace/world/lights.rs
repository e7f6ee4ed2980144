//! Lights in the form the shader uses: unit directions, cosines precomputed, and the
//! light's contribution at a point as a [`LightSample`].

use glam::DVec3;

use crate::scene::Light;
use crate::scene::transform::sin_cos_deg;

/// A non-ambient light, ready to sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WorldLight {
    /// Falls off as 1/d^2.
    Point {
        /// World position.
        position: DVec3,
        /// colour * intensity.
        strength: DVec3,
    },
    /// Constant strength from one direction.
    Directional {
        /// Unit vector towards the light (minus the travel direction).
        to_light: DVec3,
        /// colour * intensity.
        strength: DVec3,
    },
    /// A point light limited to a cone with a hard edge.
    Spot {
        /// World position.
        position: DVec3,
        /// Unit axis: the way the light travels.
        axis: DVec3,
        /// Cosine of the half-angle: exactly 0 at 90 degrees and -1 at 180 (every
        /// direction).
        cos_angle: f64,
        /// colour * intensity.
        strength: DVec3,
    },
}

/// What a light delivers to a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Strength arriving at the point, L_l(p), before visibility.
    pub radiance: DVec3,
    /// Unit vector from the point towards the light.
    pub to_light: DVec3,
    /// Where a shadow ray must reach: the light's position, or `None` for a light at
    /// infinity.
    pub light_position: Option<DVec3>,
    /// The squared distance the strength falls off with (1 for a light at infinity):
    /// `radiance` is [`falloff`] of the light's strength over this distance, bit for bit.
    pub distance_squared: f64,
}

impl WorldLight {
    /// Compiles a scene light. Ambient lights are summed by the world instead.
    ///
    /// # Panics
    /// On an ambient light.
    #[must_use]
    pub fn new(light: &Light) -> Self {
        let strength = light.strength();
        match *light {
            Light::Point { position, .. } => WorldLight::Point { position, strength },
            Light::Directional { direction, .. } => WorldLight::Directional {
                to_light: -direction.normalize(),
                strength,
            },
            Light::Spot {
                position,
                direction,
                angle_deg,
                ..
            } => WorldLight::Spot {
                position,
                axis: direction.normalize(),
                cos_angle: sin_cos_deg(angle_deg).1,
                strength,
            },
            Light::Ambient { .. } => panic!("ambient lights are not sampled"),
        }
    }

    /// The light's contribution at `p`, or `None` where it cannot light `p` at all
    /// (outside a spot cone, exactly at the light, or a light of zero strength, such as
    /// an imported legacy spot light without an angle): no shadow ray is cast for it.
    #[must_use]
    #[inline]
    pub fn sample(&self, p: DVec3) -> Option<LightSample> {
        if self.strength() == DVec3::ZERO {
            return None;
        }
        match *self {
            WorldLight::Point { position, strength } => at_distance(p, position, strength),
            WorldLight::Directional { to_light, strength } => Some(LightSample {
                // strength / 1, exactly.
                radiance: strength,
                to_light,
                light_position: None,
                distance_squared: 1.0,
            }),
            WorldLight::Spot {
                position,
                axis,
                cos_angle,
                strength,
            } => {
                let sample = at_distance(p, position, strength)?;
                // The angle between the axis and (p - position) is at most the half-angle.
                // The cosine of that angle is clamped, as rounding can take it just past
                // -1 straight behind the light, which a 180-degree spot still lights.
                let cos_to_p = (-sample.to_light).dot(axis).max(-1.0);
                (cos_to_p >= cos_angle).then_some(sample)
            }
        }
    }

    /// Everything about the light but its strength, bit for bit: two lights with the same
    /// placement sample every point alike up to their strengths.
    #[must_use]
    pub fn placement(&self) -> [u64; 8] {
        let mut key = [0u64; 8];
        let mut put = |at: usize, values: &[f64]| {
            for (i, v) in values.iter().enumerate() {
                key[at + i] = v.to_bits();
            }
        };
        match *self {
            WorldLight::Point { position, .. } => {
                put(1, &position.to_array());
                key[0] = 1;
            }
            WorldLight::Directional { to_light, .. } => {
                put(1, &to_light.to_array());
                key[0] = 2;
            }
            WorldLight::Spot {
                position,
                axis,
                cos_angle,
                ..
            } => {
                put(1, &position.to_array());
                put(4, &axis.to_array());
                put(7, &[cos_angle]);
                key[0] = 3;
            }
        }
        key
    }

    /// colour * intensity.
    #[must_use]
    pub fn strength(&self) -> DVec3 {
        match *self {
            WorldLight::Point { strength, .. }
            | WorldLight::Directional { strength, .. }
            | WorldLight::Spot { strength, .. } => strength,
        }
    }
}

/// `strength` arriving from `distance_squared` away: the one falloff of every sample.
#[inline]
#[must_use]
pub fn falloff(strength: DVec3, distance_squared: f64) -> DVec3 {
    strength / distance_squared
}

/// A point source at `position`: strength / d^2 along the unit direction to it.
fn at_distance(p: DVec3, position: DVec3, strength: DVec3) -> Option<LightSample> {
    let offset = position - p;
    let d2 = offset.length_squared();
    if d2 == 0.0 || !d2.is_finite() {
        return None;
    }
    Some(LightSample {
        radiance: falloff(strength, d2),
        to_light: offset / d2.sqrt(),
        light_position: Some(position),
        distance_squared: d2,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::LightSource;

    #[test]
    fn the_falloff_over_the_sampled_distance_is_the_sampled_radiance_bit_for_bit() {
        let strength = DVec3::new(0.7, 1.3, 2.9);
        let lights = [
            WorldLight::Point {
                position: DVec3::new(0.3, 4.1, -1.7),
                strength,
            },
            WorldLight::Directional {
                to_light: DVec3::new(0.6, 0.8, 0.0),
                strength,
            },
            WorldLight::Spot {
                position: DVec3::new(0.1, 5.0, 0.2),
                axis: -DVec3::Y,
                cos_angle: -1.0,
                strength,
            },
        ];
        for light in lights {
            for p in [DVec3::ZERO, DVec3::new(1.1, -0.3, 7.9), DVec3::splat(1e5)] {
                let sample = light.sample(p).unwrap();
                let again = falloff(light.strength(), sample.distance_squared);
                assert_eq!(
                    sample.radiance.to_array().map(f64::to_bits),
                    again.to_array().map(f64::to_bits)
                );
            }
        }
        let moved = WorldLight::Point {
            position: DVec3::new(0.3, 4.1, -1.6),
            strength,
        };
        let brighter = WorldLight::Point {
            position: DVec3::new(0.3, 4.1, -1.7),
            strength: strength * 2.0,
        };
        assert_eq!(lights[0].placement(), brighter.placement());
        assert_ne!(lights[0].placement(), moved.placement());
        assert_ne!(lights[0].placement(), lights[2].placement());
    }

    #[test]
    fn point_light_falls_off_with_distance_squared() {
        let light = WorldLight::Point {
            position: DVec3::new(0.0, 4.0, 0.0),
            strength: DVec3::splat(32.0),
        };
        let s = light.sample(DVec3::ZERO).unwrap();
        assert_eq!(s.radiance, DVec3::splat(2.0));
        assert_eq!(s.to_light, DVec3::Y);
    }

    #[test]
    fn spot_light_has_a_hard_edge_at_its_half_angle() {
        let light = WorldLight::new(&Light::Spot {
            position: DVec3::new(0.0, 1.0, 0.0),
            direction: DVec3::new(0.0, -3.0, 0.0),
            angle_deg: 45.0,
            source: LightSource::point(DVec3::ONE, 1.0),
        });
        assert!(light.sample(DVec3::new(0.99, 0.0, 0.0)).is_some());
        assert!(light.sample(DVec3::new(1.01, 0.0, 0.0)).is_none());
        assert!(
            light.sample(DVec3::new(0.0, 2.0, 0.0)).is_none(),
            "behind the spot"
        );
    }

    fn spot(angle_deg: f64) -> WorldLight {
        WorldLight::new(&Light::Spot {
            position: DVec3::ZERO,
            direction: DVec3::new(0.0, 2.0, 0.0),
            angle_deg,
            source: LightSource::point(DVec3::ONE, 1.0),
        })
    }

    #[test]
    fn wide_spot_lights_beyond_ninety_degrees_up_to_everything_at_180() {
        // 120 degrees from +y: below the light, points within 60 degrees of -y are dark.
        let (s, c) = (60f64.to_radians().sin(), 60f64.to_radians().cos());
        let wide = spot(120.0);
        assert!(wide.sample(DVec3::new(1.0, 0.0, 0.0)).is_some(), "sideways");
        assert!(wide.sample(DVec3::new(s * 1.01, -c, 0.0)).is_some());
        assert!(wide.sample(DVec3::new(s * 0.99, -c, 0.0)).is_none());
        assert!(wide.sample(DVec3::new(0.0, -1.0, 0.0)).is_none(), "behind");
        // 90 degrees: exactly sideways is on the edge and lit.
        assert!(spot(90.0).sample(DVec3::new(3.0, 0.0, 0.0)).is_some());
        assert!(spot(90.0).sample(DVec3::new(3.0, -1e-9, 0.0)).is_none());
        // 180 degrees: every direction, also straight behind and at awkward roundings.
        let all = spot(180.0);
        for p in [
            DVec3::new(0.0, -1.0, 0.0),
            DVec3::new(1e-300, -7.0, 0.0),
            DVec3::new(0.1, -0.3, 1e-17),
            DVec3::new(-5.0, 1.0, 2.0),
        ] {
            assert!(all.sample(p).is_some(), "{p}");
        }
    }

    #[test]
    fn a_light_of_zero_strength_reaches_nothing() {
        let dark = WorldLight::new(&Light::Spot {
            position: DVec3::ZERO,
            direction: DVec3::NEG_Y,
            angle_deg: 45.0,
            source: LightSource::point(DVec3::ONE, 0.0),
        });
        assert_eq!(dark.sample(DVec3::NEG_Y), None);
        let black = WorldLight::new(&Light::Point {
            position: DVec3::ZERO,
            source: LightSource::point(DVec3::ZERO, 3.0),
        });
        assert_eq!(black.sample(DVec3::X), None);
    }

    #[test]
    fn directional_light_points_against_its_travel() {
        let light = WorldLight::new(&Light::Directional {
            direction: DVec3::new(0.0, -2.0, 0.0),
            colour: DVec3::new(1.0, 0.5, 0.25),
            intensity: 2.0,
        });
        let s = light.sample(DVec3::splat(100.0)).unwrap();
        assert_eq!(s.to_light, DVec3::Y);
        assert_eq!(s.radiance, DVec3::new(2.0, 1.0, 0.5));
        assert_eq!(s.light_position, None);
    }
}
