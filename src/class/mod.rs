//! `raylab class`: a whole class at once. A folder of scenes and a folder per student
//! of renders become one report: every pair compared as `raylab diff` compares (the
//! named bugs, PSNR) and scored with LDR-FLIP, in a table, a summary of the bugs across
//! the class, and feedback per student (see docs/COMPARE.md, "A whole class").
//!
//! 1. [`roster`]: which render is of which scene (by file name), what matched nothing.
//! 2. [`run`]: the pairs in parallel, reused from the [`cache`] where done before; one
//!    [`pair`] is one comparison and its images, against its scene prepared once for
//!    all of its pairs ([`shared`]).
//! 3. [`feedback`], [`tables`], [`page`]: the words, class.csv and class.json, and
//!    index.html.
//!
//! Built on [`crate::compare`]'s public face; no egui here.

pub mod cache;
pub mod feedback;
pub mod page;
pub mod pair;
pub mod roster;
pub mod run;
pub mod shared;
pub mod tables;

use std::path::Path;

pub use pair::{Finding, PairResult};
pub use roster::{Roster, Student};
pub use run::{ClassOptions, ClassRun, Outcome, PairRow, run_class};

/// The report's page.
pub const PAGE: &str = "index.html";
/// The report's table of pairs as CSV.
pub const CSV: &str = "class.csv";
/// The report's table of pairs and everything else as JSON.
pub const JSON: &str = "class.json";

/// Writes index.html, class.csv and class.json of `run` into `report` (the pairs'
/// images are already in its cache folder).
///
/// # Errors
/// A write's error, naming the file.
pub fn write_report(run: &ClassRun, report: &Path) -> Result<(), String> {
    let write = |name: &str, text: &str| {
        let path = report.join(name);
        crate::scene::write_atomically(&path, text.as_bytes())
            .map_err(|e| format!("cannot write {}: {e}", path.display()))
    };
    write(CSV, &tables::class_csv(run)?)?;
    write(JSON, &tables::class_json(run))?;
    write(PAGE, &page::class_page(run))
}
