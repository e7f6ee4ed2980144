//! What the class report says in words: the bugs across the class ("diffuse off: 3 of
//! 40 students, in default, shapes") and, per student, sentences a teacher can paste as
//! feedback.

use std::collections::BTreeSet;

use super::run::{ClassRun, Outcome};

/// An explanation counts as a student's bug in the class summary when it explains at
/// least this share of the pair's difference; smaller ones stay in the pair's report.
pub const MIN_BUG_SHARE: f64 = 0.05;

/// One bug across the class.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BugCount {
    /// The bug's short name ([`super::pair::Finding::bug`]).
    pub bug: String,
    /// Indices of the students with it in at least one scene.
    pub students: BTreeSet<usize>,
    /// Indices of the scenes it shows in.
    pub scenes: BTreeSet<usize>,
}

/// Every bug found in the class, the most widespread first (then by name).
#[must_use]
pub fn bug_counts(run: &ClassRun) -> Vec<BugCount> {
    let mut counts: Vec<BugCount> = Vec::new();
    for row in &run.rows {
        let Outcome::Done { result, .. } = &row.outcome else {
            continue;
        };
        for finding in result.findings.iter().filter(|f| f.share >= MIN_BUG_SHARE) {
            let bug = finding.bug();
            let index = counts.iter().position(|c| c.bug == bug).unwrap_or_else(|| {
                counts.push(BugCount {
                    bug,
                    students: BTreeSet::new(),
                    scenes: BTreeSet::new(),
                });
                counts.len() - 1
            });
            counts[index].students.insert(row.student);
            counts[index].scenes.insert(row.scene);
        }
    }
    counts.sort_by(|a, b| {
        b.students
            .len()
            .cmp(&a.students.len())
            .then_with(|| a.bug.cmp(&b.bug))
    });
    counts
}

/// The sentence of the class summary for one bug.
#[must_use]
pub fn bug_sentence(run: &ClassRun, count: &BugCount) -> String {
    let scenes: Vec<&str> = count
        .scenes
        .iter()
        .map(|&s| run.roster.scenes[s].name.as_str())
        .collect();
    format!(
        "{}: {} of {} students, in {}",
        count.bug,
        count.students.len(),
        run.roster.students.len(),
        scenes.join(", ")
    )
}

/// The comparison's words for the student's picture and raylab's, and the student's:
/// `raylab diff` compares any renderer's picture, so its sentences say "the other
/// image"; a student reads about "your render" against "the reference". Longest first,
/// so that "the other image's" is not read as "the other image" + "'s".
const TO_STUDENT: [(&str, &str); 9] = [
    ("The other image's", "Your render's"),
    ("the other image's", "your render's"),
    ("The other image", "Your render"),
    ("the other image", "your render"),
    ("The picture looks like", "Your render looks like"),
    ("does its tracer", "does your tracer"),
    ("Was it rendered", "Was your render made"),
    ("raylab's", "the reference's"),
    ("raylab ", "the reference "),
];

/// An explanation's sentence as feedback to the student whose render it explains.
#[must_use]
pub fn to_student(summary: &str) -> String {
    TO_STUDENT
        .iter()
        .fold(summary.to_owned(), |text, (from, to)| {
            text.replace(from, to)
        })
}

/// Feedback for student `student`, one paragraph per scene and one for files that
/// matched nothing, in sentences.
#[must_use]
pub fn student_feedback(run: &ClassRun, student: usize) -> Vec<String> {
    let mut paragraphs = Vec::new();
    for row in run.rows.iter().filter(|r| r.student == student) {
        let scene = &run.roster.scenes[row.scene].name;
        let picture = row.picture.as_deref().unwrap_or("");
        let text = match &row.outcome {
            Outcome::Missing => format!("Scene {scene}: no render of this scene was found."),
            Outcome::NotRun => format!("Scene {scene}: not compared (the run was stopped)."),
            Outcome::Error(e) => format!(
                "Scene {scene} ({picture}): could not be compared: {}.",
                to_student(e)
            ),
            Outcome::Done { result, .. } => {
                let mut text = format!(
                    "Scene {scene} ({picture}): PSNR {:.1} dB, FLIP {:.3}.",
                    result.psnr_db, result.flip_mean
                );
                let shown: Vec<_> = result
                    .findings
                    .iter()
                    .filter(|f| f.share >= MIN_BUG_SHARE)
                    .collect();
                if shown.is_empty() {
                    text.push_str(" Your render matches the reference.");
                }
                for f in shown {
                    text.push(' ');
                    text.push_str(&to_student(&f.summary));
                }
                text
            }
        };
        paragraphs.push(text);
    }
    let unmatched = &run.roster.students[student].unmatched;
    if !unmatched.is_empty() {
        paragraphs.push(format!(
            "These files matched no scene: {}.",
            unmatched.join(", ")
        ));
    }
    paragraphs
}
