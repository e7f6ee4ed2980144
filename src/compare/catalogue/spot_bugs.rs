//! The spot-light bugs of the catalogue: a spot light without its cone, without its
//! 1/d^2 fall-off, with its angle read as radians, or with its half angle taken as the
//! full angle. Each is the scene's own light changed the way the bug says.
//!
//! The three cone bugs change where the light reaches, and so which shadow rays are
//! cast: their pictures are raylab's own tracer run again on a world whose light is
//! changed ([`SpotWorld`]), as the missing objects' are. The fall-off bug keeps the
//! cone and the shadows and multiplies the light's terms by d^2 at each hit, which the
//! recorder computes from the tracer's own numbers ([`no_falloff_change`]).
//!
//! The contract's spot light (SCENE_FORMAT.md) has a hard edge and no fall-off across
//! its cone: its only fall-off is the 1/d^2 of distance, so *no fall-off* is a spot
//! light whose strength does not fall with distance (as a directional light's).

use glam::DVec3;
use rayon::prelude::*;

use super::retrace::trace_again;
use crate::scene::{Light, Scene};
use crate::trace::{
    Branch, LightRecord, Ray, RayCounts, Recorder, SurfacePoint, TermSwitches, Tracer, View, World,
};

/// Spot lights beyond this many are not tried (each cone bug needs a world of its own).
pub const MAX_SPOT_LIGHTS: usize = 8;

/// A wrong spot light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpotBug {
    /// No cone: the spot lights every direction, as a point light.
    NoCone,
    /// No 1/d^2 fall-off: the strength at every lit point is `colour * intensity`.
    NoFalloff,
    /// The angle in degrees used as radians: the cone's cosine is `cos(angle_deg)` with
    /// `angle_deg` taken as radians.
    AngleRadians,
    /// The half angle taken as the full angle: a cone half as wide.
    FullAngle,
    /// No cone and no fall-off together: a point light whose strength is `colour *
    /// intensity` everywhere (a floor lit white from edge to edge).
    NoConeNoFalloff,
}

impl SpotBug {
    /// Every spot bug.
    pub const ALL: [SpotBug; 5] = [
        SpotBug::NoCone,
        SpotBug::NoFalloff,
        SpotBug::AngleRadians,
        SpotBug::FullAngle,
        SpotBug::NoConeNoFalloff,
    ];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SpotBug::NoCone => "spot-no-cone",
            SpotBug::NoFalloff => "spot-no-falloff",
            SpotBug::AngleRadians => "spot-angle-radians",
            SpotBug::FullAngle => "spot-full-angle",
            SpotBug::NoConeNoFalloff => "spot-no-cone-no-falloff",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            SpotBug::NoCone => "it had no cone: it lit every direction like a point light",
            SpotBug::NoFalloff => "its strength did not fall off as 1/d^2",
            SpotBug::AngleRadians => "its angle in degrees were used as radians",
            SpotBug::FullAngle => "its half angle were taken as the full angle of the cone",
            SpotBug::NoConeNoFalloff => {
                "it had neither cone nor 1/d^2 fall-off: a point light of the same strength everywhere"
            }
        }
    }

    /// The light a cone bug makes of `light` (a spot light), or `None` for the fall-off
    /// bug, another kind of light, or a bug that changes nothing.
    #[must_use]
    pub fn changed_light(self, light: &Light) -> Option<Light> {
        let Light::Spot {
            position,
            direction,
            angle_deg,
            source,
        } = *light
        else {
            return None;
        };
        let spot = |angle_deg: f64| Light::Spot {
            position,
            direction,
            angle_deg,
            source,
        };
        let changed = match self {
            SpotBug::NoFalloff => return None,
            SpotBug::NoCone | SpotBug::NoConeNoFalloff => Light::Point { position, source },
            // The half angle whose cosine is cos(angle_deg radians), in [0, 180].
            SpotBug::AngleRadians => spot(angle_deg.cos().clamp(-1.0, 1.0).acos().to_degrees()),
            SpotBug::FullAngle => spot(angle_deg / 2.0),
        };
        let same = match changed {
            Light::Spot { angle_deg: a, .. } => a == angle_deg || a <= 0.0,
            _ => angle_deg >= 180.0,
        };
        (!same).then_some(changed)
    }
}

/// The world of a cone bug on one spot light.
pub struct SpotWorld {
    /// The bug.
    pub bug: SpotBug,
    /// The light's index among the world's non-ambient lights.
    pub light: usize,
    /// The scene compiled with the light changed.
    pub world: World,
}

/// The worlds of every cone bug of the first [`MAX_SPOT_LIGHTS`] spot lights of
/// `scene` (compiled as `world`, whose meshes they share).
#[must_use]
pub fn spot_worlds(scene: &Scene, world: &World) -> Vec<SpotWorld> {
    let mut jobs = Vec::new();
    for (light, &scene_index) in world.light_scene_index.iter().enumerate() {
        if !matches!(scene.lights[scene_index], Light::Spot { .. }) {
            continue;
        }
        if jobs.len() / SpotBug::ALL.len() >= MAX_SPOT_LIGHTS {
            break;
        }
        jobs.extend(SpotBug::ALL.map(|bug| (bug, light, scene_index)));
    }
    jobs.into_par_iter()
        .filter_map(|(bug, light, scene_index)| {
            let changed = bug.changed_light(&scene.lights[scene_index])?;
            let mut scene = scene.clone();
            scene.lights[scene_index] = changed;
            let world = World::with_meshes(&scene, &world.meshes).ok()?;
            Some(SpotWorld { bug, light, world })
        })
        .collect()
}

/// What each cone bug changes of a camera ray's colour `colour`: the ray traced again
/// in each of `worlds`.
pub fn cone_changes<'a>(
    worlds: impl IntoIterator<Item = &'a SpotWorld> + 'a,
    ray: &'a Ray,
    colour: DVec3,
) -> impl Iterator<Item = (SpotBug, usize, DVec3)> + 'a {
    worlds.into_iter().filter_map(move |w| {
        let seen = if w.bug == SpotBug::NoConeNoFalloff {
            without_falloff(&w.world, w.light, ray)
        } else {
            trace_again(&w.world, ray)
        };
        (seen.is_finite() && seen != colour).then_some((w.bug, w.light, seen - colour))
    })
}

/// The colour `ray` brings back in `world` were light `light` (a point light there)
/// not to fall off: its terms at each hit times d^2, weighted down the ray's tree as
/// the mirrors and glass pass them on.
fn without_falloff(world: &World, light: usize, ray: &Ray) -> DVec3 {
    let mut falloff = FalloffRecorder {
        world,
        light,
        rays: Vec::new(),
        change: DVec3::ZERO,
    };
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    let colour = tracer.trace_primary(ray, &mut RayCounts::default(), &mut falloff);
    colour + falloff.change
}

/// Adds up what one light's terms would gain without their 1/d^2 fall-off.
struct FalloffRecorder<'w> {
    world: &'w World,
    light: usize,
    /// Per ray of the tree: the product of km and kt before it, and its hit.
    rays: Vec<(DVec3, Option<SurfacePoint>, Option<usize>)>,
    change: DVec3,
}

impl Recorder for FalloffRecorder<'_> {
    fn started(&mut self, node: u32, _depth: u32, from: Option<(u32, Branch)>) {
        let node = node as usize;
        self.rays.truncate(node);
        let weight = from.map_or(DVec3::ONE, |(parent, branch)| {
            let (before, _, object) = self.rays[parent as usize];
            object.map_or(DVec3::ZERO, |o| {
                let material = &self.world.materials[self.world.objects[o].material];
                let k = if branch.is_transmitted() {
                    material.transmission
                } else {
                    material.mirror
                };
                before * k
            })
        });
        self.rays.push((weight, None, None));
    }

    fn hit(&mut self, node: u32, ray: &Ray, hit: &SurfacePoint) {
        let entry = &mut self.rays[node as usize];
        entry.1 = Some(*hit);
        entry.2 = self.world.world_object_of_hit(ray, hit);
    }

    fn light(&mut self, node: u32, record: &LightRecord) {
        let (weight, Some(hit), _) = self.rays[node as usize] else {
            return;
        };
        if self.world.light_scene_index.get(self.light) != Some(&record.scene_index) {
            return;
        }
        if let Some(sample) = self.world.lights[self.light].sample(hit.p) {
            let terms = record.diffuse + record.specular;
            self.change += weight * no_falloff_change(terms, sample.distance_squared);
        }
    }
}

/// What the fall-off bug changes of a spot light's `diffuse + specular` terms at a point
/// `distance_squared` from it: the strength there is `d^2` times raylab's.
#[must_use]
pub fn no_falloff_change(terms: DVec3, distance_squared: f64) -> DVec3 {
    terms * (distance_squared - 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::LightSource;

    fn spot(angle_deg: f64) -> Light {
        Light::Spot {
            position: DVec3::Y,
            direction: -DVec3::Y,
            angle_deg,
            source: LightSource::point(DVec3::ONE, 1.0),
        }
    }

    fn angle(light: Option<Light>) -> f64 {
        match light {
            Some(Light::Spot { angle_deg, .. }) => angle_deg,
            other => panic!("not a spot: {other:?}"),
        }
    }

    #[test]
    fn cone_bugs_change_the_angle_as_the_bug_reads_it() {
        // cos(20 rad) = 0.408: a half angle of 65.9 degrees.
        let radians = angle(SpotBug::AngleRadians.changed_light(&spot(20.0)));
        assert!((radians.to_radians().cos() - 20f64.cos()).abs() < 1e-12);
        assert!((radians - 65.92).abs() < 0.01, "{radians}");
        assert_eq!(angle(SpotBug::FullAngle.changed_light(&spot(30.0))), 15.0);
        assert!(matches!(
            SpotBug::NoCone.changed_light(&spot(30.0)),
            Some(Light::Point { .. })
        ));
        // A spot that lights everything has no cone to lose; the fall-off bug keeps it.
        assert!(SpotBug::NoCone.changed_light(&spot(180.0)).is_none());
        assert!(SpotBug::NoFalloff.changed_light(&spot(30.0)).is_none());
    }

    #[test]
    fn without_falloff_the_terms_are_d_squared_times_raylabs() {
        let terms = DVec3::new(0.1, 0.2, 0.3);
        let change = no_falloff_change(terms, 25.0);
        assert!((terms + change - 25.0 * terms).length() < 1e-12);
    }
}
