//! The preview's final frame is the command line's picture: bit-identical for the same
//! switches and views, and samples added in batches sum exactly as in one go.

mod common;
mod worker_harness;

use common::cli::cli_options;
use raylab::preview::{Pass, PreviewRequest};
use raylab::trace::{
    Image, RenderOptions, RenderProgress, SampleSums, Term, View, World, render, render_samples,
    render_samples_into,
};
use worker_harness::{small_scene, until_final, worker_with_counter};

/// Whether two images are equal pixel for pixel (exact f32 equality).
fn identical(a: &Image, b: &Image) -> bool {
    a.width == b.width && a.height == b.height && a.pixels == b.pixels
}

#[test]
fn the_final_frame_is_bit_identical_to_the_cli_render_for_the_same_switches() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(160, 120, 16);
    let world = World::new(&scene).unwrap();
    let cases: [(&[Term], Option<Term>, View); 5] = [
        (&[], None, View::Beauty),
        (&[Term::Diffuse], None, View::Beauty),
        (&[Term::Shadows], Some(Term::Specular), View::Beauty),
        (&[], Some(Term::Reflection), View::Beauty),
        (&[Term::Ambient], None, View::Normal),
    ];
    for (generation, (off, solo, view)) in (1..).zip(cases) {
        let options = cli_options(&scene, off, solo, view);
        let mut request = PreviewRequest::for_scene(generation, scene.clone());
        request.options = options.clone();
        worker.submit(request);
        let messages = until_final(&mut worker, generation);
        let last = messages.last().unwrap().result.as_ref().unwrap();
        assert_eq!(
            last.pass,
            Pass::Full {
                samples: 16,
                target: 16
            }
        );
        let (direct, _) = render(&world, &options, &RenderProgress::default()).unwrap();
        assert!(
            identical(&last.image, &direct),
            "off {off:?} solo {solo:?} view {view}: the preview differs from the CLI"
        );
        assert_eq!(last.non_finite_samples, 0);
    }
}

#[test]
fn a_one_sample_scene_ends_on_the_cli_image_too() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(200, 100, 1);
    let options = cli_options(&scene, &[Term::Specular], None, View::ShadowMask);
    let mut request = PreviewRequest::for_scene(1, scene.clone());
    request.options = options.clone();
    worker.submit(request);
    let messages = until_final(&mut worker, 1);
    let last = messages.last().unwrap().result.as_ref().unwrap();
    let world = World::new(&scene).unwrap();
    let (direct, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    assert!(identical(&last.image, &direct));
}

#[test]
fn samples_added_in_batches_sum_exactly_as_in_one_go() {
    let scene = small_scene(48, 32, 8);
    let world = World::new(&scene).unwrap();
    let options = RenderOptions::from_scene(&scene);
    let progress = RenderProgress::default();
    let at_once = render_samples(&world, &options, 0..8, &progress).unwrap();
    let mut batched = SampleSums::zero(48, 32);
    let mut rays = 0;
    for batch in [0..1, 1..4, 4..8] {
        rays += render_samples_into(&world, &options, batch, &mut batched, &progress)
            .unwrap()
            .total();
    }
    assert_eq!(batched.sums, at_once.sums);
    assert_eq!(batched.rays, at_once.rays);
    assert_eq!(rays, at_once.rays.total());
}
