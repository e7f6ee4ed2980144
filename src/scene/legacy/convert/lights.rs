//! Light blocks: each kind takes what it needs (`Colour` always, `Location` for point and
//! spot lights, `Direction` for directional and spot lights); keywords a kind does not
//! use are ignored with a warning. A spot light without `Angle` lights nothing in the
//! legacy renderer, so it is imported as one that lights nothing (intensity 0), with a
//! warning. Older files' `ambientLight` becomes the first light. `Radius r` and `Samples N`
//! on a point or spot light make it a sphere light (legacy: N lights of colour/N at random
//! points of the sphere, fixed at load; raylab samples the sphere instead).

use super::super::error::LegacyError;
use super::super::syntax::{At, Item, LightSetting};
use super::converter::Converter;
use crate::scene::{Light, LightKind, LightSource, Scene};

/// The half-angle given to a spot light that had no `Angle`. It is imported with
/// intensity 0, so the angle changes nothing until someone raises the intensity; then it
/// gives a cone that can be seen.
pub const UNLIT_SPOT_ANGLE_DEG: f64 = 45.0;

impl Converter<'_> {
    /// A light; the `broken` keywords are missing because they were wrong, and their
    /// absence is not reported again.
    pub(super) fn light_block(
        &mut self,
        kind: LightKind,
        settings: &[Item<LightSetting>],
        broken: &[String],
        at: &At,
    ) {
        let (mut colour, mut location, mut direction, mut angle) = (None, None, None, None);
        let (mut radius, mut samples) = (0.0, 1);
        let is_positional = matches!(kind, LightKind::Point | LightKind::Spot);
        for setting in settings {
            let used = match setting.value {
                LightSetting::Colour(c) => {
                    colour = Some(c);
                    true
                }
                LightSetting::Location(p) => {
                    location = Some(p);
                    matches!(kind, LightKind::Point | LightKind::Spot)
                }
                LightSetting::Direction(d) => {
                    direction = Some(d);
                    matches!(kind, LightKind::Directional | LightKind::Spot)
                }
                LightSetting::Angle(a) => {
                    angle = Some(a);
                    kind == LightKind::Spot
                }
                LightSetting::Radius(r) => {
                    radius = r;
                    is_positional
                }
                LightSetting::Samples(n) => {
                    samples = n;
                    is_positional
                }
            };
            if !used {
                self.warn(
                    setting.at.line,
                    format!(
                        "`{}` has no effect on a {}; ignored",
                        setting.at.token, at.token
                    ),
                );
            }
        }
        let colour = self.need(colour, "Colour", broken, at);
        let source = |colour, intensity| LightSource {
            colour,
            intensity,
            radius,
            samples,
        };
        let light = match kind {
            LightKind::Ambient => colour.map(|colour| Light::Ambient {
                colour,
                intensity: 1.0,
            }),
            LightKind::Point => {
                let position = self.need(location, "Location", broken, at);
                colour.zip(position).map(|(colour, position)| Light::Point {
                    position,
                    source: source(colour, 1.0),
                })
            }
            LightKind::Directional => {
                let direction = self.need(direction, "Direction", broken, at);
                colour
                    .zip(direction)
                    .map(|(colour, direction)| Light::Directional {
                        direction,
                        colour,
                        intensity: 1.0,
                    })
            }
            LightKind::Spot => {
                let position = self.need(location, "Location", broken, at);
                let direction = self.need(direction, "Direction", broken, at);
                let angle_broken = broken.iter().any(|b| b == "Angle");
                let (angle_deg, intensity) = match angle {
                    Some(angle_deg) => (Some(angle_deg), 1.0),
                    None if angle_broken => (None, 1.0),
                    None => {
                        self.warn(
                            at.line,
                            format!(
                                "a {} without `Angle`: the legacy renderer reads an \
                                 uninitialised angle and lights nothing with it, so it is \
                                 imported with intensity 0 (it lights nothing) and angle_deg \
                                 {UNLIT_SPOT_ANGLE_DEG}; set both to use it",
                                at.token
                            ),
                        );
                        (Some(UNLIT_SPOT_ANGLE_DEG), 0.0)
                    }
                };
                match (colour, position, direction, angle_deg) {
                    (Some(colour), Some(position), Some(direction), Some(angle_deg)) => {
                        Some(Light::Spot {
                            position,
                            direction,
                            angle_deg,
                            source: source(colour, intensity),
                        })
                    }
                    _ => None,
                }
            }
        };
        if let Some(light) = light {
            self.lights.push((light, at.clone()));
        }
    }

    /// `value`, or an error at the light's kind saying it needs `keyword` (unless the
    /// keyword is there but `broken`, which was reported already).
    fn need<T>(
        &mut self,
        value: Option<T>,
        keyword: &str,
        broken: &[String],
        at: &At,
    ) -> Option<T> {
        if value.is_none() && !broken.iter().any(|b| b == keyword) {
            self.errors.push(LegacyError::new(
                at.line,
                &at.token,
                format!("a {} needs a `{keyword}`", at.token),
            ));
        }
        value
    }

    /// The scene's lights: the Scene block's ambient light first, then the Light blocks
    /// in file order, each checked against the scene rules.
    pub(super) fn scene_lights(&mut self) -> Vec<Light> {
        let mut lights = Vec::new();
        if let Some(colour) = self.ambient_light {
            lights.push(Light::Ambient {
                colour,
                intensity: 1.0,
            });
        }
        for (light, at) in std::mem::take(&mut self.lights) {
            let fragment = Scene {
                lights: vec![light.clone()],
                ..Scene::empty()
            };
            self.check(&fragment, &at, "this light cannot be imported");
            lights.push(light);
        }
        lights
    }
}
