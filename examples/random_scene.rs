//! Writes the random scene of a seed (the scenes `raylab bench --diff-accuracy` plants
//! bugs in) as a RON file, to reproduce one of its cases by hand:
//!
//! ```sh
//! cargo run --release --example random_scene -- 3 /tmp/random3.ron   # tuning seed 3, 200x150
//! raylab render /tmp/random3.ron --bug extra-object -o /tmp/bug.png
//! raylab diff /tmp/random3.ron /tmp/bug.png --spp 1
//! ```

use std::path::Path;

use raylab::bench::random_scene::random_scene;
use raylab::scene::save_scene;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(seed), Some(path)) = (args.first().and_then(|s| s.parse().ok()), args.get(1)) else {
        eprintln!("usage: random_scene SEED OUT.ron [WIDTH]");
        std::process::exit(2);
    };
    let width: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(200);
    let scene = random_scene(seed, width, width * 3 / 4);
    if let Err(e) = save_scene(&scene, Path::new(path)) {
        eprintln!("{e}");
        std::process::exit(1);
    }
}
