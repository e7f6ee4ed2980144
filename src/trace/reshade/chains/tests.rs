//! The entries' links: chains stay without them, the first tree gives every pixel its
//! links, children are found by parent and branch, and pruning keeps all but the cut.

use glam::DVec3;

use super::*;
use crate::trace::world::SurfacePoint;

/// A hit on `object`, with `t` to tell entries apart.
fn hit(object: usize, t: f64) -> CachedHit {
    CachedHit::new(Some(&SurfacePoint {
        object,
        part: 0,
        t,
        p: DVec3::splat(t),
        n_outward: DVec3::Z,
        n: DVec3::Z,
        p_error: DVec3::ZERO,
    }))
}

/// The `t` of every entry of pixel `pixel`.
fn ts(chains: &Chains, pixel: usize) -> Vec<f64> {
    let range = chains.chain(pixel);
    range.map(|e| chains.hit(e).point().unwrap().t).collect()
}

const M: ChildRay = ChildRay::Mirror;
const T: ChildRay = ChildRay::Transmitted;

/// Pixel 0: a mirror chain of three entries. Pixel 1: a camera ray's hit on object 0
/// with a mirror ray (object 1) and a transmitted one (object 2), and the transmitted
/// ray's own mirror ray (object 3).
fn two_pixels() -> Chains {
    let mut chains = Chains::with_capacity(2, 8);
    assert_eq!(chains.push(None, hit(5, 1.0)), 0);
    assert_eq!(chains.push(Some((0, M)), hit(5, 2.0)), 1);
    assert_eq!(chains.push(Some((1, M)), hit(6, 3.0)), 2);
    chains.end_chain();
    assert!(!chains.has_trees(), "a mirror chain keeps no links");
    chains.push(None, hit(0, 10.0));
    chains.push(Some((0, T)), hit(2, 12.0));
    chains.push(Some((0, M)), hit(1, 11.0));
    chains.push(Some((1, M)), hit(3, 13.0));
    chains.end_chain();
    chains
}

#[test]
fn a_tree_links_every_pixel_and_children_are_found_by_parent_and_branch() {
    let chains = two_pixels();
    assert!(chains.has_trees());
    // The chain before the tree got chain links.
    let chain = chains.chain(0);
    assert_eq!(chains.child(chain.clone(), 0, M), Some(1));
    assert_eq!(chains.child(chain.clone(), 1, M), Some(2));
    assert_eq!(chains.child(chain.clone(), 2, M), None);
    assert_eq!(chains.child(chain, 0, T), None);
    // The tree: entries in the order traced, found by their place.
    let tree = chains.chain(1);
    assert_eq!(ts(&chains, 1), [10.0, 12.0, 11.0, 13.0]);
    assert_eq!(chains.child(tree.clone(), 0, M), Some(2));
    assert_eq!(chains.child(tree.clone(), 0, T), Some(1));
    assert_eq!(chains.child(tree.clone(), 1, M), Some(3));
    assert_eq!(chains.child(tree.clone(), 2, M), None);
    assert_eq!(chains.objects(tree), [0, 2, 1, 3]);
}

#[test]
fn copying_a_pixel_keeps_its_links_whichever_side_has_them() {
    let trees = two_pixels();
    let mut chain_only = Chains::with_capacity(1, 3);
    chain_only.push(None, hit(4, 1.0));
    chain_only.push(Some((0, M)), hit(4, 2.0));
    chain_only.end_chain();
    // A chain into chains with links, and a tree into chains without.
    let mut copy = trees.prefix(2, trees.len());
    copy.extend_from(&chain_only, chain_only.chain(0));
    copy.end_chain();
    assert_eq!(copy.child(copy.chain(2), 0, M), Some(1));
    let mut copy = chain_only.prefix(1, chain_only.len());
    copy.extend_from(&trees, trees.chain(1));
    copy.end_chain();
    assert!(copy.has_trees());
    assert_eq!(copy.child(copy.chain(0), 0, M), Some(1));
    assert_eq!(copy.child(copy.chain(1), 1, M), Some(3));
}

#[test]
fn pruning_drops_exactly_the_entries_below_a_cut_ray() {
    let chains = two_pixels();
    // One light: each entry's slot says which entry it was.
    let slots: Vec<LightSlot> = (0..chains.len() as u32)
        .map(|entry| LightSlot {
            shadow: entry,
            ..LightSlot::NOTHING
        })
        .collect();
    let cut_nothing = chains.pruned(&slots, 1, |object, child| object == 9 && child == T);
    assert!(cut_nothing.is_none(), "no entry on object 9");
    // Object 0's transmitted ray: its entry and that entry's mirror ray go.
    let (kept, kept_slots) = chains
        .pruned(&slots, 1, |object, child| object == 0 && child == T)
        .unwrap();
    assert_eq!(ts(&kept, 0), [1.0, 2.0, 3.0]);
    assert_eq!(ts(&kept, 1), [10.0, 11.0]);
    let tree = kept.chain(1);
    assert_eq!(kept.child(tree.clone(), 0, M), Some(1));
    assert_eq!(kept.child(tree.clone(), 0, T), None);
    assert_eq!(kept.child(tree, 1, M), None);
    let shadows: Vec<u32> = kept_slots.iter().map(|s| s.shadow).collect();
    assert_eq!(shadows, [0, 1, 2, 3, 5]);
}
