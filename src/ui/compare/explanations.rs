//! The list of explanations under the compared pictures: one row per explanation,
//! largest share first. Clicking a row highlights its pixels and selects its object (or
//! its light) in the outliner and inspector; clicking it again clears the highlight.

use egui::{Color32, RichText};

use crate::compare::{Comparison, Explanation, PSNR_IDENTICAL_DB};
use crate::scene::Scene;
use crate::scene::tree::path_name;
use crate::ui::commands::{Command, Selection};
use crate::ui::state::light_label;

use super::session::CompareSession;

/// The sentence under an explanation's title: what it says, then where and how sure, in
/// words (the numbers of `raylab diff` are in the hover text).
fn explanation_detail(e: &Explanation, scene: &Scene) -> String {
    let pixels = e.pixels.len();
    let plural = if pixels == 1 { "" } else { "s" };
    format!(
        "{} It covers {pixels} pixel{plural} and {:.0}% of the difference; confidence {}.",
        summary_in_editor_names(e, scene),
        e.share * 100.0,
        e.sureness()
    )
}

/// The explanation's sentence with its light named as the outliner and the row's title
/// name it ("Point light 2"), not as `raylab diff` does ("light 1 (Point)": the index
/// `--bug` and the JSON take).
fn summary_in_editor_names(e: &Explanation, scene: &Scene) -> String {
    let Some((index, light)) = e.light.and_then(|l| Some((l, scene.lights.get(l)?))) else {
        return e.summary.clone();
    };
    let kind = light.kind_name();
    let editor = light_label(light, index);
    e.summary
        .replace(&format!("Light {index} ({kind})"), &editor)
        .replace(&format!("light {index} ({kind})"), &editor)
}

/// The row's text (also its accessible name), with the light named as the outliner
/// names it: "1. 50.0% diffuse · Point light 2 · 'red ball'".
#[must_use]
pub fn explanation_label(index: usize, e: &Explanation, scene: &Scene) -> String {
    let mut text = format!("{}. {:.1}% {}", index + 1, 100.0 * e.share, e.term.name());
    if let Some(light) = e.light {
        let name = scene
            .lights
            .get(light)
            .map_or_else(|| format!("light {light}"), |l| light_label(l, light));
        text.push_str(&format!(" · {name}"));
    }
    if let Some(object) = &e.object_name {
        text.push_str(&format!(" · '{object}'"));
    }
    text
}

/// What clicking an explanation selects in `scene`: its node (a part of an object's
/// tree, or the object), else its light; nothing when it names neither, or when the
/// scene no longer has them where it had them.
#[must_use]
pub fn explanation_selection(e: &Explanation, scene: &Scene) -> Option<Selection> {
    if e.node.len() > 1 {
        let same = Some(path_name(&scene.objects, &e.node)) == e.object_name;
        return same.then(|| Selection::Part(e.node.clone()));
    }
    if let Some(object) = e.object {
        let same = scene.objects.get(object).map(|o| &o.name) == e.object_name.as_ref();
        return same.then_some(Selection::Object(object));
    }
    e.light
        .filter(|&l| l < scene.lights.len())
        .map(Selection::Light)
}

/// The summary line and the rows; pushes a selection when a row is clicked. Returns the
/// height all of it needs (the rows scroll where they get less).
pub fn explanations_ui(
    ui: &mut egui::Ui,
    session: &mut CompareSession,
    scene: &Scene,
    commands: &mut Vec<Command>,
) -> f32 {
    let Some(compared) = session.compared() else {
        return 0.0;
    };
    let c = &compared.comparison;
    let top = ui.cursor().top();
    summary_ui(ui, c);
    let summary = ui.cursor().top() - top;
    let mut clicked = None;
    let rows = egui::ScrollArea::vertical()
        .auto_shrink([false, true])
        .show(ui, |ui| {
            for (i, e) in c.explanations.iter().enumerate() {
                let selected = session.highlighted() == Some(i);
                let label = explanation_label(i, e, scene);
                let response = ui
                    .selectable_label(selected, RichText::new(&label).strong())
                    .on_hover_text("Highlight its pixels and select its object or light");
                if response.clicked() {
                    clicked = Some(i);
                }
                ui.horizontal_wrapped(|ui| {
                    ui.add_space(14.0);
                    ui.weak(explanation_detail(e, scene)).on_hover_text(format!(
                        "raylab diff's numbers: factor {:.2}, cause {}, confidence {:.2}",
                        e.factor,
                        e.cause.name(),
                        e.confidence
                    ));
                });
                ui.add_space(4.0);
            }
        });
    if let Some(i) = clicked {
        if session.highlighted() == Some(i) {
            session.highlight(None);
        } else {
            session.highlight(Some(i));
            let selection = session
                .comparison()
                .and_then(|c| c.explanations.get(i))
                .and_then(|e| explanation_selection(e, scene));
            if let Some(selection) = selection {
                commands.push(Command::Select(selection));
            }
        }
    }
    summary + rows.content_size.y
}

/// PSNR, encoding and what is left unexplained.
fn summary_ui(ui: &mut egui::Ui, c: &Comparison) {
    let psnr = if c.psnr_db >= PSNR_IDENTICAL_DB {
        "identical".to_owned()
    } else {
        format!("PSNR {:.2} dB", c.psnr_db)
    };
    ui.horizontal_wrapped(|ui| {
        ui.label(RichText::new(psnr).strong());
        ui.weak(format!(
            "· other image read as {} · unexplained {:.1}% · raylab at {} spp",
            c.encoding.name(),
            100.0 * c.unexplained_share,
            c.samples_per_pixel
        ));
    });
    if c.explanations.is_empty() {
        ui.label(
            RichText::new(if c.psnr_db >= PSNR_IDENTICAL_DB {
                "The pictures are identical."
            } else {
                "No explanation: the pictures agree within 8-bit rounding."
            })
            .color(Color32::from_rgb(140, 200, 140)),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::{Cause, ExplainedTerm};
    use crate::scene::examples::EXAMPLE_SCENES;
    use crate::scene::parse_scene;
    use crate::trace::Term;

    #[test]
    fn an_explanation_of_a_part_of_a_tree_selects_that_part_while_the_scene_has_it() {
        let (_, ron) = EXAMPLE_SCENES
            .iter()
            .find(|(n, _)| *n == "csg.ron")
            .unwrap();
        let mut scene = parse_scene(ron).unwrap();
        let e = Explanation {
            term: ExplainedTerm::Term(Term::Diffuse),
            light: None,
            object: Some(2),
            object_name: Some("die/pip 1.1".to_owned()),
            node: vec![2, 1],
            factor: 2.0,
            share: 1.0,
            pixels: Vec::new(),
            cause: Cause::Factor,
            bbox: None,
            fits_as_well: Vec::new(),
            confidence: 1.0,
            summary: String::new(),
        };
        assert_eq!(
            explanation_selection(&e, &scene),
            Some(Selection::Part(vec![2, 1]))
        );
        let whole = Explanation {
            object_name: Some("die".to_owned()),
            node: vec![2],
            ..e.clone()
        };
        assert_eq!(
            explanation_selection(&whole, &scene),
            Some(Selection::Object(2))
        );
        // Renamed since: the explanation no longer points at it.
        crate::scene::tree::object_at_mut(&mut scene.objects, &[2, 1])
            .unwrap()
            .name = "pip one".to_owned();
        assert_eq!(explanation_selection(&e, &scene), None);
    }

    #[test]
    fn the_sentence_names_the_light_as_the_row_and_the_outliner_do() {
        let scene = crate::scene::examples::default_scene();
        let point = scene
            .lights
            .iter()
            .position(|l| matches!(l, crate::scene::Light::Point { .. }))
            .unwrap();
        let e = Explanation {
            term: ExplainedTerm::Light,
            light: Some(point),
            object: None,
            object_name: None,
            node: Vec::new(),
            factor: 0.0,
            share: 1.0,
            pixels: vec![0, 1],
            cause: Cause::Factor,
            bbox: None,
            fits_as_well: Vec::new(),
            confidence: 1.0,
            summary: String::new(),
        };
        let e = Explanation {
            summary: crate::compare::summary(&e, &scene),
            ..e
        };
        let editor = light_label(&scene.lights[point], point);
        assert!(
            e.summary.starts_with(&format!("Light {point} (Point)")),
            "{}",
            e.summary
        );
        let detail = explanation_detail(&e, &scene);
        assert!(
            detail.starts_with(&format!("{editor} is missing")),
            "{detail}"
        );
        assert!(explanation_label(0, &e, &scene).contains(&editor));
        assert!(!detail.contains(&format!("light {point} (")), "{detail}");
    }
}
