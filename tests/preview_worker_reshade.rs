//! Edits through the real preview worker with its hit cache: an edit that moves nothing
//! publishes the full-resolution frame first, re-shaded, and it is the direct render's
//! image; the anti-aliasing passes that follow are too; a geometry edit restarts coarse.
//! No test here asserts a time; `raylab bench` measures `edit_to_full_frame_ms`.

mod worker_harness;

use glam::DVec3;
use raylab::preview::{Pass, PreviewRequest, Published};
use raylab::scene::{Scene, Transform};
use raylab::trace::{RenderOptions, RenderProgress, Term, World, render};
use worker_harness::{small_scene, until_final, worker_with_counter};

/// The picture `raylab render` makes of `request` at `samples` per pixel.
fn direct(request: &PreviewRequest, samples: u32) -> Vec<glam::Vec3> {
    let world = World::isolated(&request.scene, &request.options.isolation).unwrap();
    let options = RenderOptions {
        samples_per_pixel: samples,
        ..request.options.clone()
    };
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
        .pixels
}

/// The passes of one generation's messages, each checked against the direct render.
fn checked_passes(messages: &[Published], request: &PreviewRequest) -> Vec<Pass> {
    let mut passes = Vec::new();
    for message in messages
        .iter()
        .filter(|m| m.generation == request.generation)
    {
        let frame = message.result.as_ref().expect("the scene renders");
        if let Pass::Full { samples, .. } = frame.pass {
            assert!(
                frame.image.pixels == direct(request, samples),
                "{:?} of generation {}",
                frame.pass,
                request.generation
            );
        }
        passes.push(frame.pass);
    }
    passes
}

fn edited(
    request: &PreviewRequest,
    generation: u64,
    edit: impl FnOnce(&mut Scene),
) -> PreviewRequest {
    let mut scene = (*request.scene).clone();
    edit(&mut scene);
    PreviewRequest {
        generation,
        scene: std::sync::Arc::new(scene),
        options: request.options.clone(),
        meshes: request.meshes.clone(),
        scene_folder: request.scene_folder.clone(),
    }
}

#[test]
fn edits_that_move_no_object_re_shade_and_match_the_direct_render() {
    let (mut worker, _) = worker_with_counter();
    let base = PreviewRequest::for_scene(1, small_scene(320, 240, 4));
    worker.submit(base.clone());
    let first = checked_passes(&until_final(&mut worker, 1), &base);
    assert_eq!(first[0], Pass::Coarse { divider: 4 }, "nothing cached yet");

    let material = edited(&base, 2, |s| {
        s.materials.get_mut("red plastic").unwrap().mirror = DVec3::splat(0.6);
    });
    let mut switch = edited(&material, 3, |_| {});
    switch.options.switches.set(Term::Specular, false);
    let light = edited(&switch, 4, |s| {
        if let raylab::scene::Light::Point { position, .. } = &mut s.lights[1] {
            position.x += 0.5;
        }
    });
    for request in [&material, &switch, &light] {
        worker.submit(request.clone());
        let passes = checked_passes(&until_final(&mut worker, request.generation), request);
        let full_first = [
            Pass::Full {
                samples: 1,
                target: 1,
            },
            Pass::Full {
                samples: 4,
                target: 4,
            },
        ];
        // A light moved casts its shadow rays again, about a traced frame's work: the
        // coarsest pass comes first, so that a light being dragged is seen moving.
        let expected = if request.generation == light.generation {
            [&[Pass::Coarse { divider: 4 }][..], &full_first].concat()
        } else {
            full_first.to_vec()
        };
        assert_eq!(passes, expected, "generation {}", request.generation);
    }

    let moved = edited(&light, 5, |s| {
        if let Transform::Trs(trs) = &mut s.objects[1].transform {
            trs.translate.y += 0.1;
        }
    });
    worker.submit(moved.clone());
    let passes = checked_passes(&until_final(&mut worker, 5), &moved);
    assert_eq!(passes[0], Pass::Coarse { divider: 4 }, "geometry re-traces");
    assert_eq!(passes.len(), 4);
}

/// Glass makes trees of rays; the worker's cache holds them, so an edit of the glass
/// (its colour, its transmission, its index, the transmission switch) is re-shaded, the
/// direct render's image, as for a scene without glass.
#[test]
fn edits_of_glass_re_shade_through_the_worker() {
    let (mut worker, _) = worker_with_counter();
    let text = raylab::scene::examples::EXAMPLE_SCENES
        .iter()
        .find(|(name, _)| *name == "glass.ron")
        .unwrap()
        .1;
    let mut scene = raylab::scene::parse_scene(text).unwrap();
    scene.camera.width = 160;
    scene.camera.height = 120;
    scene.render.samples_per_pixel = 2;
    let base = PreviewRequest::for_scene(1, scene);
    worker.submit(base.clone());
    let first = checked_passes(&until_final(&mut worker, 1), &base);
    assert!(
        matches!(first[0], Pass::Coarse { .. }),
        "nothing cached yet"
    );

    let tinted = edited(&base, 2, |s| {
        let glass = s.materials.get_mut("glass").unwrap();
        glass.diffuse = DVec3::new(0.3, 0.02, 0.02);
        glass.transmission = DVec3::new(0.5, 0.8, 0.9);
    });
    let water = edited(&tinted, 3, |s| {
        s.materials.get_mut("glass").unwrap().ior = 1.33
    });
    let mut no_glass = edited(&water, 4, |_| {});
    no_glass.options.switches.set(Term::Transmission, false);
    let one_sample = Pass::Full {
        samples: 1,
        target: 1,
    };
    for request in [&tinted, &water, &no_glass] {
        worker.submit(request.clone());
        let passes = checked_passes(&until_final(&mut worker, request.generation), request);
        // A new index traces the rays below the glass again, about a frame's work: the
        // coarsest pass comes first, as for a light moved.
        let re_shaded = if request.generation == water.generation {
            assert_eq!(passes[0], first[0], "the coarsest pass");
            passes[1]
        } else {
            passes[0]
        };
        assert_eq!(re_shaded, one_sample, "generation {}", request.generation);
    }
}
