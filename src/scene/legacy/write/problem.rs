//! What an export loses: a refusal (the dialect cannot say it, so nothing is written) or
//! a warning (written, with a named loss), each naming the object, light, material or
//! setting it is about.

use std::fmt;

/// What a problem is about, named as the user knows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Subject {
    /// An object, by its tree path (`"snowman/body"`).
    Object(String),
    /// A light, by its 0-based place in the scene's list and its kind.
    Light {
        /// Its place in `Scene::lights`.
        index: usize,
        /// Its kind's name (`"Spot"`).
        kind: &'static str,
    },
    /// A material, by its name in the scene.
    Material(String),
    /// The camera.
    Camera,
    /// The render settings (size, depth, background, anti-aliasing, conventions).
    Render,
    /// The scene as a whole.
    Scene,
}

impl fmt::Display for Subject {
    /// `object "snowman/body"`, `light 2 (Spot)`, `material "glass"`, `camera`,
    /// `render settings`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Subject::Object(path) => write!(f, "object \"{path}\""),
            Subject::Light { index, kind } => write!(f, "light {index} ({kind})"),
            Subject::Material(name) => write!(f, "material \"{name}\""),
            Subject::Camera => f.write_str("camera"),
            Subject::Render => f.write_str("render settings"),
            Subject::Scene => f.write_str("scene"),
        }
    }
}

/// One thing the course format cannot say as the scene has it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// What it is about.
    pub subject: Subject,
    /// What is lost or changed, and why.
    pub message: String,
}

impl Problem {
    /// A problem about `subject`.
    #[must_use]
    pub fn new(subject: Subject, message: impl Into<String>) -> Self {
        Self {
            subject,
            message: message.into(),
        }
    }
}

impl fmt::Display for Problem {
    /// `subject: message`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.subject, self.message)
    }
}

/// Why a scene could not be written in a dialect: everything it cannot say, and the
/// warnings found on the way (what else would have been lost).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", lines(refusals))]
pub struct CourseExportError {
    /// What the dialect cannot say; never empty.
    pub refusals: Vec<Problem>,
    /// What would have been written with a loss.
    pub warnings: Vec<Problem>,
}

fn lines(problems: &[Problem]) -> String {
    problems
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("\n")
}

/// Problems collected while writing: refusals and warnings.
#[derive(Default)]
pub(super) struct Problems {
    pub(super) refusals: Vec<Problem>,
    pub(super) warnings: Vec<Problem>,
}

impl Problems {
    /// Something the dialect cannot say: nothing will be written.
    pub(super) fn refuse(&mut self, subject: Subject, message: impl Into<String>) {
        self.refusals.push(Problem::new(subject, message));
    }

    /// Something written with a loss.
    pub(super) fn warn(&mut self, subject: Subject, message: impl Into<String>) {
        self.warnings.push(Problem::new(subject, message));
    }
}
