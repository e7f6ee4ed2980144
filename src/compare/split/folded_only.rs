//! A pixel split again under other conventions at the same depth, working out only what
//! the fold changes. The channels the recorder fills while a ray is shaded (its ambient
//! term, each light's terms, shadows and bug terms) come from the same rays, hits and
//! lights under any conventions, so they are the first split's, bit for bit; only the
//! channels filled as the tree folds back (what mirrors and glass bring back, the clamp
//! bugs, the traces again without a node or with a spot light changed) are worked out
//! again. The recorder is then told nothing of the shading ([`FoldedOnly`]), which is
//! most of its work.

use glam::DVec3;

use crate::compare::catalogue::{Kind, SpotBug};
use crate::trace::{Branch, Ray, Recorder, SurfacePoint};

/// Whether the recorder fills channels of `kind` as the ray tree folds back (what the
/// conventions change), not while its rays are shaded. Every kind is named, so that a
/// new one has to be placed.
#[must_use]
pub fn filled_by_fold(kind: Kind) -> bool {
    match kind {
        Kind::Reflection
        | Kind::Transmission
        | Kind::Clamp(_)
        // A mirror ray started on the wrong side is traced again as its mirror term
        // is folded in.
        | Kind::Spawn(_)
        | Kind::Missing(_)
        | Kind::NodeMissing => true,
        // The fall-off bug is worked out from the light's terms; the cone bugs are
        // traced again from the camera ray's colour.
        Kind::Spot(bug, _) => bug != SpotBug::NoFalloff,
        Kind::Ambient
        | Kind::ShadowCast
        | Kind::Diffuse(_)
        | Kind::Specular(_)
        | Kind::Shadow(_)
        | Kind::Normal(_)
        | Kind::Highlight(_)
        | Kind::ShadowTest(_)
        | Kind::Background
        | Kind::NodeShadowCast => false,
    }
}

/// Passes on to `inner` what the fold needs (where each ray starts, what it hit, what
/// the fold brings back), and not the shading (the ambient term, the lights): the tracer
/// then builds no light records at all.
pub struct FoldedOnly<'r, R: Recorder>(pub &'r mut R);

impl<R: Recorder> Recorder for FoldedOnly<'_, R> {
    const ACTIVE: bool = false;

    #[inline]
    fn started(&mut self, node: u32, depth: u32, from: Option<(u32, Branch)>) {
        self.0.started(node, depth, from);
    }

    #[inline]
    fn hit(&mut self, node: u32, ray: &Ray, hit: &SurfacePoint) {
        self.0.hit(node, ray, hit);
    }

    #[inline]
    fn miss(&mut self, node: u32, ray: &Ray, background: DVec3) {
        self.0.miss(node, ray, background);
    }

    #[inline]
    fn reflection(&mut self, node: u32, km: DVec3, reflected: DVec3) {
        self.0.reflection(node, km, reflected);
    }

    #[inline]
    fn transmission(&mut self, node: u32, kt: DVec3, transmitted: DVec3, branch: Branch) {
        self.0.transmission(node, kt, transmitted, branch);
    }

    #[inline]
    fn result(&mut self, node: u32, colour: DVec3) {
        self.0.result(node, colour);
    }
}
