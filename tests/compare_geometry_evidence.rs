//! A geometry verdict needs evidence that the surface under a pixel differs: lighting
//! that differs up to an object's edge (a normal left in object space, which the
//! catalogue does not know; a spot light's cone bugs, alone or beside a second bug) is
//! shading, never "the outline of X differs". Pictures with moved objects still get
//! their outline verdicts (tests/compare_different_scene.rs).

#[path = "compare/shader.rs"]
mod shader;

#[path = "compare/one_sample.rs"]
mod one_sample;

use glam::DVec3;
use one_sample::diff;
use raylab::compare::{Comparison, ExplainedTerm};
use raylab::scene::{Light, LightSource, Scene, Transform};
use shader::{Bugs, lab_scene, render};

fn assert_no_geometry(label: &str, c: &Comparison) {
    let report = c.text_lines().join("\n");
    assert!(
        !c.explanations.is_empty(),
        "{label}: a difference\n{report}"
    );
    assert!(
        c.explanations
            .iter()
            .all(|e| e.term != ExplainedTerm::Geometry),
        "{label}:\n{report}"
    );
}

/// The lab scene with its point light a spot of half angle `angle_deg` on the balls
/// (`None`: the same light without a cone, a point light).
fn spot_lab(angle_deg: Option<f64>) -> Scene {
    let mut scene = lab_scene();
    let position = DVec3::new(-1.0, 4.0, 3.0);
    scene.lights[1] = match angle_deg {
        Some(angle_deg) => Light::Spot {
            position,
            direction: DVec3::new(0.3, -1.0, -0.6),
            angle_deg,
            source: LightSource::point(DVec3::ONE, 30.0),
        },
        None => Light::Point {
            position,
            source: LightSource::point(DVec3::ONE, 30.0),
        },
    };
    scene
}

#[test]
fn a_normal_left_in_object_space_is_shading_not_an_outline() {
    let lab = lab_scene();
    for object in [0, 4] {
        let bugs = Bugs {
            normal_in_object_space: Some(object),
            ..Bugs::default()
        };
        let c = diff(&lab, &render(&lab, 1, &bugs));
        assert_no_geometry(&format!("object {object}"), &c);
    }
    // Beside a second bug, and on a cone turned further.
    let mut turned = lab.clone();
    if let Transform::Trs(trs) = &mut turned.objects[4].transform {
        trs.rotate_deg = DVec3::new(60.0, 30.0, 0.0);
    }
    let bugs = Bugs {
        normal_in_object_space: Some(4),
        ambient_off: true,
        ..Bugs::default()
    };
    assert_no_geometry("turned cone", &diff(&turned, &render(&turned, 1, &bugs)));
}

#[test]
fn spot_light_bugs_at_edges_are_never_outlines() {
    let scene = spot_lab(Some(25.0));
    // No cone: the student's picture is the point light's.
    let no_cone = spot_lab(None);
    // A cone half as wide, and one wider, whose edges cross the balls and the cone.
    let narrow = spot_lab(Some(12.5));
    let wide = spot_lab(Some(40.0));
    for (label, student) in [("no cone", &no_cone), ("narrow", &narrow), ("wide", &wide)] {
        for bugs in [
            Bugs::default(),
            Bugs {
                ambient_off: true,
                ..Bugs::default()
            },
            Bugs {
                specular_off: true,
                ..Bugs::default()
            },
        ] {
            let c = diff(&scene, &render(student, 1, &bugs));
            assert_no_geometry(&format!("{label}, {bugs:?}"), &c);
        }
    }
    let falloff = Bugs {
        spot_no_falloff: Some(1),
        shadows_off: true,
        ..Bugs::default()
    };
    assert_no_geometry("no fall-off", &diff(&scene, &render(&scene, 1, &falloff)));
}
