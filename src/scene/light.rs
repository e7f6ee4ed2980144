//! Lights: the four kinds of the contract, with the sphere lights' radius and samples.

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// A light. Strength is `colour * intensity`; point and spot lights fall off as 1/d^2.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Light {
    /// Adds `ka * colour * intensity` everywhere.
    Ambient {
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    /// A point light.
    Point {
        /// World position.
        position: DVec3,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
        /// Radius of the light's sphere; 0 (the default) is a point.
        #[serde(default, skip_serializing_if = "is_zero")]
        radius: f64,
        /// Shadow rays per shading point for a sphere light; default 1.
        #[serde(default = "default_samples", skip_serializing_if = "is_one")]
        samples: u32,
    },
    /// A light at infinity; `direction` is the way the light travels.
    Directional {
        /// The way the light travels (need not be unit length).
        direction: DVec3,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    /// A point light restricted to a cone with a hard edge.
    Spot {
        /// World position of the apex.
        position: DVec3,
        /// Axis of the cone: the way the light travels.
        direction: DVec3,
        /// Half-angle of the cone in degrees, in (0, 180]: 90 lights a half-space, 180
        /// every direction.
        angle_deg: f64,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        #[serde(default = "default_intensity")]
        intensity: f64,
        /// As for a point light: 0 (the default) is a point, more a sphere.
        #[serde(default, skip_serializing_if = "is_zero")]
        radius: f64,
        /// As for a point light: shadow rays per shading point; default 1.
        #[serde(default = "default_samples", skip_serializing_if = "is_one")]
        samples: u32,
    },
}

fn default_intensity() -> f64 {
    1.0
}

fn default_samples() -> u32 {
    1
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

fn is_one(value: &u32) -> bool {
    *value == 1
}

/// The four kinds of light, without their values: for menus, messages and importers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightKind {
    /// [`Light::Ambient`].
    Ambient,
    /// [`Light::Point`].
    Point,
    /// [`Light::Directional`].
    Directional,
    /// [`Light::Spot`].
    Spot,
}

impl LightKind {
    /// Every kind, in menu order.
    pub const ALL: [LightKind; 4] = [
        LightKind::Ambient,
        LightKind::Point,
        LightKind::Directional,
        LightKind::Spot,
    ];

    /// The kind's name, as in files: the variant name of [`Light`].
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LightKind::Ambient => "Ambient",
            LightKind::Point => "Point",
            LightKind::Directional => "Directional",
            LightKind::Spot => "Spot",
        }
    }
}

impl Light {
    /// Which kind of light this is.
    #[must_use]
    pub fn kind(&self) -> LightKind {
        match self {
            Light::Ambient { .. } => LightKind::Ambient,
            Light::Point { .. } => LightKind::Point,
            Light::Directional { .. } => LightKind::Directional,
            Light::Spot { .. } => LightKind::Spot,
        }
    }

    /// The kind's name, as in files and menus.
    #[must_use]
    pub fn kind_name(&self) -> &'static str {
        self.kind().name()
    }

    /// The light's colour, before `intensity`.
    #[must_use]
    pub fn colour(&self) -> DVec3 {
        self.colour_and_intensity().0
    }

    /// The multiplier of the light's colour.
    #[must_use]
    pub fn intensity(&self) -> f64 {
        self.colour_and_intensity().1
    }

    /// The two fields every kind of light has.
    fn colour_and_intensity(&self) -> (DVec3, f64) {
        match *self {
            Light::Ambient {
                colour, intensity, ..
            }
            | Light::Point {
                colour, intensity, ..
            }
            | Light::Directional {
                colour, intensity, ..
            }
            | Light::Spot {
                colour, intensity, ..
            } => (colour, intensity),
        }
    }

    /// For a Point or Spot light with a radius: the sphere's radius and the shadow rays
    /// per shading point. `None` for a point (radius 0) and for the other kinds.
    #[must_use]
    pub fn sphere(&self) -> Option<(f64, u32)> {
        match *self {
            Light::Point {
                radius, samples, ..
            }
            | Light::Spot {
                radius, samples, ..
            } if radius > 0.0 => Some((radius, samples)),
            _ => None,
        }
    }

    /// The light's colour times its intensity.
    #[must_use]
    pub fn strength(&self) -> DVec3 {
        self.colour() * self.intensity()
    }
}
