//! `raylab diff` on glass and soft shadows: a render without the transmission term is
//! named as the transmission term at factor 0, on a glass object; raylab's own render of
//! the glass and the soft-spot examples is explained by nothing (no false alarm).

#[path = "compare/one_sample.rs"]
mod one_sample;
#[path = "compare/own_render.rs"]
mod own_render;

use std::path::Path;

use own_render::own_render_with;
use raylab::compare::{Comparison, ExplainedTerm};
use raylab::scene::{Scene, load_scene};
use raylab::trace::{Term, TermSwitches};

fn small(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    let mut scene = load_scene(&path).unwrap();
    scene.camera.width = 96;
    scene.camera.height = 72;
    scene
}

/// The comparison of raylab's picture of `scene` with raylab's own render of it under
/// `switches` (one sample per pixel, as the comparison renders it).
fn diff(scene: &Scene, switches: TermSwitches) -> Comparison {
    one_sample::diff(scene, &own_render_with(scene, switches))
}

#[test]
fn a_render_without_transmission_is_named_as_the_transmission_term_at_factor_zero() {
    let scene = small("glass.ron");
    let mut off = TermSwitches::ALL_ON;
    off.set(Term::Transmission, false);
    let c = diff(&scene, off);
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert_eq!(
        first.term,
        ExplainedTerm::Term(Term::Transmission),
        "{report}"
    );
    assert!(first.factor < 0.1, "{report}");
    let glass: Vec<usize> = ["glass ball", "lens"]
        .iter()
        .map(|n| scene.objects.iter().position(|o| o.name == *n).unwrap())
        .collect();
    assert!(
        first.object.is_none_or(|o| glass.contains(&o)),
        "on the glass: {report}"
    );
}

#[test]
fn raylabs_own_render_of_glass_and_soft_shadows_is_not_explained_by_anything() {
    for name in ["glass.ron", "soft_spot.ron"] {
        let c = diff(&small(name), TermSwitches::ALL_ON);
        assert!(c.psnr_db >= 60.0, "{name}: {}", c.psnr_db);
        assert!(
            c.explanations.iter().all(|e| e.share < 0.05),
            "{name}: {:#?}",
            c.text_lines()
        );
    }
}
