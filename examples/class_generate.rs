//! Writes a generated class for timing `raylab class` at class scale
//! (scripts/class_bench.sh): the example scenes at a size, and students whose renders
//! are raylab's own with planted bugs (see `raylab::bench::class`).
//!
//! ```sh
//! cargo run --release --example class_generate -- DIR STUDENTS SCENES WIDTH HEIGHT
//! ```
//!
//! DIR gets `scenes/` and `submissions/student_NN/`.

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: class_generate DIR STUDENTS SCENES WIDTH HEIGHT";
    let [dir, students, scenes, width, height] = args.as_slice() else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let number = |text: &str| -> usize { text.parse().unwrap_or_else(|_| panic!("{usage}")) };
    let size = (number(width) as u32, number(height) as u32);
    match raylab::bench::class::generate_class(
        std::path::Path::new(dir),
        number(students),
        number(scenes),
        size,
    ) {
        Ok(pairs) => eprintln!("{dir}: {pairs} pairs"),
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    }
}
