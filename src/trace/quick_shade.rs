//! The quick re-shade: a pixel's colour from its cached mirror chain, its shadow answers
//! and what each light gave each hit ([`LitFactors`]), with no ray, no light sample and
//! no Phong lobe worked out again. An edit of colours (materials other than shininess,
//! light colours and intensities, ambient, background) or of the term switches needs no
//! more.
//!
//! It takes the shader's steps (`Tracer::shade` for the beauty view, then the shared
//! [`fold_back`]) with the shared term functions of [`super::phong`], so its colour is
//! the shader's bit for bit (tests/reshade.rs holds every edit kind to that). Where the
//! cache lacks something the shader would need (a ray never traced, a shadow ray never
//! cast, a light's factors unknown, a lobe for another shininess) it gives up, and the
//! pixel is shaded in full.

use glam::DVec3;

use super::chains::{CLEAR, NOT_CAST};
use super::light_factors::{LightSlot, Lit};
use super::mirror_chain::{Bounce, Chain, fold_back};
use super::phong::{diffuse_term, specular_term};
use super::record::NoRecorder;
use super::shade::{RayCounts, Tracer};
use super::terms::ActiveTerms;
use super::world::World;

/// Shades pixels of one world from their cache entries.
pub(super) struct QuickShade<'w, 's> {
    world: &'w World,
    primary: ActiveTerms,
    secondary: ActiveTerms,
    /// Per object, whether its cached lobes are stale ([`super::light_factors::stale_lobes`]).
    stale_lobes: &'s [bool],
}

impl<'w, 's> QuickShade<'w, 's> {
    /// For what `tracer` shades; `None` for the debug views, which are not the lit
    /// picture.
    pub fn new(tracer: &Tracer<'w>, stale_lobes: &'s [bool]) -> Option<Self> {
        let (primary, secondary) = tracer.beauty_terms()?;
        Some(Self {
            world: tracer.world(),
            primary,
            secondary,
            stale_lobes,
        })
    }

    /// The colour of the pixel whose chain's entries met `objects` (`u32::MAX`: a miss),
    /// with `lights` light slots per entry in `slots`, and the rays the shader would count for it; `None` where the
    /// cache cannot answer.
    pub fn pixel(
        &self,
        objects: &[u32],
        slots: &[LightSlot],
        lights: usize,
        counts: &mut RayCounts,
    ) -> Option<DVec3> {
        let mut own = RayCounts {
            primary: 1,
            ..RayCounts::default()
        };
        let mut bounces = Chain::new();
        for (depth, &object) in objects.iter().enumerate() {
            let terms = if depth == 0 {
                &self.primary
            } else {
                &self.secondary
            };
            let row = &slots[depth * lights..(depth + 1) * lights];
            let (local, mirror) = self.entry(depth as u32, object, row, terms, &mut own)?;
            match mirror {
                Some(km) => bounces.push(Bounce { local, km }),
                None => {
                    bounces.push(Bounce::local(local));
                    counts.add(&own);
                    return Some(fold_back(&bounces, &mut NoRecorder));
                }
            }
        }
        // The chain ends where the shader would cast one more mirror ray.
        None
    }

    /// One entry's own colour and, if the shader casts a mirror ray from it, its km.
    #[inline]
    fn entry(
        &self,
        depth: u32,
        object: u32,
        row: &[LightSlot],
        terms: &ActiveTerms,
        counts: &mut RayCounts,
    ) -> Option<(DVec3, Option<DVec3>)> {
        let world = self.world;
        if object == u32::MAX {
            let background = if terms.background {
                world.background
            } else {
                DVec3::ZERO
            };
            return Some((background, None));
        }
        let object = object as usize;
        if self.stale_lobes[object] {
            return None;
        }
        let material = &world.materials[world.objects[object].material];
        let mut colour = DVec3::ZERO;
        if terms.ambient {
            colour += material.ambient * world.ambient;
        }
        let has_local = material.diffuse != DVec3::ZERO || material.specular != DVec3::ZERO;
        if (terms.diffuse || terms.specular) && has_local {
            for (light, slot) in world.lights.iter().zip(row) {
                // The shader samples no light of zero strength.
                if light.strength() == DVec3::ZERO {
                    continue;
                }
                let (distance_squared, n_dot_l, lobe) = match slot.factors.get() {
                    Lit::Unknown => return None,
                    Lit::Unreachable => continue,
                    Lit::Reached {
                        distance_squared,
                        n_dot_l,
                        lobe,
                    } => (distance_squared, n_dot_l, lobe),
                };
                if n_dot_l <= 0.0 || n_dot_l.is_nan() {
                    continue;
                }
                if terms.shadows {
                    if slot.shadow == NOT_CAST {
                        return None;
                    }
                    counts.shadow += 1;
                    if slot.shadow != CLEAR {
                        continue;
                    }
                }
                let strength = light.radiance_at(distance_squared);
                let diffuse = if terms.diffuse {
                    diffuse_term(material.diffuse, strength, n_dot_l)
                } else {
                    DVec3::ZERO
                };
                let specular = if terms.specular {
                    specular_term(material.specular, strength, lobe)
                } else {
                    DVec3::ZERO
                };
                colour += diffuse + specular;
            }
        }
        let casts_mirror_ray =
            terms.reflection && depth < world.max_depth && material.mirror != DVec3::ZERO;
        if casts_mirror_ray {
            counts.reflection += 1;
        }
        Some((colour, casts_mirror_ray.then_some(material.mirror)))
    }
}
