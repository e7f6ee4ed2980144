//! REPORT/class.csv and REPORT/class.json: one row per student and scene, with the
//! pair's numbers and each explanation's cause, term, light, object, factor and share.

use serde::Serialize;

use super::feedback::{BugCount, bug_counts};
use super::pair::Finding;
use super::run::{ClassRun, Outcome, PairRow};

/// A row's status word: `done`, `missing`, `error` or `not-run`.
#[must_use]
pub fn status(outcome: &Outcome) -> &'static str {
    match outcome {
        Outcome::Done { .. } => "done",
        Outcome::Missing => "missing",
        Outcome::Error(_) => "error",
        Outcome::NotRun => "not-run",
    }
}

/// Rounds for reports: 4 decimals.
fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

#[derive(Serialize)]
struct PairJson<'a> {
    student: &'a str,
    scene: &'a str,
    picture: Option<&'a str>,
    status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
    psnr_db: Option<f64>,
    flip_mean: Option<f64>,
    flip_p99: Option<f64>,
    unexplained_share: Option<f64>,
    /// The pair's folder of images, relative to the report.
    #[serde(skip_serializing_if = "Option::is_none")]
    images: Option<String>,
    explanations: &'a [Finding],
}

#[derive(Serialize)]
struct StudentJson<'a> {
    name: &'a str,
    unmatched: &'a [String],
    missing: Vec<&'a str>,
}

#[derive(Serialize)]
struct SceneJson<'a> {
    name: &'a str,
    file: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

#[derive(Serialize)]
struct BugJson<'a> {
    bug: String,
    students: Vec<&'a str>,
    scenes: Vec<&'a str>,
}

#[derive(Serialize)]
struct ClassJson<'a> {
    raylab: &'static str,
    scenes: Vec<SceneJson<'a>>,
    students: Vec<StudentJson<'a>>,
    loose_files: &'a [String],
    pairs: Vec<PairJson<'a>>,
    bugs: Vec<BugJson<'a>>,
    computed: usize,
    reused: usize,
    cancelled: bool,
}

fn pair_json<'a>(run: &'a ClassRun, row: &'a PairRow) -> PairJson<'a> {
    let (result, folder) = match &row.outcome {
        Outcome::Done { result, folder, .. } => (Some(result), Some(folder)),
        _ => (None, None),
    };
    PairJson {
        student: &run.roster.students[row.student].name,
        scene: &run.roster.scenes[row.scene].name,
        picture: row.picture.as_deref(),
        status: status(&row.outcome),
        error: match &row.outcome {
            Outcome::Error(e) => Some(e),
            _ => None,
        },
        psnr_db: result.map(|r| round4(r.psnr_db)),
        flip_mean: result.map(|r| round4(r.flip_mean)),
        flip_p99: result.map(|r| round4(r.flip_p99)),
        unexplained_share: result.map(|r| round4(r.unexplained_share)),
        images: folder.map(|f| f.to_string_lossy().replace('\\', "/")),
        explanations: result.map_or(&[], |r| &r.findings),
    }
}

fn bug_json<'a>(run: &'a ClassRun, count: &BugCount) -> BugJson<'a> {
    BugJson {
        bug: count.bug.clone(),
        students: count
            .students
            .iter()
            .map(|&s| run.roster.students[s].name.as_str())
            .collect(),
        scenes: count
            .scenes
            .iter()
            .map(|&s| run.roster.scenes[s].name.as_str())
            .collect(),
    }
}

/// class.json: the scenes, the students (unmatched files, missing renders), every pair
/// and the bugs across the class.
#[must_use]
pub fn class_json(run: &ClassRun) -> String {
    let counts = bug_counts(run);
    let json = ClassJson {
        raylab: env!("CARGO_PKG_VERSION"),
        scenes: run
            .roster
            .scenes
            .iter()
            .zip(&run.scene_errors)
            .map(|(s, e)| SceneJson {
                name: &s.name,
                file: s
                    .path
                    .file_name()
                    .unwrap_or_default()
                    .to_string_lossy()
                    .into_owned(),
                error: e.as_deref(),
            })
            .collect(),
        students: run
            .roster
            .students
            .iter()
            .map(|s| StudentJson {
                name: &s.name,
                unmatched: &s.unmatched,
                missing: s
                    .missing(run.roster.scenes.len())
                    .into_iter()
                    .map(|i| run.roster.scenes[i].name.as_str())
                    .collect(),
            })
            .collect(),
        loose_files: &run.roster.loose_files,
        pairs: run.rows.iter().map(|row| pair_json(run, row)).collect(),
        bugs: counts.iter().map(|c| bug_json(run, c)).collect(),
        computed: run.computed,
        reused: run.reused,
        cancelled: run.cancelled,
    };
    serde_json::to_string_pretty(&json).expect("plain data serialises")
}

/// Fields of each explanation in the CSV, after `explanation_N_`.
const FINDING_FIELDS: [&str; 6] = ["cause", "term", "light", "object", "factor", "share"];

/// class.csv: one row per pair; each explanation (as many column groups as the pair
/// with the most has) as `explanation_N_cause`, `_term`, `_light`, `_object`,
/// `_factor`, `_share`.
///
/// # Errors
/// The CSV writer's message.
pub fn class_csv(run: &ClassRun) -> Result<String, String> {
    let most = run
        .rows
        .iter()
        .map(|r| match &r.outcome {
            Outcome::Done { result, .. } => result.findings.len(),
            _ => 0,
        })
        .max()
        .unwrap_or(0);
    let mut writer = csv::Writer::from_writer(Vec::new());
    let mut header: Vec<String> = [
        "student",
        "scene",
        "picture",
        "status",
        "error",
        "psnr_db",
        "flip_mean",
        "flip_p99",
        "unexplained_share",
    ]
    .map(str::to_owned)
    .to_vec();
    for n in 1..=most {
        header.extend(FINDING_FIELDS.map(|f| format!("explanation_{n}_{f}")));
    }
    let error = |e: csv::Error| e.to_string();
    writer.write_record(&header).map_err(error)?;
    for row in &run.rows {
        let json = pair_json(run, row);
        let number = |x: Option<f64>| x.map_or_else(String::new, |x| x.to_string());
        let mut record = vec![
            json.student.to_owned(),
            json.scene.to_owned(),
            json.picture.unwrap_or("").to_owned(),
            json.status.to_owned(),
            json.error.unwrap_or("").to_owned(),
            number(json.psnr_db),
            number(json.flip_mean),
            number(json.flip_p99),
            number(json.unexplained_share),
        ];
        for n in 0..most {
            match json.explanations.get(n) {
                Some(f) => record.extend([
                    f.cause.clone(),
                    f.term.clone(),
                    f.light.map_or_else(String::new, |l| l.to_string()),
                    f.object.clone().unwrap_or_default(),
                    round4(f.factor).to_string(),
                    round4(f.share).to_string(),
                ]),
                None => record.extend(std::iter::repeat_n(String::new(), FINDING_FIELDS.len())),
            }
        }
        writer.write_record(&record).map_err(error)?;
    }
    let bytes = writer.into_inner().map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|e| e.to_string())
}
