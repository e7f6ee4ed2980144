//! The course's conventions on the command line: `--conventions course` (or `contract`)
//! for all three at once, `--mirror`, `--clamp` and `--quantise` for one each; each
//! overrides what the scene file says (`render.conventions`).

use clap::Args;

use crate::scene::{ClampConvention, Conventions, MirrorConvention, Quantise, Scene};

/// How colours combine, clamp and become bytes, over the scene's own settings.
#[derive(Debug, Default, Args)]
pub struct ConventionArgs {
    /// All three at once: `course` (mirrors added, each ray clamped, bytes truncated:
    /// the course skeleton's habits) or `contract` (added, only the pixel clamped,
    /// rounded). Default: the scene's `render.conventions`.
    #[arg(long, value_parser = ["course", "contract"])]
    pub conventions: Option<String>,
    /// How a mirror's colour joins the local one: `add` (local + km reflected) or
    /// `blend` ((1 - km) local + km reflected).
    #[arg(long, value_parser = ["add", "blend"])]
    pub mirror: Option<String>,
    /// Where colour is clamped to [0, 1]: `pixel` (only the final pixel) or `each-ray`
    /// (every ray's colour before it is used).
    #[arg(long, value_parser = ["pixel", "each-ray"])]
    pub clamp: Option<String>,
    /// How a pixel becomes a byte: `round` (round(255 c)) or `truncate` (int(255 c)).
    #[arg(long, value_parser = ["round", "truncate"])]
    pub quantise: Option<String>,
}

impl ConventionArgs {
    /// The conventions these flags make of `scene`'s.
    #[must_use]
    pub fn conventions(&self, scene: &Scene) -> Conventions {
        let mut out = match self.conventions.as_deref() {
            Some("course") => Conventions::COURSE,
            Some(_) => Conventions::default(),
            None => scene.render.conventions,
        };
        if let Some(mirror) = &self.mirror {
            out.mirror = if mirror == "blend" {
                MirrorConvention::Blend
            } else {
                MirrorConvention::Add
            };
        }
        if let Some(clamp) = &self.clamp {
            out.clamp = if clamp == "each-ray" {
                ClampConvention::EachRay
            } else {
                ClampConvention::Pixel
            };
        }
        if let Some(quantise) = &self.quantise {
            out.quantise = if quantise == "truncate" {
                Quantise::Truncate
            } else {
                Quantise::Round
            };
        }
        out
    }

    /// `scene` with these conventions.
    #[must_use]
    pub fn applied(&self, scene: Scene) -> Scene {
        let conventions = self.conventions(&scene);
        let mut scene = scene;
        scene.render.conventions = conventions;
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::examples::default_scene;

    #[test]
    fn a_preset_then_single_flags_over_the_scenes_own() {
        let scene = default_scene();
        let none = ConventionArgs::default();
        assert_eq!(none.conventions(&scene), scene.render.conventions);
        let course = ConventionArgs {
            conventions: Some("course".into()),
            ..ConventionArgs::default()
        };
        assert_eq!(course.conventions(&scene), Conventions::COURSE);
        let course_blend = ConventionArgs {
            conventions: Some("course".into()),
            mirror: Some("blend".into()),
            ..ConventionArgs::default()
        };
        let c = course_blend.conventions(&scene);
        assert_eq!(c.mirror, MirrorConvention::Blend);
        assert_eq!(c.clamp, ClampConvention::EachRay);
        assert_eq!(c.quantise, Quantise::Truncate);
    }
}
