//! The catalogue of known renderer bugs, each a different way of computing raylab's own
//! numbers: a normal computed wrongly, a specular lobe with the wrong reflected vector,
//! colour clamped at the wrong time, a part of a shape that is never hit. The fit tries
//! each as a whole picture of the difference; a bug that is there explains it with a
//! weight near 1.

use glam::DVec3;

use crate::scene::Material;
use crate::trace::SurfacePoint;
use crate::trace::shapes::Primitive;
use crate::trace::{LocalLight, phong_power};
use crate::trace::{Ray, World, WorldObject};

/// A wrong shading normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NormalBug {
    /// The outward normal is used as is, not turned to face the ray (dark back faces).
    NotFlipped,
    /// The object-space normal lacks its x component.
    DropX,
    /// The object-space normal lacks its y component.
    DropY,
    /// The object-space normal lacks its z component (e.g. a cone's side).
    DropZ,
    /// The normal is taken to world space by the object-to-world matrix instead of its
    /// inverse transpose (wrong under non-uniform scale).
    ObjectMatrix,
}

impl NormalBug {
    /// Every normal bug.
    pub const ALL: [NormalBug; 5] = [
        NormalBug::NotFlipped,
        NormalBug::DropX,
        NormalBug::DropY,
        NormalBug::DropZ,
        NormalBug::ObjectMatrix,
    ];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            NormalBug::NotFlipped => "normal-not-flipped",
            NormalBug::DropX => "normal-without-x",
            NormalBug::DropY => "normal-without-y",
            NormalBug::DropZ => "normal-without-z",
            NormalBug::ObjectMatrix => "normal-by-object-matrix",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            NormalBug::NotFlipped => "its normal is not turned to face the ray",
            NormalBug::DropX => "its object-space normal lacked its x component",
            NormalBug::DropY => "its object-space normal lacked its y component",
            NormalBug::DropZ => "its object-space normal lacked its z component",
            NormalBug::ObjectMatrix => {
                "its normal were transformed by the object matrix, not its inverse transpose"
            }
        }
    }

    /// The shading normal (facing the ray) the bug gives at `hit`, or `None` where it
    /// gives raylab's or no usable normal.
    #[must_use]
    pub fn normal(self, hit: &SurfacePoint, ray_dir: DVec3, object: &WorldObject) -> Option<DVec3> {
        let m = object.world_from_object.matrix3;
        let n_object = (m.transpose() * hit.n_outward).normalize_or_zero();
        let drop = |axis: usize| {
            let mut n = n_object;
            n[axis] = 0.0;
            // A normal that loses almost all of its length is a different bug (a cap).
            (n.length() > 0.2).then(|| (object.normal_from_object * n).normalize_or_zero())
        };
        let outward = match self {
            NormalBug::NotFlipped => return (hit.n != hit.n_outward).then_some(hit.n_outward),
            NormalBug::DropX => drop(0)?,
            NormalBug::DropY => drop(1)?,
            NormalBug::DropZ => drop(2)?,
            NormalBug::ObjectMatrix => (m * n_object).normalize_or_zero(),
        };
        let facing = if outward.dot(ray_dir) > 0.0 {
            -outward
        } else {
            outward
        };
        (facing != DVec3::ZERO && (facing - hit.n).length() > 1e-9).then_some(facing)
    }
}

/// A wrong specular lobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpecularBug {
    /// `r = l - 2 (n.l) n`: the light direction reflected the wrong way (or `r.d` with
    /// the ray direction `d` instead of the view vector).
    NegatedReflection,
    /// Blinn-Phong `(n.h)^s` with `h = (l + v) / |l + v|` instead of Phong.
    HalfVector,
    /// `max(0, (r.v)^s)` instead of `max(0, r.v)^s`: even exponents light the back of
    /// the lobe.
    NoMaxBeforePower,
    /// `r = 2 (n.l) (n - l)`: the `- l` put inside the product, not normalised (a
    /// common slip writing `2(n.l)n - l`).
    NMinusL,
}

impl SpecularBug {
    /// Every specular bug.
    pub const ALL: [SpecularBug; 4] = [
        SpecularBug::NegatedReflection,
        SpecularBug::HalfVector,
        SpecularBug::NoMaxBeforePower,
        SpecularBug::NMinusL,
    ];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SpecularBug::NegatedReflection => "reflected-vector-negated",
            SpecularBug::HalfVector => "half-vector",
            SpecularBug::NoMaxBeforePower => "no-max-before-power",
            SpecularBug::NMinusL => "reflected-vector-n-minus-l",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            SpecularBug::NegatedReflection => {
                "the specular term used the wrong reflected vector, l - 2(n.l)n instead of 2(n.l)n - l"
            }
            SpecularBug::HalfVector => "the specular term used Blinn's half vector instead of r.v",
            SpecularBug::NoMaxBeforePower => "the specular term took the power before max(0, r.v)",
            SpecularBug::NMinusL => {
                "the specular term used the wrong reflected vector, 2(n.l)(n - l) instead of 2(n.l)n - l"
            }
        }
    }

    /// The specular term under the bug for a visible light with n.l > 0.
    #[must_use]
    pub fn specular(self, material: &Material, light: &LocalLight) -> DVec3 {
        let LocalLight {
            n,
            to_light,
            view,
            strength,
        } = *light;
        let s = material.shininess;
        let lobe = match self {
            SpecularBug::NegatedReflection => {
                let r = to_light - 2.0 * n.dot(to_light) * n;
                phong_power(r.dot(view).max(0.0), s)
            }
            SpecularBug::HalfVector => {
                let h = (to_light + view).normalize_or_zero();
                phong_power(n.dot(h).max(0.0), s)
            }
            SpecularBug::NMinusL => {
                let r = 2.0 * n.dot(to_light) * (n - to_light);
                phong_power(r.dot(view).max(0.0), s)
            }
            SpecularBug::NoMaxBeforePower => {
                let r_dot_v = (2.0 * n.dot(to_light) * n - to_light).dot(view);
                if s.fract() == 0.0 && s <= 1024.0 {
                    r_dot_v.powi(s as i32).max(0.0)
                } else {
                    phong_power(r_dot_v.max(0.0), s)
                }
            }
        };
        if lobe > 0.0 {
            material.specular * strength * lobe
        } else {
            DVec3::ZERO
        }
    }
}

/// Colour clamped to [0, 1] (or cut to 8 bits) before the final pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClampBug {
    /// Each ray's local colour is clamped before the reflection is added.
    LocalBeforeReflection,
    /// Each ray's whole colour is clamped before its mirror multiplies it.
    EveryRay,
    /// Each reflected ray's colour is clamped and truncated to 8 bits per channel,
    /// `floor(255 c) / 255`, before its mirror multiplies it (a colour kept as bytes
    /// between rays). The camera ray's own colour is the encoding's to write.
    TruncateEachRay,
}

impl ClampBug {
    /// Every clamping bug.
    pub const ALL: [ClampBug; 3] = [
        ClampBug::LocalBeforeReflection,
        ClampBug::EveryRay,
        ClampBug::TruncateEachRay,
    ];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ClampBug::LocalBeforeReflection => "clamp-before-reflection",
            ClampBug::EveryRay => "clamp-every-ray",
            ClampBug::TruncateEachRay => "truncate-each-ray",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            ClampBug::LocalBeforeReflection => {
                "colour was clamped per ray before the reflection was added"
            }
            ClampBug::EveryRay => {
                "each reflected ray's colour was clamped before the mirror scaled it"
            }
            ClampBug::TruncateEachRay => {
                "each reflected ray's colour was cut to 8 bits, floor(255 c) / 255 per channel, before the mirror scaled it"
            }
        }
    }

    /// A ray's colour under the bug: `local` its own terms, `km` and `reflected` its
    /// mirror term (the reflected colour as the bug computed it), if any; `camera`
    /// for the camera ray (whose colour the picture's encoding writes).
    #[must_use]
    pub fn combine(self, local: DVec3, mirror: Option<(DVec3, DVec3)>, camera: bool) -> DVec3 {
        let clamp = |c: DVec3| c.clamp(DVec3::ZERO, DVec3::ONE);
        let reflected = mirror.map_or(DVec3::ZERO, |(km, c)| km * c);
        match self {
            ClampBug::LocalBeforeReflection => clamp(local) + reflected,
            ClampBug::EveryRay => clamp(local + reflected),
            ClampBug::TruncateEachRay if camera => clamp(local + reflected),
            ClampBug::TruncateEachRay => (clamp(local + reflected) * 255.0).floor() / 255.0,
        }
    }
}

/// A wrong shadow test.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadowBug {
    /// The shadow ray skips the object it leaves: no object shadows itself (a hollow
    /// solid, a torus, a CSG object lit inside).
    NoSelfShadow,
    /// The shadow ray starts at the hit point itself, with no offset: it meets the
    /// surface it leaves at random (speckled self-shadowing, acne).
    Acne,
    /// The shadow ray is blocked by any hit along it, even beyond the light.
    BeyondLight,
}

impl ShadowBug {
    /// Every shadow bug.
    pub const ALL: [ShadowBug; 3] = [
        ShadowBug::NoSelfShadow,
        ShadowBug::Acne,
        ShadowBug::BeyondLight,
    ];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ShadowBug::NoSelfShadow => "no-self-shadow",
            ShadowBug::Acne => "shadow-acne",
            ShadowBug::BeyondLight => "shadow-beyond-light",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            ShadowBug::NoSelfShadow => {
                "its shadow rays skipped the object they left, so it never shadowed itself"
            }
            ShadowBug::Acne => {
                "its shadow rays started on the surface with no offset (shadow acne)"
            }
            ShadowBug::BeyondLight => "its shadow rays counted hits beyond the light",
        }
    }
}

/// A secondary ray started wrongly.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpawnBug {
    /// The mirror ray starts on the wrong side of the surface (`p - eps n`): it meets
    /// the surface it leaves from behind, so a mirror shows its own inside (a sphere's
    /// ambient, a plane's unlit back) instead of what it faces.
    MirrorWrongSide,
}

impl SpawnBug {
    /// Every spawning bug.
    pub const ALL: [SpawnBug; 1] = [SpawnBug::MirrorWrongSide];

    /// A short name for reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SpawnBug::MirrorWrongSide => "mirror-ray-wrong-side",
        }
    }

    /// What the bug is, as the end of a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            SpawnBug::MirrorWrongSide => {
                "its mirror rays started on the wrong side of the surface, so they met it again from behind"
            }
        }
    }

    /// The ray the bug starts at `hit` (seen along a ray with shading normal `hit.n`
    /// facing it) in direction `dir`: moved off the surface against `hit.n` by a
    /// distance a student's `eps` would be, large enough that the surface is met again
    /// whatever the rounding of its hit.
    #[must_use]
    pub fn ray(self, hit: &SurfacePoint, dir: DVec3) -> Ray {
        match self {
            SpawnBug::MirrorWrongSide => {
                let eps = WRONG_SIDE_EPS * (1.0 + hit.p.abs().max_element());
                Ray::new(hit.p - eps * hit.n, dir)
            }
        }
    }
}

/// A student's offset along the normal, relative to the point's size.
const WRONG_SIDE_EPS: f64 = 1e-5;

/// A part of a shape, which a renderer may fail to hit on its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    /// The whole of a sphere or cube.
    Whole,
    /// A plane seen from the side its normal points to.
    Front,
    /// A plane seen from behind.
    Back,
    /// The curved side of a cylinder, cone or tube.
    Side,
    /// The disc caps of a cylinder or cone, or a tube's rings.
    Caps,
}

impl Part {
    /// Every part.
    pub const ALL: [Part; 5] = [Part::Whole, Part::Front, Part::Back, Part::Side, Part::Caps];

    /// The parts a shape is made of.
    #[must_use]
    pub fn of_shape(shape: Primitive) -> &'static [Part] {
        match shape {
            Primitive::Sphere
            | Primitive::Cube
            | Primitive::Octahedron
            | Primitive::Torus { .. }
            | Primitive::Mesh => &[Part::Whole],
            Primitive::Plane => &[Part::Front, Part::Back],
            Primitive::Cylinder | Primitive::Cone | Primitive::Tube { .. } => {
                &[Part::Side, Part::Caps]
            }
        }
    }

    /// The parts of leaf `leaf` of `world`'s trees: a world object's own shape's; an
    /// operand of a CSG object is missing whole.
    #[must_use]
    pub fn of_leaf(world: &World, leaf: &super::nodes::Leaf) -> &'static [Part] {
        let object = &world.objects[leaf.world_object];
        if object.csg.is_some() {
            &[Part::Whole]
        } else {
            Part::of_shape(object.shape)
        }
    }

    /// The part of `object` that `hit` (made by a ray along `ray_dir`) lies on.
    #[must_use]
    pub fn at(object: &WorldObject, hit: &SurfacePoint, ray_dir: DVec3) -> Part {
        let n_object =
            (object.world_from_object.matrix3.transpose() * hit.n_outward).normalize_or_zero();
        match object.shape {
            Primitive::Sphere
            | Primitive::Cube
            | Primitive::Octahedron
            | Primitive::Torus { .. }
            | Primitive::Mesh => Part::Whole,
            Primitive::Plane if hit.n_outward.dot(ray_dir) < 0.0 => Part::Front,
            Primitive::Plane => Part::Back,
            // Cap normals are +-z; side normals have |z| of 0 (cylinder) or 1/sqrt 2 (cone,
            // pointing to -z).
            // A tube's rings are caps, its two barrels its side.
            Primitive::Cylinder | Primitive::Tube { .. } if n_object.z.abs() > 0.9 => Part::Caps,
            Primitive::Cone if n_object.z > 0.9 => Part::Caps,
            Primitive::Cylinder | Primitive::Cone | Primitive::Tube { .. } => Part::Side,
        }
    }

    /// The part's name in a sentence.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Part::Whole => "the whole object",
            Part::Front => "the front (normal side)",
            Part::Back => "the back",
            Part::Side => "the side",
            Part::Caps => "the caps",
        }
    }
}

/// The diffuse and specular terms of the contract for a visible light with normal `n`
/// (zero where n.l <= 0).
#[must_use]
pub fn local_terms(material: &Material, light: &LocalLight) -> (DVec3, DVec3) {
    let n_dot_l = light.n.dot(light.to_light);
    if n_dot_l <= 0.0 {
        return (DVec3::ZERO, DVec3::ZERO);
    }
    (
        light.diffuse(material.diffuse, n_dot_l),
        light.specular(material.specular, material.shininess, n_dot_l),
    )
}
