//! Randomised mutation of the example scenes and the legacy test scenes, fed to both
//! loaders: a clear error or a correct load, never a panic. A few thousand cases run with
//! the suite; `RAYLAB_FUZZ_CASES=100000 cargo test --release --test fuzz_loaders -- --ignored`
//! runs the long mode.

use std::path::Path;

use proptest::prelude::*;
use raylab::scene::legacy::import_legacy;
use raylab::scene::{parse_scene, read_scene_meshes};
use raylab::trace::{MeshStore, RenderOptions, RenderProgress, World, render_samples};

fn corpus() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut texts = Vec::new();
    for folder in ["scenes", "tests/legacy", "tests/legacy_ext"] {
        let mut paths: Vec<_> = std::fs::read_dir(root.join(folder))
            .unwrap()
            .map(|e| e.unwrap().path())
            // The mesh scenes' OBJ files (and their folders) are no input of these loaders.
            .filter(|p| p.is_file() && p.extension().is_none_or(|e| !e.eq_ignore_ascii_case("obj")))
            .collect();
        paths.sort();
        texts.extend(paths.iter().map(|p| std::fs::read_to_string(p).unwrap()));
    }
    texts
}

/// Pieces of both languages that mutations splice in.
const TOKENS: &[&str] = &[
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    "\"",
    "//",
    "/*",
    "*/",
    "inf",
    "NaN",
    "-0.0",
    "1e308",
    "5e-324",
    "-1",
    "0",
    "4294967296",
    "Sphere",
    "Cone",
    "Matrix(",
    "Spot(",
    "End",
    "Object",
    "Material",
    "Scale 0",
    "Rotate Q 1",
    "#",
    "\n",
    "\u{feff}",
    "\u{0}",
    "é",
    "Scene(",
    "transform:",
    "angle_deg: 95.0",
    // The legacy extensions (issue 38).
    "Object CSG Union",
    "CSG Difference",
    "ObjectGroup",
    "Object Torus 0.5",
    "Object Tube 1.9",
    "Object Mesh meshes/pyramid.obj",
    "FSAA 1e9",
    "Samples 1e9",
    "Radius 0.5",
    "Opacity 0.3",
    "RefractiveIndex 1.5",
    "scaleResolution 1e9",
    "Supersampling",
    "End End",
];

#[derive(Clone, Debug)]
enum Mutation {
    Delete { at: usize, len: usize },
    Insert { at: usize, token: usize },
    Duplicate { at: usize, len: usize },
    Truncate { at: usize },
    FlipByte { at: usize, bit: u8 },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), 1..40usize).prop_map(|(at, len)| Mutation::Delete { at, len }),
        (any::<usize>(), 0..TOKENS.len()).prop_map(|(at, token)| Mutation::Insert { at, token }),
        (any::<usize>(), 1..200usize).prop_map(|(at, len)| Mutation::Duplicate { at, len }),
        any::<usize>().prop_map(|at| Mutation::Truncate { at }),
        (any::<usize>(), 0..8u8).prop_map(|(at, bit)| Mutation::FlipByte { at, bit }),
    ]
}

fn apply(text: &str, mutations: &[Mutation]) -> String {
    let mut bytes = text.as_bytes().to_vec();
    for m in mutations {
        let n = bytes.len().max(1);
        match *m {
            Mutation::Delete { at, len } => {
                let at = at % n;
                let end = (at + len).min(bytes.len());
                bytes.drain(at.min(end)..end);
            }
            Mutation::Insert { at, token } => {
                let at = at % (bytes.len() + 1);
                bytes.splice(at..at, TOKENS[token].bytes());
            }
            Mutation::Duplicate { at, len } => {
                let at = at % n;
                let end = (at + len).min(bytes.len());
                let piece = bytes[at.min(end)..end].to_vec();
                bytes.splice(end..end, piece);
            }
            Mutation::Truncate { at } => bytes.truncate(at % n),
            Mutation::FlipByte { at, bit } => {
                if !bytes.is_empty() {
                    let at = at % bytes.len();
                    bytes[at] ^= 1 << bit;
                }
            }
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

/// Both loaders on one input; a loaded scene must also compile and render finitely.
/// Returns whether either loader accepted it.
/// The compiled world of a loaded scene, which must compile.
fn compiled(
    scene: &raylab::scene::Scene,
    meshes: &std::collections::BTreeMap<String, raylab::scene::MeshData>,
) -> World {
    World::with_meshes(scene, &MeshStore::build(meshes))
        .unwrap_or_else(|e| panic!("a loaded scene compiles: {e}"))
}

fn check_input(text: &str) -> bool {
    let mut loaded = false;
    if let Ok(scene) = parse_scene(text) {
        loaded = true;
        // A scene with meshes compiles with its files (the example's, beside it); a
        // mutated path is refused by the mesh loader with an error, not compiled.
        let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        if let Ok(meshes) = read_scene_meshes(&scene, &folder) {
            let world = compiled(&scene, &meshes);
            let options = RenderOptions {
                width: 6,
                height: 4,
                samples_per_pixel: 1,
                ..RenderOptions::from_scene(&scene)
            };
            let sums = render_samples(&world, &options, 0..1, &RenderProgress::default()).unwrap();
            assert_eq!(sums.non_finite, 0);
        }
    }
    if let Ok(import) = import_legacy(text) {
        loaded = true;
        // Text alone keeps mesh paths as written: those of the extension scenes resolve
        // in their folder; any other is refused by the mesh loader, as for RON.
        let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy_ext");
        if let Ok(meshes) = read_scene_meshes(&import.scene, &folder) {
            compiled(&import.scene, &meshes);
        }
    }
    loaded
}

fn cases() -> u32 {
    std::env::var("RAYLAB_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000)
}

/// Runs `cases` mutated inputs; returns how many of them loaded.
fn fuzz(cases: u32) -> u32 {
    let corpus = corpus();
    let config = ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    let loaded = std::cell::Cell::new(0u32);
    proptest!(config, |(pick in any::<usize>(), mutations in prop::collection::vec(mutation(), 1..6))| {
        let text = apply(&corpus[pick % corpus.len()], &mutations);
        if check_input(&text) {
            loaded.set(loaded.get() + 1);
        }
    });
    loaded.get()
}

#[test]
fn mutated_scenes_never_panic_either_loader() {
    let cases = cases();
    let loaded = fuzz(cases);
    // Mutations that keep a file loadable exercise the renderer too; make sure some do.
    assert!(
        loaded > cases / 50,
        "only {loaded} of {cases} mutated inputs loaded"
    );
}

#[test]
#[ignore = "long mode: 100,000 cases (or RAYLAB_FUZZ_CASES)"]
fn mutated_scenes_never_panic_either_loader_long() {
    let cases = std::env::var("RAYLAB_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100_000);
    let started = std::time::Instant::now();
    let loaded = fuzz(cases);
    println!(
        "{cases} cases, {loaded} loaded, {:.1} s",
        started.elapsed().as_secs_f64()
    );
}
