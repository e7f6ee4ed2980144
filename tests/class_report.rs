//! `raylab class` on a generated class (tests/class/generated.rs): the table, class.csv
//! and class.json name the planted bugs; a missing render, a wrong-size picture and an
//! unreadable one are rows; stray files are listed; a rerun reuses the cache, a stopped
//! run keeps what is done; the inputs are never written; the page references only files
//! inside the report.

#[path = "class/generated.rs"]
mod generated;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use generated::{HIDDEN_IN_SHAPES, first_lit, generate, snapshot};
use raylab::bench::class::{PlantedBug, render_with_bug};
use raylab::class::{ClassOptions, ClassRun, Finding, Outcome, run_class, write_report};
use raylab::compare::{CompareOptions, OtherImage, compare_with_meshes};
use raylab::scene::load_any_scene;
use raylab::trace::{MeshStore, RenderProgress, Term};

fn run(class: &generated::Class, report: &Path) -> ClassRun {
    run_class(
        &class.scenes_dir(),
        &class.submissions_dir(),
        report,
        &ClassOptions::default(),
        &AtomicBool::new(false),
        &|_, _| {},
    )
    .unwrap()
}

fn outcome<'a>(run: &'a ClassRun, student: &str, scene: &str) -> &'a Outcome {
    let s = run
        .roster
        .students
        .iter()
        .position(|x| x.name == student)
        .unwrap();
    let c = run
        .roster
        .scenes
        .iter()
        .position(|x| x.name == scene)
        .unwrap();
    &run.rows
        .iter()
        .find(|r| r.student == s && r.scene == c)
        .unwrap()
        .outcome
}

fn findings<'a>(run: &'a ClassRun, student: &str, scene: &str) -> &'a [Finding] {
    match outcome(run, student, scene) {
        Outcome::Done { result, .. } => &result.findings,
        other => panic!("{student}/{scene}: {other:?}"),
    }
}

fn top(run: &ClassRun, student: &str, scene: &str) -> Finding {
    findings(run, student, scene)
        .first()
        .unwrap_or_else(|| panic!("{student}/{scene}: no finding"))
        .clone()
}

#[test]
fn the_table_csv_and_json_name_the_planted_bugs() {
    let class = generate("bugs");
    let report = class.root.join("report");
    let run = run(&class, &report);
    write_report(&run, &report).unwrap();

    let lit = first_lit(class.scene("spotlights"));
    let hidden = class.scene("shapes").objects[HIDDEN_IN_SHAPES].name.clone();
    // The planted bugs, as the comparison names them.
    let muted = top(&run, "bob", "spotlights");
    assert_eq!(
        (muted.light, muted.factor < 0.1),
        (Some(lit), true),
        "{muted:?}"
    );
    let missing = top(&run, "bob", "shapes");
    assert_eq!(missing.cause, "missing-object", "{missing:?}");
    assert_eq!(missing.object.as_deref(), Some(hidden.as_str()));
    let specular = top(&run, "cat", "default");
    assert_eq!(
        (specular.term.as_str(), specular.factor < 0.1),
        ("specular", true),
        "{specular:?}"
    );
    let shadows = top(&run, "dan", "default");
    assert_eq!(
        (shadows.term.as_str(), shadows.factor < 0.1),
        ("shadows", true),
        "{shadows:?}"
    );
    // The right renders: nothing found, identical.
    for scene in ["default", "shapes", "spotlights"] {
        assert!(findings(&run, "ann", scene).is_empty(), "ann/{scene}");
        let Outcome::Done { result, .. } = outcome(&run, "ann", scene) else {
            unreachable!()
        };
        assert_eq!(
            (result.psnr_db, result.flip_mean),
            (100.0, 0.0),
            "ann/{scene}"
        );
    }
    // A planted bug is a visible difference.
    let Outcome::Done { result, .. } = outcome(&run, "bob", "shapes") else {
        unreachable!()
    };
    assert!(
        result.flip_mean > 0.0 && result.flip_p99 >= result.flip_mean,
        "{result:?}"
    );

    // class.csv: a row per student and scene, each explanation's fields.
    let csv_text = std::fs::read_to_string(report.join("class.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(csv_text.as_bytes());
    let header = reader.headers().unwrap().clone();
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let records: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(records.len(), 4 * 3);
    let record = |student: &str, scene: &str| {
        records
            .iter()
            .find(|r| &r[column("student")] == student && &r[column("scene")] == scene)
            .unwrap()
    };
    let bob_shapes = record("bob", "shapes");
    assert_eq!(&bob_shapes[column("explanation_1_cause")], "missing-object");
    assert_eq!(&bob_shapes[column("explanation_1_object")], hidden);
    assert_eq!(
        &record("bob", "spotlights")[column("explanation_1_light")],
        lit.to_string()
    );
    assert_eq!(
        &record("cat", "default")[column("explanation_1_term")],
        "specular"
    );
    assert_eq!(
        &record("dan", "default")[column("explanation_1_term")],
        "shadows"
    );
    assert_eq!(&record("ann", "default")[column("psnr_db")], "100");
    let number = |field: &str| -> f64 {
        bob_shapes[column(&format!("explanation_1_{field}"))]
            .parse()
            .unwrap()
    };
    // A hidden object: its geometry missing (factor 0), nearly all of the difference.
    assert!(number("factor").abs() < 0.01, "{}", number("factor"));
    assert!(
        (0.9..=1.0).contains(&number("share")),
        "{}",
        number("share")
    );

    // class.json: the same, and the bugs across the class.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(report.join("class.json")).unwrap()).unwrap();
    let pairs = json["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), 12);
    let pair = |student: &str, scene: &str| {
        pairs
            .iter()
            .find(|p| p["student"] == student && p["scene"] == scene)
            .unwrap()
    };
    assert_eq!(
        pair("bob", "shapes")["explanations"][0]["cause"],
        "missing-object"
    );
    assert_eq!(
        pair("bob", "shapes")["explanations"][0]["object"],
        hidden.as_str()
    );
    assert_eq!(pair("bob", "spotlights")["explanations"][0]["light"], lit);
    assert!(pair("bob", "shapes")["flip_mean"].as_f64().unwrap() > 0.0);
    let bugs = json["bugs"].as_array().unwrap();
    let missing_bug = bugs.iter().find(|b| b["bug"] == "missing-object").unwrap();
    assert_eq!(missing_bug["students"], serde_json::json!(["bob"]));
    assert_eq!(missing_bug["scenes"], serde_json::json!(["shapes"]));
    assert!(
        bugs.iter()
            .any(|b| b["bug"] == "specular off" && b["students"] == serde_json::json!(["cat"]))
    );

    // The page: each student's cell names the top bug, the summary counts it.
    let page = std::fs::read_to_string(report.join("index.html")).unwrap();
    assert!(
        page.contains(&format!("missing-object, &#39;{hidden}&#39;")),
        "bob's shapes cell"
    );
    assert!(page.contains("missing-object: 1 of 4 students, in shapes"));
    assert!(page.contains("specular off: 1 of 4 students, in default"));
    // The feedback speaks to the student about their render and the reference.
    let feedback = raylab::class::feedback::to_student(&missing.summary);
    assert!(
        feedback.contains("missing in your render") && feedback.contains("the reference draws"),
        "{feedback}"
    );
    assert!(
        page.contains(&raylab::class::page::escape(&feedback)),
        "bob's feedback"
    );
    for student in 0..run.roster.students.len() {
        for paragraph in raylab::class::feedback::student_feedback(&run, student) {
            assert!(
                !paragraph.contains("other image") && !paragraph.contains("raylab's"),
                "{paragraph}"
            );
        }
    }
}

#[test]
fn bad_pairs_are_rows_and_unmatched_files_are_listed() {
    let class = generate("errors");
    let report = class.root.join("report");
    let run = run(&class, &report);
    write_report(&run, &report).unwrap();
    assert_eq!(outcome(&run, "bob", "default"), &Outcome::Missing);
    match outcome(&run, "cat", "shapes") {
        Outcome::Error(e) => assert!(e.contains("40x30") && e.contains("80x60"), "{e}"),
        other => panic!("{other:?}"),
    }
    match outcome(&run, "cat", "spotlights") {
        Outcome::Error(e) => assert!(e.contains("spotlights.png is not a readable"), "{e}"),
        other => panic!("{other:?}"),
    }
    // Matched by case and suffix.
    assert!(matches!(
        outcome(&run, "ann", "spotlights"),
        Outcome::Done { .. }
    ));
    assert!(matches!(
        outcome(&run, "dan", "default"),
        Outcome::Done { .. }
    ));
    assert_eq!(outcome(&run, "dan", "shapes"), &Outcome::Missing);
    let bob = run
        .roster
        .students
        .iter()
        .find(|s| s.name == "bob")
        .unwrap();
    assert_eq!(bob.unmatched, vec!["notes.txt"]);
    assert_eq!(run.roster.loose_files, vec!["README.txt"]);

    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(report.join("class.json")).unwrap()).unwrap();
    let pair = |student: &str, scene: &str| {
        json["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["student"] == student && p["scene"] == scene)
            .unwrap()
            .clone()
    };
    assert_eq!(pair("cat", "shapes")["status"], "error");
    assert!(
        pair("cat", "shapes")["error"]
            .as_str()
            .unwrap()
            .contains("40x30")
    );
    assert_eq!(pair("bob", "default")["status"], "missing");
    let students = json["students"].as_array().unwrap();
    let bob = students.iter().find(|s| s["name"] == "bob").unwrap();
    assert_eq!(bob["unmatched"], serde_json::json!(["notes.txt"]));
    assert_eq!(bob["missing"], serde_json::json!(["default"]));
    assert_eq!(json["loose_files"], serde_json::json!(["README.txt"]));
    let page = std::fs::read_to_string(report.join("index.html")).unwrap();
    assert!(page.contains("bob: notes.txt matched no scene."));
    assert!(
        page.contains("README.txt is in the submissions folder, not in a student&#39;s folder.")
    );
    assert!(page.contains("Scene default: no render of this scene was found."));
}

#[test]
fn a_rerun_reuses_the_cache_and_a_changed_picture_costs_one_pair() {
    let class = generate("cache");
    let report = class.root.join("report");
    let first = run(&class, &report);
    // 9 renders: 7 compared, 2 errors (wrong size, not an image).
    assert_eq!((first.computed, first.reused), (7, 0));
    let again = run(&class, &report);
    assert_eq!((again.computed, again.reused), (0, 7));
    // The cached result is the computed one (numbers through JSON, to the last bits).
    let (cached, computed) = (
        findings(&again, "bob", "shapes"),
        findings(&first, "bob", "shapes"),
    );
    assert_eq!(cached.len(), computed.len());
    for (a, b) in cached.iter().zip(computed) {
        assert_eq!(
            (&a.cause, &a.term, a.light, &a.object, &a.summary),
            (&b.cause, &b.term, b.light, &b.object, &b.summary)
        );
        assert!((a.factor - b.factor).abs() < 1e-12 && (a.share - b.share).abs() < 1e-12);
    }
    // A late submission replaces a picture: one pair is compared again.
    let fixed = render_with_bug(
        class.scene("spotlights"),
        &PlantedBug::TermOff(Term::Shadows),
    );
    std::fs::write(
        class.submissions_dir().join("bob/spotlights.png"),
        fixed.unwrap(),
    )
    .unwrap();
    let late = run(&class, &report);
    assert_eq!((late.computed, late.reused), (1, 6));
    assert_eq!(top(&late, "bob", "spotlights").term, "shadows");
    // The same picture as another pair's of the same scene is that pair's result.
    std::fs::copy(
        class.submissions_dir().join("ann/spotlights_render.png"),
        class.submissions_dir().join("bob/spotlights.png"),
    )
    .unwrap();
    let copied = run(&class, &report);
    assert_eq!((copied.computed, copied.reused), (0, 7));
    assert!(findings(&copied, "bob", "spotlights").is_empty());
}

/// Each scene is prepared once and shared by its students' pairs: every compared pair's
/// result is what `raylab diff` (one `compare_with_meshes` of that pair alone) finds.
#[test]
fn every_pair_of_a_shared_scene_is_what_a_separate_diff_finds() {
    let class = generate("shared");
    let run = run(&class, &class.root.join("report"));
    let mut compared = 0;
    for row in &run.rows {
        let Outcome::Done { result, .. } = &row.outcome else {
            continue;
        };
        let scene_path = &run.roster.scenes[row.scene].path;
        let picture = &run.roster.students[row.student].renders[&row.scene];
        let (scene, _) = load_any_scene(scene_path).unwrap();
        let image = OtherImage::from_bytes(&std::fs::read(picture).unwrap(), picture).unwrap();
        let alone = compare_with_meshes(
            &scene,
            &MeshStore::default(),
            &image,
            &CompareOptions::default(),
            &RenderProgress::default(),
        )
        .unwrap();
        let pair = picture.display();
        assert_eq!(result.psnr_db.to_bits(), alone.psnr_db.to_bits(), "{pair}");
        assert_eq!(
            result.unexplained_share.to_bits(),
            alone.unexplained_share.to_bits(),
            "{pair}"
        );
        let alone_findings: Vec<_> = alone
            .explanations
            .iter()
            .map(|e| {
                (
                    e.cause.name(),
                    e.factor.to_bits(),
                    e.share.to_bits(),
                    &e.summary,
                )
            })
            .collect();
        let class_findings: Vec<_> = result
            .findings
            .iter()
            .map(|f| {
                (
                    f.cause.as_str(),
                    f.factor.to_bits(),
                    f.share.to_bits(),
                    &f.summary,
                )
            })
            .collect();
        assert_eq!(class_findings, alone_findings, "{pair}");
        compared += 1;
    }
    // ann's three, bob's two, cat's and dan's `default`: three scenes shared by 2 or 3.
    assert_eq!(compared, 7);
}

#[test]
fn a_stopped_run_keeps_the_finished_pairs_and_a_rerun_finishes() {
    let class = generate("stop");
    let report = class.root.join("report");
    let stop = AtomicBool::new(false);
    // Stop once the first pair is done, as Ctrl+C does.
    let stopped = run_class(
        &class.scenes_dir(),
        &class.submissions_dir(),
        &report,
        &ClassOptions::default(),
        &stop,
        &|done, _| {
            if done >= 1 {
                stop.store(true, Ordering::Relaxed);
            }
        },
    )
    .unwrap();
    assert!(stopped.cancelled);
    let not_run = stopped
        .rows
        .iter()
        .filter(|r| r.outcome == Outcome::NotRun)
        .count();
    assert!(
        not_run > 0 && stopped.computed >= 1,
        "{not_run} not run, {} computed",
        stopped.computed
    );
    write_report(&stopped, &report).unwrap();
    let page = std::fs::read_to_string(report.join("index.html")).unwrap();
    assert!(page.contains("not run (stopped)"));
    let rest = run(&class, &report);
    assert!(!rest.cancelled);
    assert_eq!(rest.reused, stopped.computed);
    assert_eq!(rest.computed + rest.reused, 7);
}

#[test]
fn nothing_in_the_inputs_is_written_and_a_report_inside_them_is_refused() {
    let class = generate("inputs");
    let before = (
        snapshot(&class.scenes_dir()),
        snapshot(&class.submissions_dir()),
    );
    let report = class.root.join("report");
    let run = run(&class, &report);
    write_report(&run, &report).unwrap();
    let after = (
        snapshot(&class.scenes_dir()),
        snapshot(&class.submissions_dir()),
    );
    assert!(before == after, "the inputs changed");
    for inside in [
        class.submissions_dir().join("report"),
        class.scenes_dir().join("out"),
    ] {
        let error = run_class(
            &class.scenes_dir(),
            &class.submissions_dir(),
            &inside,
            &ClassOptions::default(),
            &AtomicBool::new(false),
            &|_, _| {},
        )
        .unwrap_err();
        assert!(error.contains("overlap"), "{error}");
        assert!(!inside.exists(), "{} was created", inside.display());
    }
}

/// Every value of `attribute="..."` in `html`, unescaped.
fn attribute_values(html: &str, attribute: &str) -> Vec<String> {
    let needle = format!(" {attribute}=\"");
    html.match_indices(&needle)
        .map(|(at, _)| {
            let rest = &html[at + needle.len()..];
            let value = &rest[..rest.find('"').unwrap()];
            value
                .replace("&quot;", "\"")
                .replace("&#39;", "'")
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&")
        })
        .collect()
}

#[test]
fn the_page_references_only_files_inside_the_report() {
    let class = generate("page");
    let report = class.root.join("report");
    let run = run(&class, &report);
    write_report(&run, &report).unwrap();
    let page = std::fs::read_to_string(report.join("index.html")).unwrap();
    let root = std::fs::canonicalize(&report).unwrap();
    let mut files = 0;
    for attribute in ["src", "href"] {
        for value in attribute_values(&page, attribute) {
            if let Some(anchor) = value.strip_prefix('#') {
                assert!(page.contains(&format!("id=\"{anchor}\"")), "anchor {value}");
                continue;
            }
            assert!(
                !value.contains(':') && !value.starts_with('/'),
                "not relative: {value}"
            );
            let file: PathBuf = std::fs::canonicalize(report.join(&value))
                .unwrap_or_else(|e| panic!("{value}: {e}"));
            assert!(
                file.starts_with(&root) && file.is_file(),
                "{value} outside the report"
            );
            files += 1;
        }
    }
    // Each compared pair: thumbnail, report image, FLIP map.
    assert_eq!(files, 7 * 3);
    for tag in ["<script", "<link", "@import", "url("] {
        assert!(!page.contains(tag), "the page loads something: {tag}");
    }
}
