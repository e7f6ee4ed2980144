//! The quick re-shade: a pixel's colour from its cached entries (a mirror chain, or a
//! tree where there is glass), its shadow answers and what each light gave each hit
//! ([`LitFactors`]), with no ray, no light sample and no Phong lobe worked out again. An
//! edit of colours (materials other than shininess and `ior`, light colours and
//! intensities, ambient, background) or of the term switches needs no more.
//!
//! It takes the shader's steps (`Tracer::shade` for the beauty view, then the fold of
//! [`crate::trace::shade::fold_back`], deepest ray first, through the same
//! [`Bounce::returns`] step) with the shared term functions of
//! [`crate::trace::shade::phong`], so its colour is the shader's bit for bit
//! (tests/reshade.rs and tests/reshade_glass.rs hold every edit kind to that). Where the
//! cache lacks something the shader would need (a ray never traced, a shadow ray never
//! cast, a light's factors unknown, a lobe for another shininess) it gives up, and the
//! pixel is shaded in full.

use glam::DVec3;

use super::cached_hit::{CLEAR, NOT_CAST, decode_sphere};
use super::chains::PixelEntries;
use super::dependence::{DependenceRule, EntryTerms, TermDependence};
use super::light_factors::LightSlot;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{
    Bounce, BroughtBack, Tracer, diffuse_term, seen_terms, specular_term, visible_fraction,
};
use crate::trace::terms::ActiveTerms;
use crate::trace::world::falloff;

/// What an entry on one object needs of its material, looked up once per pass.
#[derive(Clone, Copy, Debug)]
pub(super) struct ObjectShade {
    /// `ka * ambient`, as the shader works it out.
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    pub(super) mirror: DVec3,
    pub(super) transmission: DVec3,
    /// A diffuse or specular colour: the shader looks at the lights.
    has_local: bool,
    /// The cached lobes are for another shininess.
    stale_lobes: bool,
}

/// Shades pixels of one world from their cache entries.
pub(crate) struct QuickShade<'r> {
    primary: ActiveTerms,
    secondary: ActiveTerms,
    background: DVec3,
    /// What each entry depends on before its lights.
    dependence: &'r DependenceRule,
    max_depth: u32,
    /// How mirror colours combine and where they are clamped.
    pub(super) conventions: crate::scene::Conventions,
    pub(super) objects: Vec<ObjectShade>,
    /// Per light, its strength; `None` for a light of zero strength, which the shader
    /// does not sample.
    lights: Vec<Option<DVec3>>,
    /// Some ray may cast a transmitted ray (a material has a transmission and the term
    /// is on): without glass a pixel's rays are a mirror chain.
    transmits: bool,
}

impl<'r> QuickShade<'r> {
    /// For what `tracer` shades, with per object whether its cached lobes are stale
    /// ([`super::light_factors::stale_lobes`]) and the dependence rule of its world;
    /// `None` for the debug views, which are not the lit picture.
    pub fn new(
        tracer: &Tracer,
        stale_lobes: &[bool],
        dependence: &'r DependenceRule,
    ) -> Option<Self> {
        let (primary, secondary) = tracer.beauty_terms()?;
        let world = tracer.world();
        let objects = world
            .objects
            .iter()
            .zip(stale_lobes)
            .map(|(object, &stale_lobes)| {
                let material = &world.materials[object.material];
                ObjectShade {
                    ambient: material.ambient * world.ambient,
                    diffuse: material.diffuse,
                    specular: material.specular,
                    mirror: material.mirror,
                    transmission: material.transmission,
                    has_local: material.diffuse != DVec3::ZERO || material.specular != DVec3::ZERO,
                    stale_lobes,
                }
            })
            .collect();
        let lights = world
            .lights
            .iter()
            .map(|light| Some(light.strength()).filter(|s| *s != DVec3::ZERO))
            .collect();
        let transmits = (primary.transmission || secondary.transmission)
            && world
                .materials
                .iter()
                .any(|m| m.transmission != DVec3::ZERO);
        Some(Self {
            primary,
            secondary,
            background: world.background,
            dependence,
            max_depth: world.max_depth,
            conventions: world.conventions,
            objects,
            lights,
            transmits,
        })
    }

    /// The colour of the pixel with cached entries `entries` (`lights` light slots
    /// each), and the switches it depends on (worked out as it is shaded, as
    /// [`super::dependence::DependenceRule`] would); also the rays the shader would count
    /// for it. `None` where the cache cannot answer.
    #[inline]
    pub fn pixel(
        &self,
        entries: &PixelEntries,
        lights: usize,
        counts: &mut RayCounts,
    ) -> Option<(DVec3, TermDependence)> {
        match entries.children {
            None => self.chain_pixel(entries.objects, entries.slots, lights, counts),
            Some(children) => self.tree_pixel(entries, children, lights, counts),
        }
    }

    /// [`Self::pixel`] for entries that are a mirror chain. Inlined into the tile loop,
    /// as it was before trees (out of line, a flat scene's material edit took 10% more
    /// time).
    #[inline(always)]
    fn chain_pixel(
        &self,
        objects: &[u32],
        slots: &[LightSlot],
        lights: usize,
        counts: &mut RayCounts,
    ) -> Option<(DVec3, TermDependence)> {
        // The chain the shader would follow ends at its first entry that casts no
        // mirror ray; a cached chain without one lacks the next ray.
        let last = objects
            .iter()
            .enumerate()
            .position(|(depth, &object)| !self.casts_mirror_ray(depth, object))?;
        // Nor does a chain hold a transmitted ray.
        if self.transmits
            && (objects[..=last].iter().enumerate())
                .any(|(depth, &object)| self.casts_transmitted_ray(depth, object))
        {
            return None;
        }
        let mut own = RayCounts {
            primary: 1,
            ..RayCounts::default()
        };
        let mut depends = TermDependence::NONE;
        // Deepest first, each entry folding in the colour of the one after, as
        // `fold_back` does, with no chain kept.
        let mut colour = DVec3::ZERO;
        for depth in (0..=last).rev() {
            let object = objects[depth];
            let row = &slots[depth * lights..(depth + 1) * lights];
            let (local, entry) = self.entry(depth, object, row, &mut own)?;
            depends.add(depth, entry);
            // Every entry before the last casts a mirror ray (found above).
            let casts = depth < last;
            own.reflection += u64::from(casts);
            // (The last entry may be a miss, with no object to read km from.)
            let km = if casts {
                self.objects[object as usize].mirror
            } else {
                DVec3::ZERO
            };
            let bounce = Bounce {
                local,
                km,
                kt: DVec3::ZERO,
            };
            let brought_back = BroughtBack::reflected(casts.then_some(colour));
            colour = bounce.returns(brought_back, &self.conventions);
        }
        counts.add(&own);
        Some((colour, depends))
    }

    /// The terms on at depth `depth`: the camera ray's (a solo shows them alone) or the
    /// mirror rays'.
    #[inline]
    fn terms(&self, depth: usize) -> &ActiveTerms {
        if depth == 0 {
            &self.primary
        } else {
            &self.secondary
        }
    }

    /// Whether the shader casts a mirror ray from entry `depth` on `object`
    /// (`u32::MAX`: a miss, which casts none).
    #[inline]
    pub(super) fn casts_mirror_ray(&self, depth: usize, object: u32) -> bool {
        object != u32::MAX
            && self.terms(depth).reflection
            && depth < self.max_depth as usize
            && self.objects[object as usize].mirror != DVec3::ZERO
    }

    /// Whether the shader casts a transmitted ray from entry `depth` on `object`.
    #[inline]
    pub(super) fn casts_transmitted_ray(&self, depth: usize, object: u32) -> bool {
        object != u32::MAX
            && self.terms(depth).transmission
            && depth < self.max_depth as usize
            && self.objects[object as usize].transmission != DVec3::ZERO
    }

    /// One entry's own colour (its mirror ray's share apart) and what the entry depends
    /// on. Inlined into [`Self::pixel`], as the shader's `shade` is.
    #[inline(always)]
    pub(super) fn entry(
        &self,
        depth: usize,
        object: u32,
        row: &[LightSlot],
        counts: &mut RayCounts,
    ) -> Option<(DVec3, EntryTerms)> {
        let terms = self.terms(depth);
        if object == u32::MAX {
            let background = if terms.background {
                self.background
            } else {
                DVec3::ZERO
            };
            return Some((background, self.dependence.miss_terms()));
        }
        let shade = &self.objects[object as usize];
        if shade.stale_lobes {
            return None;
        }
        let mut entry = self.dependence.hit_terms(object as usize, depth as u32);
        let mut colour = DVec3::ZERO;
        if terms.ambient {
            colour += shade.ambient;
        }
        if (terms.diffuse || terms.specular) && shade.has_local {
            for (light, slot) in self.lights.iter().zip(row) {
                let Some(strength) = *light else {
                    continue;
                };
                let factors = slot.factors;
                let n_dot_l = factors.n_dot_l();
                // Unknown (NaN): shade in full. Unreachable or behind the surface: no term,
                // as the shader's `n_dot_l > 0` test says.
                if n_dot_l.is_nan() {
                    return None;
                }
                if n_dot_l <= 0.0 {
                    continue;
                }
                let lobe = factors.lobe();
                entry.lit(lobe.is_some());
                // vis_l: all or nothing for a point light, a fraction for a sphere light.
                let mut fraction = 1.0;
                if terms.shadows {
                    if slot.shadow == NOT_CAST {
                        return None;
                    }
                    if let Some((clear, rays)) = decode_sphere(slot.shadow) {
                        counts.shadow += u64::from(rays);
                        fraction = visible_fraction(clear, rays);
                        if clear == 0 {
                            continue;
                        }
                    } else {
                        counts.shadow += 1;
                        if slot.shadow != CLEAR {
                            continue;
                        }
                    }
                }
                let strength = falloff(strength, factors.distance_squared());
                let diffuse = if terms.diffuse {
                    diffuse_term(shade.diffuse, strength, n_dot_l)
                } else {
                    DVec3::ZERO
                };
                let specular = if terms.specular {
                    specular_term(shade.specular, strength, lobe)
                } else {
                    DVec3::ZERO
                };
                let (diffuse, specular) = seen_terms(fraction, diffuse, specular);
                colour += diffuse + specular;
            }
        } else if shade.has_local {
            // The lights are not looked at, but would be with another switch.
            entry.lights(row);
        }
        Some((colour, entry))
    }
}
