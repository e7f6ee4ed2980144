//! Edits re-shaded from the hit cache against a full re-trace: for each kind of edit, the
//! re-shaded one-sample pass is bit for bit the traced one, and it traced exactly the
//! rays the edit made stale or newly needed (none for a material, switch, view or light
//! colour edit; one light's shadow rays for that light moved; everything for geometry).

mod common;
mod reshade_harness;

use glam::DVec3;
use raylab::scene::{Light, LightSource, Scene, Transform};
use raylab::trace::{Isolation, RenderOptions, RetraceReason, Reuse, Term, View};
use reshade_harness::{NOTHING, SCENES, Shot, assert_same_pass, edit_chain, example, set_colour};

/// Every edit here traces nothing. Those marked `FACTORS` (colours other than
/// shininess, term switches and solos of the lit picture, background, depth, light
/// colours) shade every pixel they shade from its cached light factors alone.
#[test]
fn material_switch_view_and_light_colour_edits_trace_nothing() {
    const FACTORS: bool = true;
    for name in SCENES {
        let base = Shot::of(example(name));
        let first_material = base.scene.materials.keys().next().unwrap().clone();
        let edit = |change: fn(&mut Scene, &mut RenderOptions, &str), quick: bool| {
            (base.edited(|s, o| change(s, o, &first_material)), quick)
        };
        let switch = |term: Term, on: bool| {
            let shot = base.edited(|_, o| o.switches.set(term, on));
            (shot, FACTORS)
        };
        let solo = |term: Term, quick: bool| {
            let shot = base.edited(|_, o| o.switches = o.switches.with_solo(Some(term)));
            (shot, quick)
        };
        let view = |view: View| (base.edited(|_, o| o.view = view), !FACTORS);
        let edits = [
            edit(
                |s, _, m| {
                    let m = s.materials.get_mut(m).unwrap();
                    m.ambient *= 3.0;
                    m.specular *= 0.5;
                },
                FACTORS,
            ),
            switch(Term::Specular, false),
            switch(Term::Diffuse, false),
            switch(Term::Shadows, false),
            switch(Term::Reflection, false),
            solo(Term::Diffuse, FACTORS),
            solo(Term::Specular, FACTORS),
            // Solo shadows is the shadow-mask view.
            solo(Term::Shadows, !FACTORS),
            solo(Term::Reflection, FACTORS),
            view(View::Normal),
            view(View::Depth),
            view(View::ObjectId),
            view(View::ShadowMask),
            edit(
                |s, _, _| s.render.background = DVec3::new(0.3, 0.1, 0.0),
                FACTORS,
            ),
            edit(|s, _, _| s.render.max_depth = 1, FACTORS),
            // Back to the base: the deeper mirror rays of max_depth 5 were kept.
            (base.clone(), FACTORS),
            edit(
                |s, _, _| {
                    for light in &mut s.lights {
                        match light {
                            Light::Ambient { intensity, .. }
                            | Light::Point {
                                source: LightSource { intensity, .. },
                                ..
                            }
                            | Light::Directional { intensity, .. }
                            | Light::Spot {
                                source: LightSource { intensity, .. },
                                ..
                            } => *intensity *= 0.5,
                        }
                        set_colour(light, DVec3::new(0.2, 0.9, 0.4));
                    }
                },
                FACTORS,
            ),
            // A light turned down to nothing and up again keeps its factors.
            edit(
                |s, _, _| set_colour(s.lights.last_mut().unwrap(), DVec3::ZERO),
                FACTORS,
            ),
            (base.clone(), FACTORS),
            // Last: the edit after a new shininess shades that material's pixels in full.
            edit(
                |s, _, m| {
                    let m = s.materials.get_mut(m).unwrap();
                    m.diffuse = DVec3::new(0.9, 0.2, 0.1);
                    m.shininess = 0.0;
                },
                !FACTORS,
            ),
        ];
        let (shots, quick): (Vec<Shot>, Vec<bool>) = edits.into_iter().unzip();
        let passes = edit_chain(&base, &shots, name);
        for (step, (pass, quick)) in passes.iter().zip(quick).enumerate() {
            let what = format!("{name}, edit {step}");
            assert!(pass.reused, "{what}");
            assert_eq!(pass.traced, NOTHING, "{what}");
            if quick {
                assert_eq!(
                    pass.quick_pixels, pass.shaded_pixels,
                    "{what}: every shaded pixel from its factors"
                );
            } else {
                assert_eq!(pass.quick_pixels, 0, "{what}: shaded in full");
            }
        }
    }
}

/// The lobes kept are for one shininess: a new one, set while the specular term is off,
/// has them worked out again before the term comes back.
#[test]
fn a_new_shininess_works_its_lobes_out_again_even_while_specular_is_off() {
    let base = Shot::of(example("default.ron"));
    let no_specular = base.edited(|_, o| o.switches.set(Term::Specular, false));
    let duller = no_specular.edited(|s, _| {
        s.materials.get_mut("red plastic").unwrap().shininess = 3.0;
    });
    let back_on = duller.edited(|_, o| o.switches.set(Term::Specular, true));
    let passes = edit_chain(&base, &[no_specular.clone(), duller, back_on], "shininess");
    assert_eq!(passes[0].quick_pixels, passes[0].shaded_pixels);
    // The red ball's pixels are shaded in full: their lobes were for shininess 60.
    let (quick, shaded) = (passes[1].quick_pixels, passes[1].shaded_pixels);
    assert!(quick == 0 && shaded > 0, "{quick} of {shaded} from factors");
    assert_eq!(
        passes[2].quick_pixels, passes[2].shaded_pixels,
        "new lobes kept"
    );

    // With diffuse off too the shader looks at no light there: the old lobes are
    // forgotten, and the pixels are shaded in full when the terms come back.
    let unlit = no_specular.edited(|_, o| o.switches.set(Term::Diffuse, false));
    let duller = unlit.edited(|s, _| {
        s.materials.get_mut("red plastic").unwrap().shininess = 3.0;
    });
    let lit = duller.edited(|_, o| *o = base.options.clone());
    let passes = edit_chain(&base, &[unlit, duller, lit], "shininess, unlit");
    assert!(passes[2].quick_pixels < passes[2].shaded_pixels);
}

/// A re-shaded pass keeps the guard: the non-finite sample is counted in its pixel
/// while the light is that strong, and gone when it is turned down.
#[test]
fn a_re_shaded_pass_counts_a_non_finite_sample_in_its_pixel() {
    let base = Shot::of(raylab::scene::parse_scene(common::LIGHT_ON_THE_SURFACE).unwrap());
    let edits = [
        base.edited(|s, _| s.materials.get_mut("white").unwrap().ambient *= 3.0),
        base.edited(|s, _| match &mut s.lights[1] {
            Light::Point {
                source: LightSource { intensity, .. },
                ..
            } => *intensity = 1.0,
            _ => unreachable!("the second light is the point light"),
        }),
        base.clone(),
    ];
    let passes = edit_chain(&base, &edits, "infinite light");
    let non_finite: Vec<u64> = passes.iter().map(|p| p.sums.non_finite).collect();
    assert_eq!(non_finite, [1, 0, 1]);
    assert_eq!(passes[0].sums.non_finite_pixels, [16 * 33 + 16]);
    for pass in &passes {
        assert_eq!(pass.quick_pixels, pass.shaded_pixels);
    }
}

#[test]
fn a_material_made_shiny_or_lit_traces_only_the_rays_it_now_needs() {
    // Red plastic has no mirror: giving it one needs mirror rays never traced (and their
    // hits' shadow rays), but no camera ray.
    let base = Shot::of(example("default.ron"));
    let shiny = base.edited(|s, _| {
        s.materials.get_mut("red plastic").unwrap().mirror = DVec3::splat(0.5);
    });
    let passes = edit_chain(&base, &[shiny], "mirror 0 -> 0.5");
    let traced = passes[0].traced;
    assert_eq!(traced.primary, 0);
    assert!(traced.reflection > 0);
    let more = passes[0].sums.rays.reflection - base.traced().rays.reflection;
    assert_eq!(traced.reflection, more, "exactly the new mirror rays");

    // Gold without diffuse and specular casts no shadow ray; lit again it needs them.
    let dull = base.edited(|s, _| {
        let gold = s.materials.get_mut("gold").unwrap();
        gold.diffuse = DVec3::ZERO;
        gold.specular = DVec3::ZERO;
    });
    let passes = edit_chain(&dull, std::slice::from_ref(&base), "gold lit again");
    let traced = passes[0].traced;
    assert_eq!((traced.primary, traced.reflection), (0, 0));
    let more = base.traced().rays.shadow - dull.traced().rays.shadow;
    assert!(more > 0);
    assert_eq!(traced.shadow, more, "exactly gold's shadow rays");
}

#[test]
fn a_material_edit_shades_only_the_pixels_whose_rays_meet_that_material() {
    let base = Shot::of(example("default.ron"));
    let all = 64 * 48;
    let redder = base.edited(|s, _| {
        s.materials.get_mut("red plastic").unwrap().diffuse.x = 0.95;
    });
    let passes = edit_chain(&base, &[redder, base.clone()], "red plastic and back");
    for pass in &passes {
        // The red ball and its reflections, not the floor, the sky or the other balls.
        assert!(pass.shaded_pixels > 0 && pass.shaded_pixels < all / 4);
    }
}

/// The shadow rays `shot` casts towards scene light `light` (those of the others do not
/// change when it is muted).
fn shadow_rays_of(shot: &Shot, light: usize) -> u64 {
    let muted = shot.edited(|_, o| {
        o.isolation.muted_lights.insert(light);
    });
    shot.traced().rays.shadow - muted.traced().rays.shadow
}

#[test]
fn moving_a_light_recasts_its_shadow_rays_and_no_other_ray() {
    for name in ["default.ron", "spotlights.ron"] {
        let base = Shot::of(example(name));
        for (index, light) in base.scene.lights.iter().enumerate() {
            if matches!(light, Light::Ambient { .. }) {
                continue;
            }
            let moved = base.edited(|s, _| match &mut s.lights[index] {
                Light::Point { position, .. } | Light::Spot { position, .. } => {
                    *position += DVec3::new(0.3, -0.2, 0.1);
                }
                Light::Directional { direction, .. } => *direction += DVec3::new(0.1, 0.0, 0.2),
                Light::Ambient { .. } => unreachable!(),
            });
            let what = format!("{name}, light {index} moved");
            let passes = edit_chain(&base, std::slice::from_ref(&moved), &what);
            let traced = passes[0].traced;
            assert_eq!((traced.primary, traced.reflection), (0, 0), "{what}");
            assert!(traced.shadow > 0, "{what}");
            assert_eq!(traced.shadow, shadow_rays_of(&moved, index), "{what}");
        }
    }
}

#[test]
fn a_wider_spot_cone_casts_the_shadow_rays_it_now_needs() {
    let base = Shot::of(example("default.ron"));
    let wider = base.edited(|s, _| {
        for light in &mut s.lights {
            if let Light::Spot { angle_deg, .. } = light {
                *angle_deg = 60.0;
            }
        }
    });
    let passes = edit_chain(&base, std::slice::from_ref(&wider), "spot 22 -> 60 degrees");
    let traced = passes[0].traced;
    assert_eq!((traced.primary, traced.reflection), (0, 0));
    assert_eq!(
        traced.shadow,
        wider.traced().rays.shadow - base.traced().rays.shadow
    );
}

#[test]
fn muting_and_solo_lights_reshade_and_unmuted_lights_recast_only_their_shadows() {
    let base = Shot::of(example("default.ron"));
    let edits = [
        base.edited(|_, o| {
            o.isolation.muted_lights.insert(1);
        }),
        // Solo the spot: the point and directional lights leave the world.
        base.edited(|_, o| {
            o.isolation.solo_lights.insert(3);
        }),
        base.clone(),
    ];
    let passes = edit_chain(&base, &edits, "isolation");
    assert!(passes.iter().all(|p| p.reused));
    assert_eq!(passes[0].traced, NOTHING, "mute");
    assert_eq!(passes[1].traced, NOTHING, "solo");
    // The cache keeps the lights of the world it served: the two lights back in the
    // picture cast their shadow rays again, and nothing else does.
    let back = passes[2].traced;
    assert_eq!((back.primary, back.reflection), (0, 0));
    assert_eq!(
        back.shadow,
        shadow_rays_of(&base, 1) + shadow_rays_of(&base, 2)
    );
}

#[test]
fn lights_added_to_a_scene_without_any_cast_all_their_shadow_rays_only() {
    let lit = Shot::of(example("default.ron"));
    let dark = lit.edited(|s, _| s.lights.retain(|l| matches!(l, Light::Ambient { .. })));
    let passes = edit_chain(&dark, &[lit.clone(), dark.clone()], "lights added, removed");
    let traced = passes[0].traced;
    assert_eq!((traced.primary, traced.reflection), (0, 0));
    assert_eq!(traced.shadow, lit.traced().rays.shadow);
    assert_eq!(passes[1].traced, NOTHING, "lights removed again");
}

#[test]
fn geometry_camera_size_and_hidden_objects_retrace_everything() {
    let base = Shot::of(example("default.ron"));
    let moved_object = base.edited(|s, _| {
        if let Transform::Trs(trs) = &mut s.objects[1].transform {
            trs.translate.x += 0.25;
        }
    });
    let other_shape = base.edited(|s, _| s.objects[2].shape = raylab::scene::Shape::Cube);
    let camera = base.edited(|s, _| s.camera.fov_deg += 1.0);
    let hidden = base.edited(|_, o| {
        o.isolation = Isolation::default();
        o.isolation.hidden_objects.insert(2);
    });
    let size = base.edited(|_, o| o.width = 63);
    let cache = base.cached(None).cache;
    let cases = [
        (&moved_object, RetraceReason::Objects),
        (&other_shape, RetraceReason::Objects),
        (&camera, RetraceReason::Camera),
        (&hidden, RetraceReason::Objects),
        (&size, RetraceReason::Size),
    ];
    for (shot, reason) in cases {
        let reuse = cache.reuse(&shot.world(), shot.options.width, shot.options.height);
        assert_eq!(reuse, Reuse::Retrace(reason));
        let pass = shot.cached(Some(&cache));
        assert!(!pass.reused, "{reason:?}");
        assert_eq!(pass.traced, pass.sums.rays, "{reason:?}: every ray traced");
        assert_same_pass(&pass.sums, &shot.traced(), &format!("{reason:?}"));
    }
    // A light moved is not a geometry edit: only its column goes.
    let world = base.world();
    let reuse = cache.reuse(&world, 64, 48);
    assert_eq!(reuse.recast_lights(), Vec::<usize>::new());
    let moved_light = base.edited(|s, _| {
        if let Light::Point { position, .. } = &mut s.lights[1] {
            position.y += 1.0;
        }
    });
    let reuse = cache.reuse(&moved_light.world(), 64, 48);
    assert!(reuse.is_reshade());
    assert_eq!(
        reuse.recast_lights(),
        vec![0],
        "world light 0 is scene light 1"
    );
}

/// A sphere light's hits keep the count of its rays that reached the light: an edit of
/// anything else re-shades them (the scenes of `SCENES` include one), while a new
/// radius, sample count or position recasts that light's rays and no other.
#[test]
fn a_sphere_lights_new_size_count_or_place_recasts_its_rays_only() {
    let base = Shot::of(example("soft_spot.ron"));
    let index = base
        .scene
        .lights
        .iter()
        .position(|l| matches!(l, Light::Spot { source: LightSource { radius, .. }, .. } if *radius > 0.0))
        .expect("the example's soft spot");
    let with = |change: fn(&mut Light)| base.edited(|s, _| change(&mut s.lights[index]));
    let edits = [
        (
            "twice the radius",
            with(|l| {
                if let Light::Spot {
                    source: LightSource { radius, .. },
                    ..
                } = l
                {
                    *radius *= 2.0
                }
            }),
        ),
        (
            "4 rays, not 16",
            with(|l| {
                if let Light::Spot {
                    source: LightSource { samples, .. },
                    ..
                } = l
                {
                    *samples = 4
                }
            }),
        ),
        (
            "moved",
            with(|l| {
                if let Light::Spot { position, .. } = l {
                    position.x += 0.3
                }
            }),
        ),
    ];
    for (what, edited) in edits {
        let passes = edit_chain(&base, std::slice::from_ref(&edited), what);
        let traced = passes[0].traced;
        assert!(passes[0].reused, "{what}");
        assert_eq!((traced.primary, traced.reflection), (0, 0), "{what}");
        assert!(traced.shadow > 0, "{what}");
        assert_eq!(traced.shadow, shadow_rays_of(&edited, index), "{what}");
    }
}
