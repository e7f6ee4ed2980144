//! The legacy COSC342 importer's errors: every kind reported with its line and token, all
//! of a file's problems at once and in line order, values a scene cannot hold, and input
//! that is not a legacy file at all.

mod common;

use std::path::Path;

use common::legacy::{assert_one_error, errors_of_file, errors_of_text, legacy_path};
use raylab::scene::legacy::{LegacyImportFileError, import_legacy, import_legacy_file};
use raylab::scene::validate;

#[test]
fn each_error_file_reports_its_one_error_at_its_line_and_token() {
    let cases: &[(&str, usize, &str, &str)] = &[
        ("err_bad_number.txt", 2, "1,0", "not a number"),
        ("err_wrong_count.txt", 2, "Translate", "found 2"),
        ("err_missing_end.txt", 5, "Object", "no `End`"),
        (
            "err_missing_end_inside.txt",
            4,
            "Object",
            "`End` of the Object block at line 1 missing",
        ),
        (
            "err_after_last_end.txt",
            4,
            "Scale",
            "unexpected end of file",
        ),
        (
            "err_material_before_definition.txt",
            2,
            "gold",
            "before it is defined (its definition is at line 5)",
        ),
        ("err_zero_scale.txt", 2, "0", "singular"),
    ];
    for &(file, line, token, fragment) in cases {
        assert_one_error(&errors_of_file(file), line, token, fragment);
    }
}

#[test]
fn every_error_is_reported_in_line_order() {
    let errors = errors_of_file("err_many.txt");
    let summary: Vec<(usize, &str)> = errors
        .0
        .iter()
        .map(|e| (e.line, e.token.as_str()))
        .collect();
    assert_eq!(
        summary,
        [
            (3, "0"),
            (6, "W"),
            (9, "nowhere"),
            (10, "-1"),
            (12, "PointLight")
        ],
        "{errors}"
    );
    assert_eq!(errors.to_string().lines().count(), 5);
}

#[test]
fn values_the_scene_format_cannot_hold_are_errors_at_their_token() {
    let cases: &[(&str, usize, &str, &str)] = &[
        ("Scene\nrayDepth 2.5\nEnd", 2, "2.5", "whole number"),
        (
            "Scene\nrayDepth -1\nEnd",
            2,
            "-1",
            "whole number, 0 or more",
        ),
        ("Scene\nbackgroundColour 0 0 -1\nEnd", 2, "-1", "negative"),
        (
            "Camera PinholeCamera 0\nEnd",
            1,
            "0",
            "focal length must be positive",
        ),
        ("Camera PinholeCamera\nEnd", 1, "PinholeCamera", "found 0"),
        ("Camera Fisheye 1\nEnd", 1, "Fisheye", "unknown camera type"),
        ("Light NeonLight\nEnd", 1, "NeonLight", "unknown light type"),
        ("Object Torus\nEnd", 1, "Torus", "takes R"),
        ("Object Tube 2\nEnd", 1, "2", "between 0 and 2"),
        ("Object Mesh\nEnd", 1, "Mesh", "takes PATH"),
        (
            "Object Sphere Opacity 1.5\nEnd",
            1,
            "1.5",
            "from 0 (clear) to 1",
        ),
        (
            "Material m RefractiveIndex 0\nEnd",
            1,
            "0",
            "refractive index",
        ),
        ("Scene FSAA 0\nEnd", 1, "0", "whole number, 1 or more"),
        ("Scene scaleResolution -2\nEnd", 1, "-2", "more than 0"),
        (
            "Light PointLight Colour 1 1 1 Location 0 0 0 Radius -1\nEnd",
            1,
            "-1",
            "negative",
        ),
        (
            "CSG Xor Object Sphere End End",
            1,
            "Xor",
            "Union, Intersection or Difference",
        ),
        (
            "ObjectGroup Object Sphere End",
            1,
            "ObjectGroup",
            "no `End`",
        ),
        ("Object Sphere 2\nEnd", 1, "2", "takes no numbers"),
        ("Light\nEnd", 1, "Light", "needs a light type"),
        (
            "Light DirectionalLight Colour 1 1 1\nDirection 0 0 0\nEnd",
            2,
            "Direction",
            "zero",
        ),
        (
            "Light DirectionalLight\nColour 1 1 1\nEnd",
            1,
            "DirectionalLight",
            "needs a `Direction`",
        ),
        (
            "Light PointLight\nLocation 1 1 1\nEnd",
            1,
            "PointLight",
            "needs a `Colour`",
        ),
        (
            "Light SpotLight Colour 1 1 1 Location 0 0 0 Direction 0 0 1\nAngle 180.5\nEnd",
            2,
            "180.5",
            "at most 180",
        ),
        (
            "Light SpotLight Colour 1 1 1 Location 0 0 0 Direction 0 0 1\nAngle 0\nEnd",
            2,
            "0",
            "more than 0",
        ),
        (
            "Material m\nSpecular 1 1 1 -2\nEnd",
            2,
            "-2",
            "exponent cannot be negative",
        ),
        ("Object Sphere\nMaterial\nEnd", 2, "Material", "takes NAME"),
        (
            "Object Sphere\nRotate 30\nEnd",
            2,
            "Rotate",
            "an axis and a number",
        ),
        (
            "Object Sphere\nScale 1e999\nEnd",
            2,
            "1e999",
            "out of range",
        ),
        (
            "Scene\nrenderSize 20000 10\nEnd",
            2,
            "20000",
            "from 1 to 16384",
        ),
        ("Object Sphere End\nEnd", 2, "End", "no block before it"),
        (
            "Object Sphere\nScale 1e-200\nScale 1e-200\nEnd",
            1,
            "Sphere",
            "cannot be imported",
        ),
        (
            "Camera PinholeCamera 1e-300\nEnd",
            1,
            "PinholeCamera",
            "camera cannot be imported",
        ),
    ];
    for &(text, line, token, fragment) in cases {
        let errors = errors_of_text(text);
        assert_eq!(errors.0.len(), 1, "{text:?}: {errors}");
        let message = errors.to_string();
        assert!(
            message.starts_with(&format!("line {line}: `{token}`: ")) && message.contains(fragment),
            "{text:?}: {message}"
        );
    }
}

#[test]
fn a_wrong_keyword_is_not_also_reported_missing_but_other_missing_ones_are() {
    let errors = errors_of_text("Light SpotLight\nColour 1 x 1\nDirection 0 0 1\nEnd");
    let summary: Vec<(usize, &str)> = errors
        .0
        .iter()
        .map(|e| (e.line, e.token.as_str()))
        .collect();
    // `Colour 1` has one number, then `x` is an unknown keyword (skipped with a warning,
    // the issue 38 policy); the missing Location counts, the wrong Colour is not
    // reported a second time as missing.
    assert_eq!(summary, [(1, "SpotLight"), (2, "Colour")], "{errors}");
    assert!(errors.0[0].message.contains("`Location`"), "{errors}");
    // A wrong Angle is one error, not also a missing Angle (nor the unlit-spot warning).
    let errors = errors_of_text(
        "Light SpotLight Colour 1 1 1 Location 0 0 0 Direction 0 0 1\nAngle -3\nEnd",
    );
    assert_one_error(&errors, 2, "-3", "more than 0");
}

#[test]
fn unreadable_and_non_utf8_files_are_errors() {
    let missing = import_legacy_file(&legacy_path("no such file.txt"));
    assert!(
        matches!(missing, Err(LegacyImportFileError::Read { .. })),
        "{missing:?}"
    );

    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("legacy_latin1.txt");
    std::fs::write(&path, b"Material caf\xe9\nEnd\n").expect("write temp file");
    match import_legacy_file(&path) {
        Err(LegacyImportFileError::NotText { line, .. }) => assert_eq!(line, 1),
        other => panic!("expected NotText, got {other:?}"),
    }
}

#[test]
fn arbitrary_bytes_never_panic() {
    // A handful of nasty inputs: every one either imports or reports errors.
    for text in [
        "",
        "End",
        "End End",
        "#",
        "Scene",
        "Object",
        "Object Sphere Material",
        "Rotate X",
        "Camera PinholeCamera 1 Rotate",
        "Object Sphere Scale3 1e308 1e308 1e308 Scale 1e308 End",
        "Light SpotLight Angle nan End",
        "\u{feff}Scene End",
        "Object Sphere Translate - + . End",
    ] {
        if let Ok(import) = import_legacy(text) {
            validate(&import.scene).unwrap_or_else(|e| panic!("{text:?}: {e}"));
        }
    }
}
