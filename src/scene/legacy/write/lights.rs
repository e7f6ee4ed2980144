//! Lights as Light blocks (and, in the 2016 dialect, the Scene block's `ambientLight`).
//!
//! A course light has only a colour, its strength: raylab's `colour * intensity` is
//! written as `Colour`, which the importer reads back with intensity 1 (the same
//! strength, so the same picture). The 2020 dialect has every kind, and sphere lights
//! as the extension's `Radius r Samples N`. The 2016 framework has point lights only and
//! one ambient colour in the Scene block: ambient lights are added into it (warned when
//! there are several), directional and spot lights are refused, and a sphere light is
//! written as a point light (warned: its soft shadows become hard).

use glam::DVec3;

use super::super::convert::Dialect;
use super::numbers::{number, triple};
use super::problem::{Problems, Subject};
use crate::scene::Light;

/// What the lights add up to in the file.
#[derive(Default)]
pub struct WrittenLights {
    /// The Light blocks, in scene order.
    pub blocks: String,
    /// The Scene block's `ambientLight` (2016 only).
    pub scene_ambient: Option<DVec3>,
}

/// Writes `lights` in `dialect`.
pub fn write_lights(lights: &[Light], dialect: Dialect, problems: &mut Problems) -> WrittenLights {
    let mut written = WrittenLights::default();
    let mut ambient_count = 0;
    for (index, light) in lights.iter().enumerate() {
        let subject = Subject::Light {
            index,
            kind: light.kind_name(),
        };
        let strength = light.strength();
        if dialect == Dialect::Framework2016 {
            match light {
                Light::Ambient { .. } => {
                    ambient_count += 1;
                    if ambient_count > 1 {
                        problems.warn(
                            subject,
                            "added into the Scene block's ambientLight (the 2016 framework \
                             has one ambient colour)",
                        );
                    }
                    let sum = written.scene_ambient.unwrap_or(DVec3::ZERO) + strength;
                    written.scene_ambient = Some(sum);
                    continue;
                }
                Light::Directional { .. } | Light::Spot { .. } => {
                    problems.refuse(
                        subject,
                        format!(
                            "the 2016 framework has point lights only; a {} light cannot be \
                             written (use --dialect 2020)",
                            light.kind_name()
                        ),
                    );
                    continue;
                }
                Light::Point { .. } => {}
            }
        }
        let block = match light {
            Light::Ambient { .. } => format!("Light AmbientLight\n  Colour {}\n", triple(strength)),
            Light::Point { position, .. } => format!(
                "Light PointLight\n  Colour {}\n  Location {}\n",
                triple(strength),
                triple(*position)
            ),
            Light::Directional { direction, .. } => format!(
                "Light DirectionalLight\n  Colour {}\n  Direction {}\n",
                triple(strength),
                triple(*direction)
            ),
            Light::Spot {
                position,
                direction,
                angle_deg,
                ..
            } => format!(
                "Light SpotLight\n  Colour {}\n  Location {}\n  Direction {}\n  Angle {}\n",
                triple(strength),
                triple(*position),
                triple(*direction),
                number(*angle_deg)
            ),
        };
        written.blocks.push_str(&block);
        if let Some((radius, samples)) = light.sphere() {
            match dialect {
                Dialect::Framework2020 => written.blocks.push_str(&format!(
                    "  Radius {}\n  Samples {samples}\n",
                    number(radius)
                )),
                Dialect::Framework2016 => problems.warn(
                    subject,
                    format!(
                        "its sphere (radius {}, {samples} samples) is not written: the 2016 \
                         dialect has no Radius or Samples, so its soft shadows become hard",
                        number(radius)
                    ),
                ),
            }
        }
        written.blocks.push_str("End\n");
    }
    written
}
