//! How a failed check reads: an `Invalid` error, prefixed with where it failed, and the
//! names the check knew of.

use super::super::error::SceneError;

/// A failed check with its message.
pub(super) fn invalid<T>(message: String) -> Result<T, SceneError> {
    Err(SceneError::Invalid(message))
}

/// The message of a failed check, prefixed with where it failed (`lights[0] (Point)`).
pub(super) fn prefixed(at: &str, error: SceneError) -> SceneError {
    match error {
        SceneError::Invalid(message) => SceneError::Invalid(format!("{at}: {message}")),
        other => other,
    }
}

/// Names quoted and joined by commas, or "none", for "defined: ..." hints.
pub(super) fn list_or_none<'a>(names: impl Iterator<Item = &'a String>) -> String {
    let names: Vec<String> = names.map(|n| format!("\"{n}\"")).collect();
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(", ")
    }
}
