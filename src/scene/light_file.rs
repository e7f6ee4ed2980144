//! A light as files hold it: each kind's fields side by side, as the contract
//! (`SCENE_FORMAT.md`) writes them. [`Light`] reads and writes through this form, so its
//! [`LightSource`] changes nothing in the files. `#[serde(flatten)]` cannot do this: RON
//! writes a flattened struct as a map, and flatten does not work with
//! `deny_unknown_fields`. The impls are here, not derived on [`Light`] with
//! `#[serde(from, into)]`, so that `light` does not import this module back.

use glam::DVec3;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::light::{Light, LightSource};

impl Serialize for Light {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        LightFile::from(self.clone()).serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Light {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        LightFile::deserialize(deserializer).map(Light::from)
    }
}

/// [`Light`] in the file's layout; named `Light` for serde so messages name the type as
/// before.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Light", deny_unknown_fields)]
enum LightFile {
    Ambient {
        colour: DVec3,
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    Point {
        position: DVec3,
        colour: DVec3,
        #[serde(default = "default_intensity")]
        intensity: f64,
        #[serde(default, skip_serializing_if = "is_zero")]
        radius: f64,
        #[serde(default = "default_samples", skip_serializing_if = "is_one")]
        samples: u32,
    },
    Directional {
        direction: DVec3,
        colour: DVec3,
        #[serde(default = "default_intensity")]
        intensity: f64,
    },
    Spot {
        position: DVec3,
        direction: DVec3,
        angle_deg: f64,
        colour: DVec3,
        #[serde(default = "default_intensity")]
        intensity: f64,
        #[serde(default, skip_serializing_if = "is_zero")]
        radius: f64,
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

impl From<LightFile> for Light {
    fn from(file: LightFile) -> Self {
        match file {
            LightFile::Ambient { colour, intensity } => Light::Ambient { colour, intensity },
            LightFile::Point {
                position,
                colour,
                intensity,
                radius,
                samples,
            } => Light::Point {
                position,
                source: LightSource {
                    colour,
                    intensity,
                    radius,
                    samples,
                },
            },
            LightFile::Directional {
                direction,
                colour,
                intensity,
            } => Light::Directional {
                direction,
                colour,
                intensity,
            },
            LightFile::Spot {
                position,
                direction,
                angle_deg,
                colour,
                intensity,
                radius,
                samples,
            } => Light::Spot {
                position,
                direction,
                angle_deg,
                source: LightSource {
                    colour,
                    intensity,
                    radius,
                    samples,
                },
            },
        }
    }
}

impl From<Light> for LightFile {
    fn from(light: Light) -> Self {
        match light {
            Light::Ambient { colour, intensity } => LightFile::Ambient { colour, intensity },
            Light::Point { position, source } => LightFile::Point {
                position,
                colour: source.colour,
                intensity: source.intensity,
                radius: source.radius,
                samples: source.samples,
            },
            Light::Directional {
                direction,
                colour,
                intensity,
            } => LightFile::Directional {
                direction,
                colour,
                intensity,
            },
            Light::Spot {
                position,
                direction,
                angle_deg,
                source,
            } => LightFile::Spot {
                position,
                direction,
                angle_deg,
                colour: source.colour,
                intensity: source.intensity,
                radius: source.radius,
                samples: source.samples,
            },
        }
    }
}
