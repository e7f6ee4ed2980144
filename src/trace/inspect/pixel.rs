//! The pixel inspector: every number behind one pixel, recorded by the tracer's own
//! shading code through a [`Recorder`], so what it shows is what the image computed.

use glam::{DVec2, DVec3};

use crate::trace::film::{PinholeCamera, RenderOptions};
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{
    Branch, LightOutcome, LightRecord, Recorder, ShadowRay, SkippedLight, Tracer,
};
use crate::trace::shapes::TriangleHit;
use crate::trace::terms::{Term, TermSwitches};
use crate::trace::world::{SurfacePoint, World};

/// What one ray of the pixel's tree (the camera ray, then each mirror and transmitted
/// ray) met.
#[derive(Clone, Debug, PartialEq)]
pub struct BounceReport {
    /// 0 for the camera ray, then 1, 2, ... for each ray after it.
    pub depth: u32,
    /// The index in [`PixelReport::bounces`] of the ray that started this one, and which
    /// of its rays this is; `None` for the camera ray.
    pub from: Option<(usize, Branch)>,
    /// The ray.
    pub ray: Ray,
    /// The surface hit, or `None` for a miss.
    pub hit: Option<SurfacePoint>,
    /// Which surface of the object tree that is (its path, and on a CSG object which
    /// crossing), when the hit is found again in the world.
    pub surface: Option<HitSurface>,
    /// On a mesh: which triangle of its file the ray met, and the barycentric weights.
    pub triangle: Option<TriangleHit>,
    /// Colour returned by a miss (background, or black where the switches hide it).
    pub background: DVec3,
    /// The ambient term added.
    pub ambient: DVec3,
    /// Each light that can reach the point (in front of it or not, inside any spot cone).
    pub lights: Vec<LightRecord>,
    /// The lights passed over at the point, and why.
    pub skipped: Vec<SkippedLight>,
    /// Where each blocked shadow ray met its blocker: `(scene index of the light, the
    /// blocker's surface, which leaf of its tree that is)`.
    pub blocker_hits: Vec<(usize, SurfacePoint, HitSurface)>,
    /// The shadow rays of sphere lights, as cast: `(scene index of the light, the ray)`.
    pub sphere_shadow_rays: Vec<(usize, ShadowRay)>,
    /// `(km, colour of the reflected ray)` when a mirror ray was cast.
    pub reflection: Option<(DVec3, DVec3)>,
    /// `(kt, colour of the transmitted ray)` when a transmitted ray was cast.
    pub transmission: Option<(DVec3, DVec3)>,
    /// The colour this ray returned.
    pub colour: DVec3,
    /// Its colour before the `EachRay` convention clamped it, where the clamp changed it.
    pub unclamped: Option<DVec3>,
}

impl BounceReport {
    fn new(depth: u32, from: Option<(usize, Branch)>) -> Self {
        Self {
            depth,
            from,
            ray: Ray::new(DVec3::ZERO, DVec3::ZERO),
            hit: None,
            surface: None,
            triangle: None,
            background: DVec3::ZERO,
            ambient: DVec3::ZERO,
            lights: Vec::new(),
            skipped: Vec::new(),
            blocker_hits: Vec::new(),
            sphere_shadow_rays: Vec::new(),
            reflection: None,
            transmission: None,
            colour: DVec3::ZERO,
            unclamped: None,
        }
    }

    /// Every non-ambient light of the scene that the point was shaded with, in the
    /// scene's order, with what it did: `(scene index, outcome, its record if sampled)`.
    #[must_use]
    pub fn light_outcomes(&self) -> Vec<(usize, LightOutcome, Option<&LightRecord>)> {
        let mut all: Vec<_> = self
            .lights
            .iter()
            .map(|l| (l.scene_index, LightOutcome::of(l), Some(l)))
            .chain(
                self.skipped
                    .iter()
                    .map(|s| (s.scene_index, LightOutcome::Skipped(s.why), None)),
            )
            .collect();
        all.sort_by_key(|(index, _, _)| *index);
        all
    }

    /// Where the shadow ray to scene light `scene_index` met its blocker, if it was blocked.
    #[must_use]
    pub fn blocker_hit(&self, scene_index: usize) -> Option<&SurfacePoint> {
        self.blocker_hits
            .iter()
            .find(|(light, ..)| *light == scene_index)
            .map(|(_, hit, _)| hit)
    }

    /// The leaf of the blocker's tree that the shadow ray at `point` met (a blocker's
    /// surface point names the ray), if some shadow ray of this bounce was blocked there.
    #[must_use]
    pub fn blocker_surface_at(&self, point: DVec3) -> Option<&HitSurface> {
        self.blocker_hits
            .iter()
            .find(|(_, hit, _)| hit.p == point)
            .map(|(.., surface)| surface)
    }

    /// The sum of the recorded terms; equals `colour` (checked by the tests).
    #[must_use]
    pub fn sum_of_terms(&self) -> DVec3 {
        let local: DVec3 = self.lights.iter().map(|l| l.diffuse + l.specular).sum();
        let mirror = self.reflection.map_or(DVec3::ZERO, |(km, c)| km * c);
        let transmitted = self.transmission.map_or(DVec3::ZERO, |(kt, c)| kt * c);
        if self.hit.is_some() {
            self.ambient + local + mirror + transmitted
        } else {
            self.background
        }
    }
}

/// The leaf of the object tree a ray met.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HitSurface {
    /// Tree path of the leaf: `"ball"`, `"snowman/body"`, `"die/pip 3.1"`.
    pub path: String,
    /// On a CSG object: which of its surfaces along the ray's line this is (0 = the
    /// first, counting those behind the origin too) and how many there are.
    pub crossing: Option<(usize, usize)>,
    /// Whether it is a Difference's cut (a subtracted operand's surface).
    pub cut: bool,
}

impl HitSurface {
    /// The leaf of world object `index` that the ray met at `hit.t`.
    fn find(world: &World, index: usize, ray: &Ray, hit: &SurfacePoint) -> Self {
        let object = &world.objects[index];
        let Some(tree) = &object.csg else {
            return Self {
                path: object.name.clone(),
                crossing: None,
                cut: false,
            };
        };
        let surfaces = tree.surfaces(&ray.transformed(&object.object_from_world));
        let crossing = surfaces.iter().position(|(s, _)| s.hit.t == hit.t);
        let leaf = &tree.leaves[hit.part as usize];
        Self {
            path: leaf.path.clone(),
            crossing: crossing.map(|k| (k, surfaces.len())),
            cut: crossing.is_some_and(|k| surfaces[k].0.cut),
        }
    }
}

/// Everything behind one pixel's centre sample.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelReport {
    /// The pixel.
    pub pixel: (u32, u32),
    /// The camera ray, then each mirror and transmitted ray in the order they were
    /// shaded (breadth first: a ray's parent comes before it).
    pub bounces: Vec<BounceReport>,
    /// The pixel's colour before clamping.
    pub unclamped: DVec3,
    /// The colour written: clamped to [0, 1].
    pub clamped: DVec3,
}

/// Collects a [`PixelReport`] as the shader runs: the recorder's ray `node` is the index
/// into `bounces`.
struct ReportRecorder<'w> {
    world: &'w World,
    bounces: Vec<BounceReport>,
}

impl ReportRecorder<'_> {
    fn at(&mut self, node: u32, ray: &Ray) -> &mut BounceReport {
        let bounce = &mut self.bounces[node as usize];
        bounce.ray = *ray;
        bounce
    }
}

impl Recorder for ReportRecorder<'_> {
    fn started(&mut self, node: u32, depth: u32, from: Option<(u32, Branch)>) {
        debug_assert_eq!(node as usize, self.bounces.len(), "rays start in order");
        let from = from.map(|(parent, branch)| (parent as usize, branch));
        self.bounces.push(BounceReport::new(depth, from));
    }
    fn hit(&mut self, node: u32, ray: &Ray, hit: &SurfacePoint) {
        // One search serves both: a group's members share the hit's scene index.
        let index = self.world.world_object_of_hit(ray, hit);
        let surface = index.map(|i| HitSurface::find(self.world, i, ray, hit));
        let triangle = index.and_then(|i| self.world.triangle_hit(i, ray, f64::INFINITY));
        let bounce = self.at(node, ray);
        bounce.hit = Some(*hit);
        bounce.surface = surface;
        bounce.triangle = triangle;
    }
    fn miss(&mut self, node: u32, ray: &Ray, background: DVec3) {
        self.at(node, ray).background = background;
    }
    fn ambient(&mut self, node: u32, colour: DVec3) {
        self.bounces[node as usize].ambient = colour;
    }
    fn light(&mut self, node: u32, record: &LightRecord) {
        let bounce = &mut self.bounces[node as usize];
        bounce.lights.push(*record);
        // The renderer only asks whether something is in the way; the record also shows
        // where the ray meets the blocker (the record names it by its scene index).
        if let Some(shadow) = record.shadow_ray
            && let Some(blocker) = shadow.blocked_by
            && let Some((index, hit)) = (0..self.world.objects.len())
                .filter(|&i| self.world.object_scene_index[i] == blocker)
                .filter_map(|i| {
                    let hit = self.world.intersect_object(i, &shadow.ray, shadow.t_max)?;
                    Some((i, hit))
                })
                .min_by(|(_, a), (_, b)| a.t.total_cmp(&b.t))
        {
            let surface = HitSurface::find(self.world, index, &shadow.ray, &hit);
            let hit = SurfacePoint {
                object: blocker,
                ..hit
            };
            bounce.blocker_hits.push((record.scene_index, hit, surface));
        }
    }
    fn sphere_shadow_ray(&mut self, node: u32, light: usize, ray: &ShadowRay) {
        self.bounces[node as usize]
            .sphere_shadow_rays
            .push((light, *ray));
    }
    fn skipped_light(&mut self, node: u32, skipped: &SkippedLight) {
        self.bounces[node as usize].skipped.push(*skipped);
    }
    fn reflection(&mut self, node: u32, km: DVec3, reflected: DVec3) {
        self.bounces[node as usize].reflection = Some((km, reflected));
    }
    fn transmission(&mut self, node: u32, kt: DVec3, transmitted: DVec3, _: Branch) {
        self.bounces[node as usize].transmission = Some((kt, transmitted));
    }
    fn result(&mut self, node: u32, colour: DVec3) {
        self.bounces[node as usize].colour = colour;
    }
    fn clamped(&mut self, node: u32, unclamped: DVec3) {
        self.bounces[node as usize].unclamped = Some(unclamped);
    }
}

/// Inspects the centre of pixel `(px, py)` of an image rendered with `options` (beauty
/// view with its term switches), through the same code path as the renderer. Object and
/// light indices in the report are the scene's.
///
/// # Panics
/// When `world` was compiled for other isolation switches than `options.isolation`.
#[must_use]
pub fn inspect_pixel(world: &World, options: &RenderOptions, px: u32, py: u32) -> PixelReport {
    crate::trace::world::assert_compiled_for(world, &options.isolation);
    let camera = PinholeCamera::new(&world.camera, options.width, options.height);
    let tracer = Tracer::new(world, options.switches, crate::trace::terms::View::Beauty);
    let ray = camera.ray(DVec2::new(f64::from(px) + 0.5, f64::from(py) + 0.5));
    let mut recorder = ReportRecorder {
        world,
        bounces: Vec::new(),
    };
    let unclamped = tracer.trace_primary(&ray, &mut RayCounts::default(), &mut recorder);
    PixelReport {
        pixel: (px, py),
        bounces: recorder.bounces,
        unclamped,
        clamped: unclamped.clamp(DVec3::ZERO, DVec3::ONE),
    }
}

/// The switches a report was traced with, in words: "all terms on", or
/// "off: diffuse, shadows · solo specular" (as `--off` and `--solo` name them).
#[must_use]
pub fn switches_text(switches: TermSwitches) -> String {
    let off: Vec<&str> = Term::ALL
        .into_iter()
        .filter(|t| !switches.is_on(*t))
        .map(Term::name)
        .collect();
    let mut parts = Vec::new();
    if !off.is_empty() {
        parts.push(format!("off: {}", off.join(", ")));
    }
    if let Some(solo) = switches.solo {
        parts.push(format!("solo {solo}"));
    }
    if parts.is_empty() {
        "all terms on".to_owned()
    } else {
        parts.join(" · ")
    }
}

/// A pixel that is not in the image, as an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "pixel ({x}, {y}) is outside the {width} x {height} image (x runs from 0 to {}, y from 0 to {})",
    width.saturating_sub(1),
    height.saturating_sub(1)
)]
pub struct PixelOutside {
    /// The pixel's column.
    pub x: u32,
    /// The pixel's row.
    pub y: u32,
    /// The image width.
    pub width: u32,
    /// The image height.
    pub height: u32,
}

/// As [`inspect_pixel`], for a pixel that may lie outside the image.
///
/// # Errors
/// When `(px, py)` is not a pixel of the `options.width` x `options.height` image.
pub fn try_inspect_pixel(
    world: &World,
    options: &RenderOptions,
    px: u32,
    py: u32,
) -> Result<PixelReport, PixelOutside> {
    if px >= options.width || py >= options.height {
        return Err(PixelOutside {
            x: px,
            y: py,
            width: options.width,
            height: options.height,
        });
    }
    Ok(inspect_pixel(world, options, px, py))
}

/// The scene index of the object under pixel point `(x, y)` (in pixels, fractional) of a
/// `width` x `height` image: the tracer's own primary ray, so picking is exact (and never
/// finds an object the world was compiled without).
#[must_use]
pub fn pick(world: &World, width: u32, height: u32, point: DVec2) -> Option<usize> {
    let camera = PinholeCamera::new(&world.camera, width, height);
    world
        .intersect(&camera.ray(point), f64::INFINITY)
        .map(|hit| world.scene_object(hit.object))
}
