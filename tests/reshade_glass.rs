//! Edits of scenes with glass re-shaded from the hit cache, whose pixels hold trees of
//! rays: each pass bit for bit a full trace (`edit_chain` checks it), tracing exactly the
//! rays the edit made stale or newly needed. A colour edit traces nothing; a material
//! made transmissive traces its new transmitted rays and what lies below them; an `ior`
//! edit traces again exactly the rays below the transmitted rays of the objects of that
//! material, total internal reflection flipping included; the `transmission` switch
//! grows and prunes the trees without a ray once they were traced.

mod reshade_harness;

use glam::DVec3;
use raylab::scene::Scene;
use raylab::trace::{BounceReport, Branch, RayCounts, RenderOptions, Term, inspect_pixel};
use reshade_harness::{GLASS_TREES_NAME, NOTHING, Shot, edit_chain, example};

/// Closest-hit rays (camera, mirror, transmitted) of a pass's counts.
fn closest_hit_rays(rays: &RayCounts) -> u64 {
    rays.primary + rays.reflection + rays.transmission
}

/// The rays of `shot`'s one-sample pass (the pixel inspector's record of each pixel
/// centre) that lie below a transmitted ray from a hit on a scene object `bent` names:
/// the rays an edit of those objects' `ior` makes stale, with their shadow rays.
fn rays_below_transmitted(shot: &Shot, bent: impl Fn(usize) -> bool) -> RayCounts {
    let world = shot.world();
    let mut counts = RayCounts::default();
    let (width, height) = (shot.options.width, shot.options.height);
    for py in 0..height {
        for px in 0..width {
            let report = inspect_pixel(&world, &shot.options, px, py);
            let mut stale = vec![false; report.bounces.len()];
            for (index, bounce) in report.bounces.iter().enumerate() {
                let Some((parent, branch)) = bounce.from else {
                    continue;
                };
                let below_bent = branch.is_transmitted()
                    && report.bounces[parent]
                        .hit
                        .is_some_and(|hit| bent(hit.object));
                stale[index] = stale[parent] || below_bent;
                if !stale[index] {
                    continue;
                }
                match branch {
                    Branch::Mirror => counts.reflection += 1,
                    Branch::Refracted | Branch::InternallyReflected => counts.transmission += 1,
                }
                let cast = bounce.lights.iter().filter(|l| l.shadow_ray_cast);
                counts.shadow += cast.map(|l| u64::from(l.visibility.1)).sum::<u64>();
            }
        }
    }
    counts
}

/// How many transmitted rays of `shot`'s pass are internally reflected.
fn internal_reflections(shot: &Shot) -> usize {
    let world = shot.world();
    let (width, height) = (shot.options.width, shot.options.height);
    (0..height)
        .flat_map(|py| (0..width).map(move |px| (px, py)))
        .map(|(px, py)| {
            let report = inspect_pixel(&world, &shot.options, px, py);
            let tir = |b: &&BounceReport| matches!(b.from, Some((_, Branch::InternallyReflected)));
            report.bounces.iter().filter(tir).count()
        })
        .sum()
}

#[test]
fn a_material_made_transmissive_traces_its_new_rays_only_and_back_traces_nothing() {
    let base = Shot::of(example("glass.ron"));
    let see_through = base.edited(|s, _| {
        s.materials.get_mut("red").unwrap().transmission = DVec3::splat(0.5);
    });
    let passes = edit_chain(&base, &[see_through.clone(), base.clone()], "red 0 -> 0.5");
    let traced = passes[0].traced;
    assert!(passes[0].reused);
    assert_eq!(traced.primary, 0, "no camera ray");
    assert!(traced.transmission > 0);
    let (before, after) = (base.traced().rays, see_through.traced().rays);
    assert_eq!(
        closest_hit_rays(&traced),
        closest_hit_rays(&after) - closest_hit_rays(&before),
        "exactly the rays of the new branches"
    );
    assert_eq!(traced.shadow, after.shadow - before.shadow);
    // Back to opaque: the transmitted branches are kept, unused; nothing traced.
    assert_eq!(passes[1].traced, NOTHING);
    assert_eq!(passes[1].quick_pixels, passes[1].shaded_pixels);
}

#[test]
fn an_ior_edit_traces_again_exactly_the_rays_below_the_glass() {
    for (name, material) in [("glass.ron", "glass"), (GLASS_TREES_NAME, "prism")] {
        let base = Shot::of(example(name));
        let ior = |value: f64| {
            move |s: &mut Scene, _: &mut RenderOptions| {
                s.materials.get_mut(material).unwrap().ior = value;
            }
        };
        let water = base.edited(ior(1.33));
        let back = base.edited(ior(1.5));
        let bluer = back.edited(|s, _| {
            s.materials.get_mut(material).unwrap().diffuse = DVec3::new(0.0, 0.1, 0.3);
        });
        let what = format!("{name}: {material} ior 1.5 -> 1.33 -> 1.5");
        let passes = edit_chain(&base, &[water.clone(), back.clone(), bluer], &what);
        let glass = |shot: &Shot| {
            let scene = shot.scene.clone();
            move |object: usize| scene.objects[object].material == material
        };
        for (pass, shot) in passes.iter().zip([&water, &back]) {
            assert!(pass.reused, "{what}");
            let expected = rays_below_transmitted(shot, glass(shot));
            assert!(expected.transmission > 0, "{what}: the glass transmits");
            assert_eq!(
                pass.traced, expected,
                "{what}: the rays below the glass only"
            );
            let all = shot.traced().rays;
            assert!(closest_hit_rays(&pass.traced) < closest_hit_rays(&all) - all.primary);
        }
        assert_eq!(passes[2].traced, NOTHING, "{what}: then a colour edit");
        // The index moves the critical angle: total internal reflection comes and goes.
        assert_ne!(internal_reflections(&base), internal_reflections(&water));
    }
}

#[test]
fn colour_edits_of_glass_trace_no_ray_and_shade_from_the_cached_factors() {
    for name in ["glass.ron", GLASS_TREES_NAME] {
        let base = Shot::of(example(name));
        let glass = if name == "glass.ron" {
            "glass"
        } else {
            "prism"
        };
        let edits = [
            base.edited(|s, _| {
                s.materials.get_mut(glass).unwrap().transmission = DVec3::new(0.5, 0.7, 0.9);
            }),
            base.edited(|s, _| {
                let m = s.materials.get_mut(glass).unwrap();
                m.diffuse = DVec3::new(0.3, 0.02, 0.02);
                m.mirror = DVec3::splat(0.2);
            }),
        ];
        let passes = edit_chain(&base, &edits, name);
        for (step, pass) in passes.iter().enumerate() {
            let what = format!("{name}, edit {step}");
            assert!(pass.reused, "{what}");
            assert_eq!(pass.traced, NOTHING, "{what}");
            assert!(pass.shaded_pixels > 0, "{what}");
            assert_eq!(
                pass.quick_pixels, pass.shaded_pixels,
                "{what}: from factors"
            );
        }
    }
}

#[test]
fn the_transmission_switch_grows_and_prunes_the_trees() {
    let all = 64 * 48;
    let base = Shot::of(example("glass.ron"));
    let set = |on: bool| {
        move |_: &mut Scene, o: &mut RenderOptions| {
            o.switches.set(Term::Transmission, on);
        }
    };
    let solo = |term: Option<Term>| {
        move |_: &mut Scene, o: &mut RenderOptions| {
            o.switches = o.switches.with_solo(term);
        }
    };
    let off = base.edited(set(false));
    let on = off.edited(set(true));
    let solo_on = on.edited(solo(Some(Term::Transmission)));
    let solo_off = solo_on.edited(set(false));
    let back = solo_off.edited(|_, o| *o = base.options.clone());
    let shots = [off.clone(), on, solo_on, solo_off, back];
    let passes = edit_chain(&base, &shots, "transmission off, on, solo");
    for (step, pass) in passes.iter().enumerate() {
        assert_eq!(pass.traced, NOTHING, "step {step}");
        assert_eq!(pass.quick_pixels, pass.shaded_pixels, "step {step}");
    }
    // Only the pixels whose rays meet the glass depend on the switch.
    assert!(passes[0].shaded_pixels > 0 && passes[0].shaded_pixels < all / 2);

    // From a cache traced with the term off, turning it on traces the transmitted
    // branches (and their rays), no camera ray.
    let passes = edit_chain(&off, std::slice::from_ref(&base), "transmission on, fresh");
    let traced = passes[0].traced;
    assert_eq!(traced.primary, 0);
    let (before, after) = (off.traced().rays, base.traced().rays);
    assert_eq!(
        closest_hit_rays(&traced),
        closest_hit_rays(&after) - closest_hit_rays(&before)
    );
    assert_eq!(traced.transmission, after.transmission);
}

#[test]
fn a_deeper_max_depth_grows_the_trees_and_a_shallower_one_keeps_them() {
    let base = Shot::of(example(GLASS_TREES_NAME));
    let shallow = base.edited(|s, _| s.render.max_depth = 2);
    let passes = edit_chain(
        &shallow,
        &[base.clone(), shallow.clone()],
        "max_depth 2 -> 5 -> 2",
    );
    let traced = passes[0].traced;
    let (before, after) = (shallow.traced().rays, base.traced().rays);
    assert_eq!(traced.primary, 0);
    assert_eq!(
        closest_hit_rays(&traced),
        closest_hit_rays(&after) - closest_hit_rays(&before)
    );
    assert_eq!(passes[1].traced, NOTHING);
}
