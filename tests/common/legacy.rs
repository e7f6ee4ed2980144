//! Helpers for the legacy importer's tests: the files in `tests/legacy`, importing them,
//! their errors, and the materials and transforms they should give.

use std::path::{Path, PathBuf};

use glam::DVec3;
use raylab::scene::legacy::{
    LegacyErrors, LegacyImport, LegacyImportFileError, import_legacy, import_legacy_file,
};
use raylab::scene::{Material, Scene, Transform, Trs};
use raylab::trace::{Image, RenderOptions, RenderProgress, World, render};

/// The path of a file in `tests/legacy`.
pub fn legacy_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/legacy")
        .join(name)
}

/// The text of a file in `tests/legacy`.
pub fn legacy_text(name: &str) -> String {
    std::fs::read_to_string(legacy_path(name)).unwrap_or_else(|e| panic!("read {name}: {e}"))
}

/// Imports a file in `tests/legacy`, which must import.
pub fn import_file(name: &str) -> LegacyImport {
    match import_legacy_file(&legacy_path(name)) {
        Ok(import) => import,
        Err(e) => panic!("{name} should import: {e}"),
    }
}

/// Imports legacy text, which must import.
pub fn import_text(text: &str) -> LegacyImport {
    import_legacy(text).unwrap_or_else(|e| panic!("should import:\n{e}"))
}

/// The errors of legacy text, which must not import.
pub fn errors_of_text(text: &str) -> LegacyErrors {
    match import_legacy(text) {
        Ok(import) => panic!("should fail, imported {:?}", import.scene),
        Err(errors) => errors,
    }
}

/// The errors of a file in `tests/legacy`, which must not import.
pub fn errors_of_file(name: &str) -> LegacyErrors {
    match import_legacy_file(&legacy_path(name)) {
        Err(LegacyImportFileError::Legacy { errors, .. }) => errors,
        other => panic!("{name} should fail with legacy errors, got {other:?}"),
    }
}

/// Asserts exactly one error, at `line` on `token`, whose text contains `fragment`.
pub fn assert_one_error(errors: &LegacyErrors, line: usize, token: &str, fragment: &str) {
    assert_eq!(errors.0.len(), 1, "{errors}");
    let text = errors.to_string();
    assert!(
        text.starts_with(&format!("line {line}: `{token}`: ")),
        "{text}"
    );
    assert!(text.contains(fragment), "{text} lacks {fragment:?}");
}

/// Asserts two vectors agree to a relative 1e-12.
pub fn assert_vec(actual: DVec3, expected: DVec3) {
    assert!(
        (actual - expected).abs().max_element() <= 1e-12 * expected.abs().max_element().max(1.0),
        "{actual} expected {expected}"
    );
}

/// A translate / rotate / scale transform.
pub fn trs(translate: [f64; 3], rotate_deg: [f64; 3], scale: [f64; 3]) -> Transform {
    Transform::Trs(Trs {
        translate: DVec3::from(translate),
        rotate_deg: DVec3::from(rotate_deg),
        scale: DVec3::from(scale),
    })
}

/// A material from its five fields.
pub fn material(
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    shininess: f64,
    mirror: DVec3,
) -> Material {
    Material {
        ambient,
        diffuse,
        specular,
        shininess,
        mirror,
        transmission: DVec3::ZERO,
        ior: 1.0,
    }
}

/// The legacy default material.
pub fn magenta() -> Material {
    let m = DVec3::new(1.0, 0.0, 1.0);
    material(m, m, DVec3::ZERO, 1.0, DVec3::ZERO)
}

/// Renders a scene at its own size and settings.
pub fn render_scene(scene: &Scene) -> Image {
    let world = World::new(scene).expect("imported scenes are valid");
    let options = RenderOptions::from_scene(scene);
    render(&world, &options, &RenderProgress::default())
        .expect("not cancelled")
        .0
}
