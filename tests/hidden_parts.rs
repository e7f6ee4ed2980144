//! Hiding a part of an object tree: a hidden part counts as empty space (a hidden pip no
//! longer cuts the die, as if it were not there; a lens, the intersection of two balls,
//! is empty with one ball hidden), and every other node keeps its path, so picks still
//! name the right parts.

use std::collections::BTreeSet;
use std::path::Path;

use raylab::scene::tree::siblings_mut;
use raylab::scene::{Scene, load_scene};
use raylab::trace::{
    Image, Isolation, PinholeCamera, RenderOptions, RenderProgress, TermSwitches, View, World,
    render,
};

fn csg_scene() -> Scene {
    load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron")).unwrap()
}

fn picture(scene: &Scene, isolation: &Isolation) -> Image {
    let world = World::isolated(scene, isolation).unwrap();
    let options = RenderOptions {
        width: 160,
        height: 120,
        samples_per_pixel: 1,
        switches: TermSwitches::ALL_ON,
        view: View::Beauty,
        isolation: isolation.clone(),
    };
    render(&world, &options, &RenderProgress::default())
        .unwrap()
        .0
}

fn hiding(paths: &[&[usize]]) -> Isolation {
    Isolation {
        hidden_parts: paths.iter().map(|p| p.to_vec()).collect::<BTreeSet<_>>(),
        ..Isolation::NONE
    }
}

#[test]
fn a_hidden_part_counts_as_empty_space() {
    let scene = csg_scene();
    let die = scene.objects.iter().position(|o| o.name == "die").unwrap();
    let lens = scene.objects.iter().position(|o| o.name == "lens").unwrap();
    // Pips cut from the die: hidden, they cut nothing, as if they were not there.
    let hidden = [vec![die, 1], vec![die, 8]];
    let isolation = hiding(&[&hidden[0], &hidden[1]]);
    let mut without = scene.clone();
    // Removed from the back so the earlier paths stay right.
    for path in hidden.iter().rev() {
        let list = siblings_mut(&mut without.objects, path).unwrap();
        list.remove(path[path.len() - 1]);
    }
    let shown = picture(&scene, &isolation).to_rgba8();
    let expected = picture(&without, &Isolation::NONE).to_rgba8();
    let full = picture(&scene, &Isolation::NONE).to_rgba8();
    assert_eq!(
        differing(&shown, &expected),
        (0, 0),
        "against the scene without them"
    );
    assert!(
        differing(&shown, &full).0 > 20,
        "the parts show in the full picture"
    );
    // Half a lens hidden: the intersection with empty space is empty.
    let half = picture(&scene, &hiding(&[&[lens, 1]])).to_rgba8();
    let no_lens = Isolation {
        hidden_objects: BTreeSet::from([lens]),
        ..Isolation::NONE
    };
    assert_eq!(
        differing(&half, &picture(&scene, &no_lens).to_rgba8()),
        (0, 0)
    );
}

#[test]
fn other_parts_keep_their_paths_while_one_is_hidden() {
    let scene = csg_scene();
    let die = scene.objects.iter().position(|o| o.name == "die").unwrap();
    let isolation = hiding(&[&[die, 1]]);
    let full = World::isolated(&scene, &Isolation::NONE).unwrap();
    let hidden = World::isolated(&scene, &isolation).unwrap();
    let camera = PinholeCamera::new(&scene.camera, 160, 120);
    let mut same = 0;
    for y in 0..120 {
        for x in 0..160 {
            let ray = camera.ray(glam::DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
            let (Some(a), Some(b)) = (
                full.intersect(&ray, f64::INFINITY),
                hidden.intersect(&ray, f64::INFINITY),
            ) else {
                continue;
            };
            let (pa, pb) = (full.node_path(&a), hidden.node_path(&b));
            assert_ne!(pb, vec![die, 1], "the hidden pip is never hit");
            if pa != vec![die, 1] && a.t == b.t {
                assert_eq!(pa, pb, "pixel ({x}, {y})");
                same += 1;
            }
        }
    }
    assert!(same > 1000, "{same}");
}

/// How many pixels differ, and by how much at most (in 8-bit levels).
fn differing(a: &[u8], b: &[u8]) -> (usize, u8) {
    let mut count = 0;
    let mut most = 0;
    for (p, q) in a.chunks(4).zip(b.chunks(4)) {
        let d = p
            .iter()
            .zip(q)
            .map(|(x, y)| x.abs_diff(*y))
            .max()
            .unwrap_or(0);
        if d > 0 {
            count += 1;
            most = most.max(d);
        }
    }
    (count, most)
}
