//! REPORT/index.html: one self-contained page (inline CSS, no script, nothing fetched
//! from the network) with the class table, the bugs across the class and a section of
//! feedback per student. Images are files in the report folder, linked by relative path.

use std::fmt::Write as _;
use std::path::Path;

use super::feedback::{bug_counts, bug_sentence, student_feedback};
use super::pair::{FLIP_MAP, REPORT_IMAGE, THUMBNAIL};
use super::run::{ClassRun, Outcome, PairRow};

/// The page's style: a plain table, cells tinted by how visible the difference is.
const STYLE: &str = "
body { font-family: sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 1.6em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #ccc; padding: 4px 6px; vertical-align: top; font-size: 0.85em; }
th { background: #f0f0f0; }
td.same { background: #eef8ee; } td.small { background: #fdf6e3; }
td.large { background: #fbe9e7; } td.none { background: #f4f4f4; color: #777; }
td img { display: block; margin-bottom: 3px; }
.bug { font-weight: bold; } .num { color: #555; }
.error { color: #a00; } p.feedback { max-width: 60em; }
";

/// FLIP means at or below this read as no visible difference.
const FLIP_SAME: f64 = 0.01;
/// FLIP means above this read as a large difference.
const FLIP_LARGE: f64 = 0.1;

/// Escapes text for HTML content and attribute values.
#[must_use]
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// A relative path as a URL path (forward slashes, each part escaped for HTML).
fn href(folder: &Path, file: &str) -> String {
    let parts: Vec<String> = folder
        .components()
        .map(|c| escape(&c.as_os_str().to_string_lossy()))
        .collect();
    format!("{}/{}", parts.join("/"), escape(file))
}

fn cell(row: &PairRow) -> String {
    match &row.outcome {
        Outcome::Missing => "<td class=\"none\">no render</td>".to_owned(),
        Outcome::NotRun => "<td class=\"none\">not run (stopped)</td>".to_owned(),
        Outcome::Error(e) => format!(
            "<td class=\"large\"><span class=\"error\">error</span>: {}</td>",
            escape(e)
        ),
        Outcome::Done { result, folder, .. } => {
            let class = if result.flip_mean <= FLIP_SAME {
                "same"
            } else if result.flip_mean > FLIP_LARGE {
                "large"
            } else {
                "small"
            };
            let bug = result
                .findings
                .first()
                .map_or_else(|| "no bug found".to_owned(), |f| f.bug_where());
            format!(
                "<td class=\"{class}\"><a href=\"{report}\"><img src=\"{thumb}\" alt=\"{alt}\" width=\"120\"></a>\
                 <span class=\"bug\">{bug}</span><br><span class=\"num\">PSNR {psnr:.1} dB<br>FLIP {mean:.3} (p99 {p99:.3})</span><br>\
                 <a href=\"{flip}\">FLIP map</a></td>",
                report = href(folder, REPORT_IMAGE),
                thumb = href(folder, THUMBNAIL),
                flip = href(folder, FLIP_MAP),
                alt = escape(row.picture.as_deref().unwrap_or("")),
                bug = escape(&bug),
                psnr = result.psnr_db,
                mean = result.flip_mean,
                p99 = result.flip_p99,
            )
        }
    }
}

fn class_table(run: &ClassRun, html: &mut String) {
    html.push_str("<table>\n<tr><th>student</th>");
    for scene in &run.roster.scenes {
        let _ = write!(html, "<th>{}</th>", escape(&scene.name));
    }
    html.push_str("</tr>\n");
    for (s, student) in run.roster.students.iter().enumerate() {
        let _ = write!(
            html,
            "<tr><th><a href=\"#student-{s}\">{}</a></th>",
            escape(&student.name)
        );
        for row in run.rows.iter().filter(|r| r.student == s) {
            html.push_str(&cell(row));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</table>\n");
}

fn problems(run: &ClassRun, html: &mut String) {
    let mut items = Vec::new();
    for (scene, error) in run.roster.scenes.iter().zip(&run.scene_errors) {
        if let Some(e) = error {
            items.push(format!("Scene {} does not load: {}", scene.name, e));
        }
    }
    for file in &run.roster.loose_files {
        items.push(format!(
            "{file} is in the submissions folder, not in a student's folder."
        ));
    }
    for student in &run.roster.students {
        if !student.unmatched.is_empty() {
            items.push(format!(
                "{}: {} matched no scene.",
                student.name,
                student.unmatched.join(", ")
            ));
        }
    }
    items.extend(run.warnings.iter().map(|w| format!("warning: {w}")));
    if items.is_empty() {
        return;
    }
    html.push_str("<h2>Files and scenes to check</h2>\n<ul>\n");
    for item in items {
        let _ = writeln!(html, "<li>{}</li>", escape(&item));
    }
    html.push_str("</ul>\n");
}

/// The whole page.
#[must_use]
pub fn class_page(run: &ClassRun) -> String {
    let mut html = String::new();
    html.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    html.push_str("<title>raylab class report</title>\n<style>");
    html.push_str(STYLE);
    html.push_str("</style>\n</head>\n<body>\n<h1>raylab class report</h1>\n");
    let done = run
        .rows
        .iter()
        .filter(|r| matches!(r.outcome, Outcome::Done { .. }))
        .count();
    let _ = writeln!(
        html,
        "<p>{} students, {} scenes, {done} renders compared with raylab's (PSNR in dB, higher is closer; \
         LDR-FLIP mean and 99th percentile, 0 is no visible difference). raylab {}.{}</p>",
        run.roster.students.len(),
        run.roster.scenes.len(),
        env!("CARGO_PKG_VERSION"),
        if run.cancelled {
            " The run was stopped: pairs marked 'not run' are not compared yet; run again to finish."
        } else {
            ""
        }
    );
    html.push_str("<h2>Class table</h2>\n");
    class_table(run, &mut html);
    html.push_str("<h2>Bugs across the class</h2>\n");
    let counts = bug_counts(run);
    if counts.is_empty() {
        html.push_str("<p>No bug found in any render.</p>\n");
    } else {
        html.push_str("<ul>\n");
        for count in &counts {
            let _ = writeln!(html, "<li>{}</li>", escape(&bug_sentence(run, count)));
        }
        html.push_str("</ul>\n");
    }
    problems(run, &mut html);
    html.push_str("<h2>Feedback per student</h2>\n");
    for (s, student) in run.roster.students.iter().enumerate() {
        let _ = writeln!(
            html,
            "<h3 id=\"student-{s}\">{}</h3>",
            escape(&student.name)
        );
        for paragraph in student_feedback(run, s) {
            let _ = writeln!(html, "<p class=\"feedback\">{}</p>", escape(&paragraph));
        }
    }
    html.push_str("</body>\n</html>\n");
    html
}
