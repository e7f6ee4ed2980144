//! Lights: the four kinds of the contract; a Point's and a Spot's shared fields in one
//! [`LightSource`].

use glam::DVec3;

/// A light. Strength is `colour * intensity`; point and spot lights fall off as 1/d^2.
///
/// Files hold the fields of each kind side by side (`Point(position: .., colour: ..,
/// radius: ..)`, see `SCENE_FORMAT.md`); in memory a Point's and a Spot's shared fields
/// are one [`LightSource`]. Its `Serialize` and `Deserialize` are in `light_file`, which
/// converts, so files read and write as before.
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// Adds `ka * colour * intensity` everywhere.
    Ambient {
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        intensity: f64,
    },
    /// A point light.
    Point {
        /// World position.
        position: DVec3,
        /// What it emits, and the size of the sphere it emits from.
        source: LightSource,
    },
    /// A light at infinity; `direction` is the way the light travels.
    Directional {
        /// The way the light travels (need not be unit length).
        direction: DVec3,
        /// Light colour (linear RGB, may exceed 1).
        colour: DVec3,
        /// Multiplier of `colour`.
        intensity: f64,
    },
    /// A point light restricted to a cone with a hard edge.
    Spot {
        /// World position of the apex.
        position: DVec3,
        /// Axis of the cone: the way the light travels.
        direction: DVec3,
        /// Half-angle of the cone in degrees, in (0, 180]: 90 lights a half-space, 180
        /// every direction.
        angle_deg: f64,
        /// What it emits, and the size of the sphere it emits from.
        source: LightSource,
    },
}

/// The fields a Point and a Spot light share: what the light emits (`colour *
/// intensity`) and the sphere it emits from (`radius`, sampled by `samples` shadow rays).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSource {
    /// Light colour (linear RGB, may exceed 1).
    pub colour: DVec3,
    /// Multiplier of `colour`; default 1 in files.
    pub intensity: f64,
    /// Radius of the light's sphere; 0 (the default) is a point.
    pub radius: f64,
    /// Shadow rays per shading point for a sphere light; default 1.
    pub samples: u32,
}

impl LightSource {
    /// A source of no size (radius 0, one shadow ray) emitting `colour * intensity`.
    #[must_use]
    pub fn point(colour: DVec3, intensity: f64) -> Self {
        Self {
            colour,
            intensity,
            radius: 0.0,
            samples: 1,
        }
    }
}

/// The four kinds of light, without their values: for menus, messages and importers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightKind {
    /// [`Light::Ambient`].
    Ambient,
    /// [`Light::Point`].
    Point,
    /// [`Light::Directional`].
    Directional,
    /// [`Light::Spot`].
    Spot,
}

impl LightKind {
    /// Every kind, in menu order.
    pub const ALL: [LightKind; 4] = [
        LightKind::Ambient,
        LightKind::Point,
        LightKind::Directional,
        LightKind::Spot,
    ];

    /// The kind's name, as in files: the variant name of [`Light`].
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LightKind::Ambient => "Ambient",
            LightKind::Point => "Point",
            LightKind::Directional => "Directional",
            LightKind::Spot => "Spot",
        }
    }
}

impl Light {
    /// Which kind of light this is.
    #[must_use]
    pub fn kind(&self) -> LightKind {
        match self {
            Light::Ambient { .. } => LightKind::Ambient,
            Light::Point { .. } => LightKind::Point,
            Light::Directional { .. } => LightKind::Directional,
            Light::Spot { .. } => LightKind::Spot,
        }
    }

    /// The kind's name, as in files and menus.
    #[must_use]
    pub fn kind_name(&self) -> &'static str {
        self.kind().name()
    }

    /// The light's colour, before `intensity`.
    #[must_use]
    pub fn colour(&self) -> DVec3 {
        self.colour_and_intensity().0
    }

    /// The multiplier of the light's colour.
    #[must_use]
    pub fn intensity(&self) -> f64 {
        self.colour_and_intensity().1
    }

    /// The two fields every kind of light has.
    fn colour_and_intensity(&self) -> (DVec3, f64) {
        match *self {
            Light::Ambient {
                colour, intensity, ..
            }
            | Light::Directional {
                colour, intensity, ..
            } => (colour, intensity),
            Light::Point { source, .. } | Light::Spot { source, .. } => {
                (source.colour, source.intensity)
            }
        }
    }

    /// For a Point or Spot light with a radius: the sphere's radius and the shadow rays
    /// per shading point. `None` for a point (radius 0) and for the other kinds.
    #[must_use]
    pub fn sphere(&self) -> Option<(f64, u32)> {
        match *self {
            Light::Point { source, .. } | Light::Spot { source, .. } if source.radius > 0.0 => {
                Some((source.radius, source.samples))
            }
            _ => None,
        }
    }

    /// The light's colour times its intensity.
    #[must_use]
    pub fn strength(&self) -> DVec3 {
        self.colour() * self.intensity()
    }
}
