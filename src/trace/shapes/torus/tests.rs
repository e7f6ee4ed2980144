//! The torus's hard cases: far, grazing, tangent, along the axis, through the hole, from
//! the surface, and horn and spindle tori. A solver that takes the quartic's coefficients
//! from the raw origin fails the far rays; one that keeps every root of the quartic hits
//! a spindle's inner lemon.

use super::*;
use crate::trace::shapes::test_support::assert_hit;

const MINOR: f64 = 0.25;

/// The radial distance where the tube of radius `MINOR` meets the height `z`, outer side.
fn outer_radius_at(z: f64) -> f64 {
    1.0 + (MINOR * MINOR - z * z).sqrt()
}

#[test]
fn far_rays_hit_the_near_side_exactly() {
    for distance in [10.0, 1e4, 1e6, 1e8] {
        let ray = Ray::new(DVec3::new(distance, 0.0, 0.1), -DVec3::X);
        let x = outer_radius_at(0.1);
        let hit = intersect(&ray, f64::INFINITY, MINOR).expect("a far ray hits");
        // t carries the origin's rounding; the point is re-projected exactly.
        assert!(
            (hit.t - (distance - x)).abs() <= 1e-15 * distance * 4.0,
            "{}",
            hit.t
        );
        assert!((hit.p - DVec3::new(x, 0.0, 0.1)).length() < 1e-9 * distance.max(1.0).sqrt());
        let expected_n = DVec3::new(x - 1.0, 0.0, 0.1) / MINOR;
        assert!(
            (hit.n - expected_n).length() < 1e-6,
            "{} at {distance}",
            hit.n
        );
    }
}

#[test]
fn along_the_axis_passes_through_the_hole() {
    let ray = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
    assert!(intersect(&ray, f64::INFINITY, MINOR).is_none());
    let off_axis = Ray::new(DVec3::new(0.5, 0.2, 5.0), -DVec3::Z);
    assert!(intersect(&off_axis, f64::INFINITY, MINOR).is_none());
    // Straight down onto the tube's top.
    let onto_tube = Ray::new(DVec3::new(1.0, 0.0, 5.0), -DVec3::Z);
    assert_hit(
        intersect(&onto_tube, f64::INFINITY, MINOR),
        &onto_tube,
        4.75,
        DVec3::Z,
    );
}

#[test]
fn through_the_centre_meets_four_surfaces() {
    let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    assert_hit(intersect(&ray, f64::INFINITY, MINOR), &ray, 3.75, -DVec3::X);
    let mut out = Vec::new();
    crossings(&ray, &mut out, MINOR);
    let ts: Vec<f64> = out.iter().map(|h| h.t).collect();
    let expected = [3.75, 4.25, 5.75, 6.25];
    assert_eq!(ts.len(), 4, "{ts:?}");
    for (t, e) in ts.iter().zip(expected) {
        assert!((t - e).abs() < 1e-12, "{ts:?}");
    }
    // From inside the hole: the inner side, its normal towards the axis.
    let in_hole = Ray::new(DVec3::ZERO, DVec3::X);
    assert_hit(
        intersect(&in_hole, f64::INFINITY, MINOR),
        &in_hole,
        0.75,
        -DVec3::X,
    );
}

#[test]
fn tangent_rays_touch_or_miss_but_never_pass_inside() {
    // Along the top of the tube, z = minor: touches at x = -1 (and x = 1).
    let ray = Ray::new(DVec3::new(-5.0, 0.0, MINOR), DVec3::X);
    if let Some(hit) = intersect(&ray, f64::INFINITY, MINOR) {
        assert!(
            (hit.p - DVec3::new(-1.0, 0.0, MINOR)).length() < 1e-6,
            "{}",
            hit.p
        );
        assert!((hit.n - DVec3::Z).length() < 1e-6 && hit.n.is_finite());
    }
    // A hair above misses; a little below enters near x = -1.
    let above = Ray::new(DVec3::new(-5.0, 0.0, MINOR + 1e-9), DVec3::X);
    assert!(intersect(&above, f64::INFINITY, MINOR).is_none());
    let below = Ray::new(DVec3::new(-5.0, 0.0, MINOR - 1e-6), DVec3::X);
    let hit = intersect(&below, f64::INFINITY, MINOR).expect("just below enters");
    assert!((hit.p.x + 1.0).abs() < 1e-2 && hit.n.dot(below.dir) < 0.0);
    // Along the outer equator's tangent line: touches at (1.25, 0, 0).
    let equator = Ray::new(DVec3::new(1.0 + MINOR, -5.0, 0.0), DVec3::Y);
    if let Some(hit) = intersect(&equator, f64::INFINITY, MINOR) {
        assert!((hit.p - DVec3::new(1.0 + MINOR, 0.0, 0.0)).length() < 1e-6);
        assert!(hit.n.is_finite());
    }
}

#[test]
fn grazing_rays_near_the_top_give_finite_hits_on_the_surface() {
    for k in 1..200 {
        let z = MINOR * (1.0 - 10f64.powf(-f64::from(k) / 12.0));
        let ray = Ray::new(DVec3::new(-3.0, 0.3, z), DVec3::new(1.0, 0.0, 1e-12));
        if let Some(hit) = intersect(&ray, f64::INFINITY, MINOR) {
            assert!(hit.p.is_finite() && hit.n.is_finite() && hit.t.is_finite());
            assert!(hit.n.dot(ray.dir) <= 1e-9, "enters from outside: {}", hit.n);
            let radial = (hit.p.x * hit.p.x + hit.p.y * hit.p.y).sqrt();
            let off = ((radial - 1.0).hypot(hit.p.z) - MINOR).abs();
            assert!(off < 1e-15, "{off:e}");
        }
    }
}

#[test]
fn rays_from_the_surface_leave_or_cross_to_the_far_side() {
    let leaving = Ray::new(DVec3::new(1.0 + MINOR, 0.0, 0.0), DVec3::X);
    assert!(intersect(&leaving, f64::INFINITY, MINOR).is_none());
    let entering = Ray::new(DVec3::new(1.0 + MINOR, 0.0, 0.0), -DVec3::X);
    // Out through the inner side at x = 0.75, whose outward normal faces the axis.
    assert_hit(
        intersect(&entering, f64::INFINITY, MINOR),
        &entering,
        0.5,
        -DVec3::X,
    );
    // Along the surface's tangent plane from a point on it: no hit at t ~ 0.
    let along = Ray::new(DVec3::new(1.0 + MINOR, 0.0, 0.0), DVec3::Z);
    assert!(intersect(&along, f64::INFINITY, MINOR).is_none_or(|h| h.t > 1e-6));
}

#[test]
fn a_horn_torus_is_pinched_at_the_centre() {
    let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    assert_hit(intersect(&ray, f64::INFINITY, 1.0), &ray, 3.0, -DVec3::X);
    // From inside, next to the pinch: out through the outer side.
    let inside = Ray::new(DVec3::new(0.5, 0.0, 0.5), DVec3::X);
    let hit = intersect(&inside, f64::INFINITY, 1.0).expect("from inside the horn torus");
    let x = 1.0 + 0.75f64.sqrt();
    assert_hit(Some(hit), &inside, x - 0.5, DVec3::new(x - 1.0, 0.0, 0.5));
}

#[test]
fn a_spindle_torus_has_no_inner_lemon_surface() {
    let minor = 1.5;
    // From the centre, inside the solid: out through the outer surface at x = 2.5, not
    // the lemon's root at x = 0.5.
    let from_centre = Ray::new(DVec3::ZERO, DVec3::X);
    assert_hit(
        intersect(&from_centre, f64::INFINITY, minor),
        &from_centre,
        2.5,
        DVec3::X,
    );
    let mut out = Vec::new();
    crossings(
        &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X),
        &mut out,
        minor,
    );
    let ts: Vec<f64> = out.iter().map(|h| h.t).collect();
    assert_eq!(ts.len(), 2, "{ts:?}");
    assert!((ts[0] - 2.5).abs() < 1e-12 && (ts[1] - 7.5).abs() < 1e-12);
    // Down the axis: the apple's tip at z = sqrt(minor^2 - 1).
    let down = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
    let tip = (minor * minor - 1.0_f64).sqrt();
    assert_hit(
        intersect(&down, f64::INFINITY, minor),
        &down,
        5.0 - tip,
        DVec3::Z,
    );
}

#[test]
fn degenerate_rays_never_give_nan() {
    let rays = [
        Ray::new(DVec3::ZERO, DVec3::ZERO),
        Ray::new(DVec3::splat(f64::MAX), DVec3::X),
        Ray::new(DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 1e-300)),
        Ray::new(DVec3::new(-1e300, 0.0, 0.0), DVec3::X),
    ];
    for ray in rays {
        if let Some(hit) = intersect(&ray, f64::INFINITY, MINOR) {
            assert!(
                hit.p.is_finite() && hit.n.is_finite() && hit.t.is_finite(),
                "{ray:?}"
            );
        }
    }
}
