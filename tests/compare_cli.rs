//! `raylab diff` on the command line: JSON with the fields, readable lines, the
//! report image, legacy `.txt` scenes and PPM images; and for a wrong size, a missing
//! file, a non-image or a 16-bit image, a clear message and a non-zero exit.

mod common;

#[path = "compare/shader.rs"]
mod shader;

use std::path::Path;

use common::cli::{out_dir, raylab};
use shader::{Bugs, lab_scene, render as render_with};

fn lab_path() -> String {
    concat!(env!("CARGO_MANIFEST_DIR"), "/tests/compare/lab.ron").to_owned()
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn write_png(file: &Path, width: u32, height: u32, rgb: &[[u8; 3]]) {
    let flat: Vec<u8> = rgb.iter().flatten().copied().collect();
    image::RgbImage::from_raw(width, height, flat)
        .unwrap()
        .save(file)
        .unwrap();
}

fn failure(args: &[&str]) -> String {
    let result = raylab(args);
    assert!(!result.status.success(), "should fail: {args:?}");
    let stderr = String::from_utf8_lossy(&result.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

#[test]
fn json_has_the_fixed_fields_sorted_by_share_and_the_report_is_written() {
    let dir = out_dir("compare-cli");
    let scene = lab_scene();
    let other = render_with(
        &scene,
        1,
        &Bugs {
            specular_off: true,
            ..Bugs::default()
        },
    );
    let other_path = dir.join("no_specular.ppm");
    let flat: Vec<u8> = other.rgb.iter().flatten().copied().collect();
    image::RgbImage::from_raw(other.width, other.height, flat)
        .unwrap()
        .save_with_format(&other_path, image::ImageFormat::Pnm)
        .unwrap();
    let report = dir.join("report.png");
    let result = raylab(&[
        "diff",
        &lab_path(),
        path(&other_path),
        "--json",
        "-o",
        path(&report),
    ]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&result.stdout).unwrap();
    assert!(json["psnr_db"].as_f64().unwrap() < 60.0);
    assert!(json["unexplained_share"].as_f64().is_some());
    let explanations = json["explanations"].as_array().unwrap();
    assert!(!explanations.is_empty());
    for e in explanations {
        for field in [
            "term", "light", "object", "factor", "share", "pixels", "summary",
        ] {
            assert!(e.get(field).is_some(), "{field} missing in {e}");
        }
    }
    let shares: Vec<f64> = explanations
        .iter()
        .map(|e| e["share"].as_f64().unwrap())
        .collect();
    assert!(shares.windows(2).all(|w| w[0] >= w[1]), "{shares:?}");
    assert_eq!(explanations[0]["term"], "specular");
    let png = image::open(&report).unwrap();
    assert!(
        png.width() > 3 * 120 && png.height() > 90,
        "{}x{}",
        png.width(),
        png.height()
    );
}

#[test]
fn readable_lines_without_json() {
    let dir = out_dir("compare-cli");
    let scene = lab_scene();
    let other = render_with(
        &scene,
        1,
        &Bugs {
            drop_light: Some(1),
            ..Bugs::default()
        },
    );
    let other_path = dir.join("no_light.png");
    write_png(&other_path, other.width, other.height, &other.rgb);
    let result = raylab(&["diff", &lab_path(), path(&other_path), "--spp", "1"]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let text = String::from_utf8_lossy(&result.stdout);
    assert!(text.starts_with("PSNR "), "{text}");
    assert!(
        text.contains("1. ") && text.contains("diffuse (light 1"),
        "{text}"
    );
    assert!(text.contains("unexplained:"), "{text}");
}

#[test]
fn a_legacy_scene_is_imported_and_its_own_render_is_identical() {
    let dir = out_dir("compare-cli");
    let legacy = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/legacy/lit_sphere.txt");
    let ron = dir.join("lit_sphere.ron");
    assert!(
        raylab(&["import", legacy, "-o", path(&ron)])
            .status
            .success()
    );
    let png = dir.join("lit_sphere.png");
    assert!(
        raylab(&["render", path(&ron), "-o", path(&png)])
            .status
            .success()
    );
    let result = raylab(&["diff", legacy, path(&png), "--json"]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&result.stdout).unwrap();
    assert!(json["psnr_db"].as_f64().unwrap() >= 60.0);
    assert!(
        json["explanations"].as_array().unwrap().is_empty(),
        "{json}"
    );
}

#[test]
fn a_size_mismatch_names_both_sizes() {
    let file = out_dir("compare-cli").join("small.png");
    write_png(&file, 10, 8, &vec![[0, 0, 0]; 80]);
    let stderr = failure(&["diff", &lab_path(), path(&file)]);
    assert!(
        stderr.contains("10x8") && stderr.contains("120x90"),
        "{stderr}"
    );
}

#[test]
fn a_missing_file_is_named() {
    let file = out_dir("compare-cli").join("nowhere.png");
    let stderr = failure(&["diff", &lab_path(), path(&file)]);
    assert!(
        stderr.contains("cannot read") && stderr.contains("nowhere.png"),
        "{stderr}"
    );
}

#[test]
fn a_file_that_is_not_an_image_is_named() {
    let file = out_dir("compare-cli").join("notes.png");
    std::fs::write(&file, "these are not pixels").unwrap();
    let stderr = failure(&["diff", &lab_path(), path(&file)]);
    assert!(
        stderr.contains("notes.png is not a readable PNG or PPM image"),
        "{stderr}"
    );
    let truncated = out_dir("compare-cli").join("truncated.png");
    let mut bytes = Vec::new();
    image::RgbImage::new(120, 90)
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .unwrap();
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let stderr = failure(&["diff", &lab_path(), path(&truncated)]);
    assert!(
        stderr.contains("truncated.png is not a readable"),
        "{stderr}"
    );
}

#[test]
fn a_sixteen_bit_image_is_refused_with_the_reason() {
    let file = out_dir("compare-cli").join("deep.png");
    image::ImageBuffer::<image::Rgb<u16>, _>::new(120, 90)
        .save(&file)
        .unwrap();
    let stderr = failure(&["diff", &lab_path(), path(&file)]);
    assert!(stderr.contains("8-bit"), "{stderr}");
}

#[test]
fn a_broken_scene_is_named() {
    let file = out_dir("compare-cli").join("broken.ron");
    std::fs::write(&file, "Scene(objects: [").unwrap();
    let image = out_dir("compare-cli").join("any.png");
    write_png(&image, 2, 2, &[[0, 0, 0]; 4]);
    let stderr = failure(&["diff", path(&file), path(&image)]);
    assert!(stderr.contains("broken.ron"), "{stderr}");
}
