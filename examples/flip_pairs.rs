//! raylab's LDR-FLIP of pairs of 8-bit pictures, one JSON object per line, for
//! scripts/flip_check.py to hold against the `flip-evaluator` Python package.
//!
//! ```sh
//! cargo run --release --example flip_pairs -- REFERENCE.png TEST.png [REFERENCE TEST ...]
//! ```

use std::path::Path;

use raylab::compare::OtherImage;
use raylab::compare::perceptual::ldr_flip;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.is_empty() || !args.len().is_multiple_of(2) {
        eprintln!("usage: flip_pairs REFERENCE TEST [REFERENCE TEST ...]");
        std::process::exit(2);
    }
    for pair in args.chunks(2) {
        let load = |p: &str| OtherImage::load(Path::new(p)).unwrap_or_else(|e| panic!("{e}"));
        let (reference, test) = (load(&pair[0]), load(&pair[1]));
        let flip = ldr_flip(reference.width, reference.height, &reference.rgb, &test.rgb);
        println!(
            "{}",
            serde_json::json!({
                "reference": pair[0],
                "test": pair[1],
                "mean": flip.mean,
                "p99": flip.p99,
            })
        );
    }
}
