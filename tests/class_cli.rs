//! `raylab class` on the command line: the report's files, the summary line with pairs
//! compared and reused, a rerun reusing the cache, and a report folder inside the
//! submissions refused with a non-zero exit.

mod common;

#[path = "class/generated.rs"]
mod generated;

use common::cli::raylab;

#[test]
fn class_writes_the_report_and_a_rerun_reuses_it() {
    let class = generated::generate("cli");
    let report = class.root.join("report");
    let (scenes, submissions) = (class.scenes_dir(), class.submissions_dir());
    let args = [
        "class",
        scenes.to_str().unwrap(),
        submissions.to_str().unwrap(),
        "-o",
        report.to_str().unwrap(),
    ];
    let first = raylab(&args);
    let stderr = String::from_utf8_lossy(&first.stderr);
    assert!(first.status.success(), "{stderr}");
    assert!(
        stderr
            .contains("4 students x 3 scenes; 7 pairs compared, 0 reused from the cache, 2 errors"),
        "{stderr}"
    );
    for file in ["index.html", "class.csv", "class.json"] {
        assert!(report.join(file).is_file(), "{file}");
    }
    let again = raylab(&args);
    let stderr = String::from_utf8_lossy(&again.stderr);
    assert!(
        stderr.contains("0 pairs compared, 7 reused from the cache"),
        "{stderr}"
    );

    let inside = class.submissions_dir().join("report");
    let refused = raylab(&[
        "class",
        scenes.to_str().unwrap(),
        submissions.to_str().unwrap(),
        "-o",
        inside.to_str().unwrap(),
    ]);
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("overlap"));
}
