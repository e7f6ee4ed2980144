//! What of a sample's rays depends on the conventions that fold them, watched while the
//! split traces it, so that a split under other conventions can keep the pixels whose
//! samples it would make again bit for bit.
//!
//! The conventions change only how each ray tree is folded (mirror `Add` or `Blend`, a
//! clamp per ray or per pixel): at the same depth limit the trees are the same rays with
//! the same hits, lights and shadow rays. A tree folds alike under both mirror
//! conventions when no mirror ray was cast in it, and alike under both clamps when every
//! ray's colour already lies in [0, 1]. A sample is the same under other conventions
//! when that holds for every tree its split folds: the camera ray's, and each trace
//! again without a tree node. A spot light's cone bugs trace again in changed worlds
//! whose colours are not watched: where only the spot light changed, the rays are the
//! camera ray's tree's (the same mirror rays) and the sample counts as one whose clamp
//! matters; a sample that traced a world changed otherwise is never kept.

use std::ops::BitOrAssign;

use glam::DVec3;

use crate::compare::catalogue::trace_again;
use crate::scene::{ClampConvention, Conventions};
use crate::trace::{
    Branch, LightRecord, NoRecorder, Ray, RayCounts, Recorder, ShadowRay, SkippedLight,
    SurfacePoint, TermSwitches, Tracer, View, World,
};

#[cfg(doc)]
use crate::compare::catalogue::SpotWorld;

/// Which conventions a sample's (or a pixel's samples') colours depend on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FoldFlags(u8);

impl FoldFlags {
    /// A mirror ray was cast: the mirror convention changes the colour.
    pub const MIRROR: Self = Self(1);
    /// A ray's colour lies outside [0, 1] (or may have been clamped into it): the clamp
    /// convention changes the colour.
    pub const UNCLAMPED: Self = Self(2);
    /// A cone bug's world ([`SpotWorld`]), changed in more than its spot light, was
    /// traced: not watched.
    pub const SPOT: Self = Self(4);

    /// Whether a sample with these flags, split under `from` (conventions and depth
    /// limit), gives the same bits split under `to`.
    #[must_use]
    pub fn same_under(self, from: (Conventions, u32), to: (Conventions, u32)) -> bool {
        let ((from, from_depth), (to, to_depth)) = (from, to);
        from_depth == to_depth
            && from.quantise == to.quantise
            && !self.has(Self::SPOT)
            && (from.mirror == to.mirror || !self.has(Self::MIRROR))
            && (from.clamp == to.clamp || !self.has(Self::UNCLAMPED))
    }

    /// Whether no other conventions at this depth give the same bits (both the mirror
    /// and the clamp matter): nothing more to watch.
    #[must_use]
    pub fn depends_on_all(self) -> bool {
        self.has(Self::MIRROR) && self.has(Self::UNCLAMPED)
    }

    /// Whether every flag of `flags` is set.
    #[must_use]
    pub fn contains(self, flags: Self) -> bool {
        self.0 & flags.0 == flags.0
    }

    fn has(self, flag: Self) -> bool {
        self.contains(flag)
    }
}

impl BitOrAssign for FoldFlags {
    fn bitor_assign(&mut self, other: Self) {
        self.0 |= other.0;
    }
}

/// Whether a ray's returned `colour`, under the `clamp` convention, may be another
/// colour under the other clamp. Per pixel: unless clamping it changes no bit. Per ray:
/// unless each channel lies strictly inside (0, 1), where the clamp did nothing (a 0 or
/// a 1 may be a clamped value).
fn clamp_matters(colour: DVec3, clamp: ClampConvention) -> bool {
    match clamp {
        ClampConvention::Pixel => {
            let clamped = colour.clamp(DVec3::ZERO, DVec3::ONE);
            clamped.to_array().map(f64::to_bits) != colour.to_array().map(f64::to_bits)
        }
        ClampConvention::EachRay => {
            !colour.cmpgt(DVec3::ZERO).all() || !colour.cmplt(DVec3::ONE).all()
        }
    }
}

/// A recorder that passes every call on to `inner` and notes what of the tree depends
/// on the conventions (the clamp the tree is folded with is `clamp`).
pub struct FoldWatch<'r, R: Recorder> {
    inner: &'r mut R,
    clamp: ClampConvention,
    /// What the trees watched so far depend on.
    pub flags: FoldFlags,
}

impl<'r, R: Recorder> FoldWatch<'r, R> {
    /// Watches the trees `inner` records, folded with the `clamp` convention.
    pub fn new(inner: &'r mut R, clamp: ClampConvention) -> Self {
        Self {
            inner,
            clamp,
            flags: FoldFlags::default(),
        }
    }
}

impl<R: Recorder> Recorder for FoldWatch<'_, R> {
    const ACTIVE: bool = R::ACTIVE;

    #[inline]
    fn started(&mut self, node: u32, depth: u32, from: Option<(u32, Branch)>) {
        if matches!(from, Some((_, Branch::Mirror))) {
            self.flags |= FoldFlags::MIRROR;
        }
        self.inner.started(node, depth, from);
    }

    #[inline]
    fn hit(&mut self, node: u32, ray: &Ray, hit: &SurfacePoint) {
        self.inner.hit(node, ray, hit);
    }

    #[inline]
    fn miss(&mut self, node: u32, ray: &Ray, background: DVec3) {
        self.inner.miss(node, ray, background);
    }

    #[inline]
    fn ambient(&mut self, node: u32, colour: DVec3) {
        self.inner.ambient(node, colour);
    }

    #[inline]
    fn light(&mut self, node: u32, record: &LightRecord) {
        self.inner.light(node, record);
    }

    #[inline]
    fn sphere_shadow_ray(&mut self, node: u32, light: usize, ray: &ShadowRay) {
        self.inner.sphere_shadow_ray(node, light, ray);
    }

    #[inline]
    fn skipped_light(&mut self, node: u32, skipped: &SkippedLight) {
        self.inner.skipped_light(node, skipped);
    }

    #[inline]
    fn reflection(&mut self, node: u32, km: DVec3, reflected: DVec3) {
        self.inner.reflection(node, km, reflected);
    }

    #[inline]
    fn transmission(&mut self, node: u32, kt: DVec3, transmitted: DVec3, branch: Branch) {
        self.inner.transmission(node, kt, transmitted, branch);
    }

    #[inline]
    fn result(&mut self, node: u32, colour: DVec3) {
        if clamp_matters(colour, self.clamp) {
            self.flags |= FoldFlags::UNCLAMPED;
        }
        self.inner.result(node, colour);
    }

    #[inline]
    fn clamped(&mut self, node: u32, unclamped: DVec3) {
        self.flags |= FoldFlags::UNCLAMPED;
        self.inner.clamped(node, unclamped);
    }
}

/// [`trace_again`]'s colour of `ray` in `world`, bit for bit (the same tracer, a
/// recorder that records nothing), adding what its tree depends on to `flags` (unless
/// they already say the sample depends on every convention).
pub fn trace_again_watched(world: &World, ray: &Ray, flags: &mut FoldFlags) -> DVec3 {
    if flags.depends_on_all() {
        return trace_again(world, ray);
    }
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    let mut nothing = NoRecorder;
    let mut watch = FoldWatch::new(&mut nothing, world.conventions.clamp);
    let colour = tracer.trace_primary(ray, &mut RayCounts::default(), &mut watch);
    *flags |= watch.flags;
    colour
}
