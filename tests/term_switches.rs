//! The term switches: solos add up to the full picture, switches change what they say.

use std::path::Path;

use raylab::scene::load_scene;
use raylab::trace::{
    Image, Isolation, RenderOptions, RenderProgress, Term, TermSwitches, View, World,
    inspect_pixel, render,
};

fn default_world(switches: TermSwitches) -> (World, RenderOptions) {
    let scene =
        load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron")).unwrap();
    let options = RenderOptions {
        width: 96,
        height: 72,
        samples_per_pixel: 1,
        switches,
        view: View::Beauty,
        isolation: Isolation::NONE,
    };
    (World::new(&scene).unwrap(), options)
}

fn render_default(switches: TermSwitches, view: View) -> Image {
    let (world, options) = default_world(switches);
    let options = RenderOptions { view, ..options };
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
}

#[test]
fn solo_ambient_diffuse_specular_reflection_add_up_to_the_full_picture() {
    let full = render_default(TermSwitches::ALL_ON, View::Beauty);
    let solos: Vec<Image> = [
        Term::Ambient,
        Term::Diffuse,
        Term::Specular,
        Term::Reflection,
    ]
    .into_iter()
    .map(|t| render_default(TermSwitches::ALL_ON.with_solo(Some(t)), View::Beauty))
    .collect();
    let mut lit_pixels = 0;
    for (i, expected) in full.pixels.iter().enumerate() {
        let sum: glam::Vec3 = solos.iter().map(|s| s.pixels[i]).sum();
        let tolerance = 1e-5 * expected.abs().max_element().max(1.0);
        assert!(
            (sum - *expected).abs().max_element() <= tolerance,
            "pixel {i}: {sum} vs {expected}"
        );
        if expected.max_element() > 0.1 {
            lit_pixels += 1;
        }
    }
    assert!(lit_pixels > full.pixels.len() / 2);
    // Each solo shows something on its own: the sum is not one term doing all the work.
    for solo in &solos {
        assert!(solo.pixels.iter().any(|p| p.max_element() > 0.05));
    }
}

#[test]
fn switching_a_term_off_removes_at_least_its_solo() {
    let full = render_default(TermSwitches::ALL_ON, View::Beauty);
    let mut no_specular = TermSwitches::ALL_ON;
    no_specular.set(Term::Specular, false);
    let without = render_default(no_specular, View::Beauty);
    // Off applies at every depth, so compare against the full minus solo specular only
    // where no mirror is involved: the primary-level difference is at least the solo.
    let solo = render_default(
        TermSwitches::ALL_ON.with_solo(Some(Term::Specular)),
        View::Beauty,
    );
    for i in 0..full.pixels.len() {
        let removed = full.pixels[i] - without.pixels[i];
        assert!(
            (removed - solo.pixels[i]).min_element() >= -1e-5,
            "pixel {i}"
        );
    }
    assert_ne!(full, without);
}

#[test]
fn shadows_off_never_darkens_and_solo_shadows_is_the_mask() {
    let full = render_default(TermSwitches::ALL_ON, View::Beauty);
    let mut no_shadows = TermSwitches::ALL_ON;
    no_shadows.set(Term::Shadows, false);
    let unshadowed = render_default(no_shadows, View::Beauty);
    assert!(
        full.pixels
            .iter()
            .zip(&unshadowed.pixels)
            .all(|(a, b)| (*b - *a).min_element() >= -1e-6)
    );
    assert!(
        full.pixels
            .iter()
            .zip(&unshadowed.pixels)
            .any(|(a, b)| (*b - *a).max_element() > 0.05)
    );

    let mask = render_default(
        TermSwitches::ALL_ON.with_solo(Some(Term::Shadows)),
        View::Beauty,
    );
    // The mask says what the shading saw: at every pixel, the share of the lights in
    // front of the surface whose shadow ray the beauty pass found unblocked, as the
    // pixel inspector records it from the shading code (not from the mask's own code).
    let (world, options) = default_world(TermSwitches::ALL_ON);
    let mut shadowed = 0;
    for py in 0..options.height {
        for px in 0..options.width {
            let report = inspect_pixel(&world, &options, px, py);
            let primary = &report.bounces[0];
            let in_front: Vec<_> = primary.lights.iter().filter(|l| l.n_dot_l > 0.0).collect();
            let expected = if primary.hit.is_none() || in_front.is_empty() {
                0.0
            } else {
                assert!(in_front.iter().all(|l| l.shadow_ray_cast), "({px}, {py})");
                let lit = in_front.iter().filter(|l| l.blocked_by.is_none()).count();
                (lit as f64 / in_front.len() as f64) as f32
            };
            shadowed += usize::from(expected < 1.0 && !in_front.is_empty());
            assert_eq!(mask.get(px, py).x, expected, "({px}, {py})");
        }
    }
    assert!(
        shadowed > 100,
        "the default scene has shadows ({shadowed} pixels)"
    );
    assert!(
        mask.pixels
            .iter()
            .all(|p| p.x == p.y && p.y == p.z && (0.0..=1.0).contains(&p.x))
    );
    assert!(
        mask.pixels.iter().any(|p| p.x == 1.0)
            && mask.pixels.iter().any(|p| p.x > 0.0 && p.x < 1.0)
    );
    let mask_no_shadows = render_default(no_shadows.with_solo(Some(Term::Shadows)), View::Beauty);
    assert!(
        mask_no_shadows
            .pixels
            .iter()
            .all(|p| p.x == 0.0 || p.x == 1.0)
    );
}

#[test]
fn debug_views_are_in_range_and_distinct() {
    for view in [View::Normal, View::Depth, View::ObjectId, View::ShadowMask] {
        let image = render_default(TermSwitches::ALL_ON, view);
        assert!(
            image
                .pixels
                .iter()
                .all(|p| p.min_element() >= 0.0 && p.max_element() <= 1.0),
            "{view}"
        );
        assert_ne!(image, render_default(TermSwitches::ALL_ON, View::Beauty));
    }
    let ids = render_default(TermSwitches::ALL_ON, View::ObjectId);
    let mut distinct: Vec<[u32; 3]> = ids
        .pixels
        .iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect();
    distinct.sort_unstable();
    distinct.dedup();
    // 6 objects and the background.
    assert!(distinct.len() >= 7, "{}", distinct.len());
}
