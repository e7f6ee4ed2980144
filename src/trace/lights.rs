//! Lights in the form the shader uses: unit directions, cosines precomputed, and the
//! light's contribution at a point as a [`LightSample`].

use glam::DVec3;

use crate::scene::Light;

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
        /// Cosine of the half-angle.
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
                cos_angle: angle_deg.to_radians().cos(),
                strength,
            },
            Light::Ambient { .. } => panic!("ambient lights are not sampled"),
        }
    }

    /// The light's contribution at `p`, or `None` where it cannot light `p` at all
    /// (outside a spot cone, or exactly at the light).
    #[must_use]
    pub fn sample(&self, p: DVec3) -> Option<LightSample> {
        match *self {
            WorldLight::Point { position, strength } => at_distance(p, position, strength),
            WorldLight::Directional { to_light, strength } => Some(LightSample {
                radiance: strength,
                to_light,
                light_position: None,
            }),
            WorldLight::Spot {
                position,
                axis,
                cos_angle,
                strength,
            } => {
                let sample = at_distance(p, position, strength)?;
                // The angle between the axis and (p - position) is at most the half-angle.
                ((-sample.to_light).dot(axis) >= cos_angle).then_some(sample)
            }
        }
    }
}

/// A point source at `position`: strength / d^2 along the unit direction to it.
fn at_distance(p: DVec3, position: DVec3, strength: DVec3) -> Option<LightSample> {
    let offset = position - p;
    let d2 = offset.length_squared();
    if d2 == 0.0 || !d2.is_finite() {
        return None;
    }
    Some(LightSample {
        radiance: strength / d2,
        to_light: offset / d2.sqrt(),
        light_position: Some(position),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
            colour: DVec3::ONE,
            intensity: 1.0,
        });
        assert!(light.sample(DVec3::new(0.99, 0.0, 0.0)).is_some());
        assert!(light.sample(DVec3::new(1.01, 0.0, 0.0)).is_none());
        assert!(
            light.sample(DVec3::new(0.0, 2.0, 0.0)).is_none(),
            "behind the spot"
        );
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
