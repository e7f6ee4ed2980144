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
        // The light's diffuse and specular terms, both missing, are one line: the light.
        text.contains("1. ") && text.contains("light (light 1"),
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

/// Where the report image's panels start and how large they are: the layout of
/// `src/compare/report/png.rs` (12-pixel margins, a 58-pixel caption, 360-pixel panels
/// in four columns) for the 120x90 lab scene.
const REPORT_MARGIN: u32 = 12;
const REPORT_CAPTION: u32 = 58;
const REPORT_PANEL: (u32, u32) = (360, 270);

/// The pixels of panel `column` of the report's first row.
fn first_row_panel(report: &image::RgbImage, column: u32) -> Vec<[u8; 3]> {
    let x0 = REPORT_MARGIN + column * (REPORT_PANEL.0 + REPORT_MARGIN);
    let y0 = REPORT_MARGIN + REPORT_CAPTION;
    (y0..y0 + REPORT_PANEL.1)
        .flat_map(|y| (x0..x0 + REPORT_PANEL.0).map(move |x| report.get_pixel(x, y).0))
        .collect()
}

/// `raylab diff --json --report` on `other`: the JSON's raw text, and the report image.
fn diff_with_report(other: &Path, report: &Path) -> (String, image::RgbImage) {
    let result = raylab(&[
        "diff",
        &lab_path(),
        path(other),
        "--json",
        "--report",
        path(report),
    ]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let text = String::from_utf8(result.stdout).unwrap();
    (text, image::open(report).unwrap().to_rgb8())
}

#[test]
fn flip_is_in_the_json_after_the_old_fields_and_its_map_is_a_fourth_panel() {
    let dir = out_dir("compare-cli-flip");
    let own = dir.join("own.png");
    let own_render = raylab(&["render", &lab_path(), "-o", path(&own)]);
    assert!(own_render.status.success());
    let scene = lab_scene();
    let buggy = render_with(
        &scene,
        1,
        &Bugs {
            specular_off: true,
            ..Bugs::default()
        },
    );
    let buggy_path = dir.join("no_specular.png");
    write_png(&buggy_path, buggy.width, buggy.height, &buggy.rgb);

    let (same_text, same_report) = diff_with_report(&own, &dir.join("same.png"));
    let (bug_text, bug_report) = diff_with_report(&buggy_path, &dir.join("bug.png"));

    // Every field the JSON had keeps its place; FLIP's two come after them.
    let keys = [
        "\"psnr_db\"",
        "\"explanations\"",
        "\"unexplained_share\"",
        "\"encoding\"",
        "\"width\"",
        "\"height\"",
        "\"samples_per_pixel\"",
        "\"flip_mean\"",
        "\"flip_p99\"",
    ];
    let at: Vec<usize> = keys
        .iter()
        .map(|k| {
            bug_text
                .rfind(k)
                .unwrap_or_else(|| panic!("{k} in {bug_text}"))
        })
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{keys:?} at {at:?}");

    let figure = |text: &str, key: &str| {
        let json: serde_json::Value = serde_json::from_str(text).unwrap();
        json[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key} in {json}"))
    };
    assert_eq!(figure(&same_text, "flip_mean"), 0.0, "{same_text}");
    assert_eq!(figure(&same_text, "flip_p99"), 0.0, "{same_text}");
    let (mean, p99) = (
        figure(&bug_text, "flip_mean"),
        figure(&bug_text, "flip_p99"),
    );
    assert!(mean > 0.005 && p99 > mean && p99 <= 1.0, "{bug_text}");

    // Four panels in the first row; the fourth is FLIP's map: all but black for the
    // same picture, with bright pixels (magma's orange and yellow) for the bug.
    for report in [&same_report, &bug_report] {
        assert_eq!(
            report.width(),
            REPORT_MARGIN + 4 * (REPORT_PANEL.0 + REPORT_MARGIN)
        );
    }
    let brightest = |pixels: &[[u8; 3]]| {
        pixels
            .iter()
            .map(|p| p.iter().map(|&c| u32::from(c)).sum::<u32>())
            .max()
            .unwrap()
    };
    assert!(brightest(&first_row_panel(&same_report, 3)) < 30);
    assert!(brightest(&first_row_panel(&bug_report, 3)) > 300);
    // The panel is a picture, not the white page around it.
    assert!(brightest(&first_row_panel(&bug_report, 3)) < 3 * 255);
}
