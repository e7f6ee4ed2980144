//! Golden images: small renders of the example scenes compared with checked-in PNGs, so a
//! change that alters pictures is a visible decision. Regenerate with
//! `RAYLAB_BLESS=1 cargo test --test golden` and look at the new files before committing.

use std::path::{Path, PathBuf};

use raylab::scene::{load_scene, read_scene_meshes};
use raylab::trace::{MeshStore, RenderOptions, RenderProgress, World, render};

/// Long side of the golden renders, in pixels.
const GOLDEN_WIDTH: u32 = 160;
/// Samples per pixel of the golden renders.
const GOLDEN_SPP: u32 = 4;
/// A pixel channel may differ by this much (in 8-bit steps) ...
const CHANNEL_TOLERANCE: u8 = 2;
/// ... and at most this fraction of pixels may differ by more (hard edges may move).
const OUTLIER_FRACTION: f64 = 0.002;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn render_small(scene_name: &str) -> image::RgbImage {
    let scene = load_scene(&root().join("scenes").join(format!("{scene_name}.ron"))).unwrap();
    let meshes = read_scene_meshes(&scene, &root().join("scenes")).unwrap();
    let world = World::with_meshes(&scene, &MeshStore::build(&meshes)).unwrap();
    let mut options = RenderOptions::from_scene(&scene);
    options.width = GOLDEN_WIDTH;
    options.height = (f64::from(GOLDEN_WIDTH) * f64::from(scene.camera.height)
        / f64::from(scene.camera.width))
    .round() as u32;
    options.samples_per_pixel = GOLDEN_SPP;
    let (picture, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    image::RgbImage::from_raw(
        picture.width,
        picture.height,
        picture
            .to_rgba8()
            .chunks(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect(),
    )
    .unwrap()
}

fn check(scene_name: &str) {
    let actual = render_small(scene_name);
    let path = root()
        .join("tests/golden")
        .join(format!("{scene_name}.png"));
    if std::env::var_os("RAYLAB_BLESS").is_some() {
        actual.save(&path).unwrap();
        return;
    }
    let expected = image::open(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (bless with RAYLAB_BLESS=1)", path.display()))
        .to_rgb8();
    assert_eq!(actual.dimensions(), expected.dimensions(), "{scene_name}");
    let outliers = actual
        .pixels()
        .zip(expected.pixels())
        .filter(|(a, b)| {
            a.0.iter()
                .zip(b.0.iter())
                .any(|(x, y)| x.abs_diff(*y) > CHANNEL_TOLERANCE)
        })
        .count();
    let allowed = (OUTLIER_FRACTION * f64::from(actual.width() * actual.height())).ceil() as usize;
    if outliers > allowed {
        let failed = std::env::temp_dir().join(format!("raylab-golden-{scene_name}.png"));
        actual.save(&failed).unwrap();
        panic!(
            "{scene_name}: {outliers} pixels differ by more than {CHANNEL_TOLERANCE}/255 (allowed {allowed}); the new render is at {}",
            failed.display()
        );
    }
}

#[test]
fn default_scene() {
    check("default");
}

#[test]
fn shapes() {
    check("shapes");
}

#[test]
fn spotlights() {
    check("spotlights");
}

#[test]
fn coloured_shadows() {
    check("coloured_shadows");
}

#[test]
fn mirror_cap() {
    check("mirror_cap");
}

#[test]
fn specular_exponents() {
    check("specular_exponents");
}

#[test]
fn csg() {
    check("csg");
}

#[test]
fn more_shapes() {
    check("more_shapes");
}

#[test]
fn glass() {
    check("glass");
}

#[test]
fn soft_spot() {
    check("soft_spot");
}

#[test]
fn mesh() {
    check("mesh");
}

#[test]
fn every_example_scene_has_a_golden_image() {
    for entry in std::fs::read_dir(root().join("scenes")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "ron") {
            continue; // the OBJ files of the mesh scene
        }
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        assert!(
            root()
                .join("tests/golden")
                .join(format!("{stem}.png"))
                .exists(),
            "scenes/{stem}.ron has no golden image"
        );
    }
}
