//! The sentence of each explanation: what its numbers say, for a reader.

use super::explanation::{Cause, ExplainedTerm, Explanation};
use crate::compare::catalogue::{ClampBug, Part};
use crate::compare::extras::ShapeGuess;
use crate::compare::fit::Encoding;
use crate::scene::tree::object_at;
use crate::scene::{ClampConvention, CsgOp, Light, MirrorConvention, Quantise, Scene, Shape};
use crate::trace::Term;

/// The lights a tracer's light loop visits: every light but the ambient ones.
#[must_use]
pub fn looped_lights(scene: &Scene) -> usize {
    scene
        .lights
        .iter()
        .filter(|l| !matches!(l, Light::Ambient { .. }))
        .count()
}

/// For a factor that a loop's bug makes, the sentence naming it: a whole light missing
/// that is the last of the list (a loop that stops one short), or the ambient term
/// scaled by the number of lights (added inside the light loop).
fn loop_hint(e: &Explanation, scene: &Scene) -> String {
    let whole_light = e.object.is_none()
        && matches!(
            e.term,
            ExplainedTerm::Light | ExplainedTerm::Term(Term::Diffuse | Term::Specular)
        );
    if let Some(light) = e.light
        && whole_light
        && e.factor < 0.05
        && light + 1 == scene.lights.len()
        && scene.lights.len() > 1
    {
        return " It is the last light of the scene: a loop over the lights that stops one short skips it.".to_owned();
    }
    let lights = looped_lights(scene);
    if e.term == ExplainedTerm::Term(Term::Ambient)
        && e.light.is_none()
        && lights >= 2
        && (e.factor - lights as f64).abs() < 0.15 * lights as f64
    {
        return format!(
            " That is the number of lights ({lights}): the ambient is added once per light, inside the light loop."
        );
    }
    String::new()
}

fn light_name(scene: &Scene, light: usize) -> String {
    let kind = scene.lights.get(light).map_or("?", Light::kind_name);
    format!("light {light} ({kind})")
}

fn on_object(name: Option<&str>) -> String {
    name.map_or_else(String::new, |n| format!(" on '{n}'"))
}

/// The sentence for an explanation whose other fields are set.
#[must_use]
pub fn summary(e: &Explanation, scene: &Scene) -> String {
    let object = e.object_name.as_deref();
    let light = e.light.map(|l| light_name(scene, l));
    let f = e.factor;
    let weight = 1.0 - f;
    let term = e.term.name();
    match e.cause {
        Cause::Factor if e.term == ExplainedTerm::Term(Term::Shadows) => {
            let whose = light.map_or("Shadows".to_owned(), |l| format!("Shadows of {l}"));
            if f < 0.1 {
                format!(
                    "{whose}{} are missing: shadowed places are lit in the other image (shadow factor {f:.2}).",
                    on_object(object)
                )
            } else {
                format!(
                    "{whose}{} take away {f:.2} of the light raylab's take away.",
                    on_object(object)
                )
            }
        }
        Cause::Factor if e.term == ExplainedTerm::Light => {
            let whose = capitalised(light.as_deref().unwrap_or("every light"));
            format!(
                "{whose} is missing in the other image{}: neither its diffuse nor its specular term is there (factor {f:.2}).",
                on_object(object)
            ) + &loop_hint(e, scene)
        }
        Cause::Factor => {
            let subject = match (&light, object) {
                (Some(l), Some(o)) => format!("The {term} of {l} on '{o}'"),
                (Some(l), None) => format!("The {term} of {l}"),
                (None, Some(o)) => format!("The {term} of '{o}'"),
                (None, None) => format!("The {term} term"),
            };
            let sentence = if f < 0.05 {
                format!("{subject} is missing in the other image (factor {f:.2}).")
            } else {
                format!("{subject} is {f:.2} times raylab's in the other image.")
            };
            sentence + &loop_hint(e, scene)
        }
        Cause::Normal(bug) => match object {
            Some(o) => format!(
                "'{o}' is shaded as if {} (the bug's picture fits with weight {weight:.2}).",
                bug.describe()
            ),
            None => format!(
                "Every object is shaded as if {} (weight {weight:.2}).",
                bug.describe()
            ),
        },
        Cause::Highlight(bug) => format!(
            "Highlights{} look as if {} (weight {weight:.2}).",
            on_object(object),
            bug.describe()
        ),
        Cause::ShadowTest(bug) => match object {
            Some(o) => format!(
                "'{o}' is lit as if {} (the bug's picture fits with weight {weight:.2}).",
                bug.describe()
            ),
            None => format!(
                "Shadows look as if {} (weight {weight:.2}).",
                bug.describe()
            ),
        },
        Cause::Clamp(ClampBug::TruncateEachRay) => format!(
            "Reflections{} are darker by up to a level per bounce: {} (weight {weight:.2}).",
            on_object(object).replace(" on ", " in "),
            ClampBug::TruncateEachRay.describe()
        ),
        Cause::Clamp(bug) => format!(
            "Reflections{} are darker where they exceed 1: {} (weight {weight:.2}).",
            on_object(object).replace(" on ", " in "),
            bug.describe()
        ),
        Cause::Spawn(bug) => match object {
            Some(o) => format!(
                "'{o}' reflects as if {} (the bug's picture fits with weight {weight:.2}).",
                bug.describe()
            ),
            None => format!("Mirrors reflect as if {} (weight {weight:.2}).", bug.describe()),
        },
        Cause::Spot(bug) => format!(
            "{} lights the other image as if {} (weight {weight:.2}; explains {:.1}% of the difference).",
            capitalised(light.as_deref().unwrap_or("every spot light")),
            bug.describe(),
            100.0 * e.share
        ),
        Cause::Missing(part) => {
            let o = object.unwrap_or("an object");
            match part {
                Some(Part::Back) => format!(
                    "'{o}' is invisible from behind in the other image: a one-sided plane (weight {weight:.2})."
                ),
                Some(Part::Whole) | None if is_cut(scene, &e.node) => format!(
                    "'{o}' is not cut in the other image{}: the solid shows there whole, as if the operand were missing (weight {weight:.2}).",
                    e.bbox.map_or_else(String::new, |b| format!(
                        " (raylab cuts it at x {}..{}, y {}..{})",
                        b.x0, b.x1, b.y0, b.y1
                    ))
                ),
                Some(Part::Whole) | None => format!(
                    "'{o}' is missing in the other image{}: what lies behind it shows instead, and its shadows are gone (weight {weight:.2}).{}",
                    e.bbox.map_or_else(String::new, |b| format!(
                        " (raylab draws it at x {}..{}, y {}..{})",
                        b.x0, b.x1, b.y0, b.y1
                    )),
                    if e.node.len() == 1 && e.node[0] + 1 == scene.objects.len() && scene.objects.len() > 1 {
                        " It is the last object of the scene: a loop over the objects that stops one short skips it."
                    } else {
                        ""
                    }
                ),
                Some(p) => format!(
                    "{} of '{o}' {} missing in the other image: what lies behind shows instead (weight {weight:.2}).",
                    capitalised(p.describe()),
                    if p == Part::Caps { "are" } else { "is" }
                ),
            }
        }
        Cause::ExtraObject(shape) => extra_object_summary(e, shape, &[], scene),
        Cause::Conventions {
            depth: Some(depth), ..
        } => format!(
            "The other image's rays bounce past the scene's ray depth ({}): its mirrors facing each other go on to depth {depth} or more, as a tracer without a depth limit does.",
            scene.render.max_depth
        ),
        Cause::Conventions { other, .. } => {
            let mirror = match other.mirror {
                MirrorConvention::Blend => "blends mirrors as (1 - km) local + km reflected",
                MirrorConvention::Add => "adds mirrors as local + km reflected",
            };
            let clamp = match other.clamp {
                ClampConvention::EachRay => "clamps each ray's colour to [0, 1]",
                ClampConvention::Pixel => "clamps only the pixel",
            };
            format!(
                "The other image follows other conventions than the scene: it {mirror} and {clamp} (render.conventions: (mirror: {:?}, clamp: {:?})).",
                other.mirror, other.clamp
            )
        }
        Cause::Encoding(encoding) => {
            let scene_writes = match scene.render.conventions.quantise {
                Quantise::Round => "round(255 c)",
                Quantise::Truncate => "floor(255 c), as the scene's conventions say",
            };
            match encoding {
                Encoding::LinearTruncate => format!(
                    "The other image truncates to 8 bits, floor(255 c), where raylab writes {scene_writes}."
                ),
                Encoding::LinearRound => format!(
                    "The other image rounds to 8 bits, round(255 c), where raylab writes {scene_writes}."
                ),
                other => format!(
                    "The other image is written as {}, raylab's as linear {scene_writes}.",
                    other.name()
                ),
            }
        }
        Cause::Silhouette => format!(
            "The outline of {} differs over {} pixels: the shape is elsewhere, another size, or hit where it should not be.",
            object.map_or("the objects".to_owned(), |o| format!("'{o}'")),
            e.pixels.len()
        ),
        Cause::Shading => format!(
            "Shading varies across {} in a way no factor or known bug explains; it follows the {term} term, as a wrong normal or reflected vector would.",
            object.map_or("the picture".to_owned(), |o| format!("'{o}'"))
        ),
        Cause::Sampling => "The pictures differ along edges as another renderer's anti-aliasing makes them (more samples, or other places in the pixel): not a bug.".to_owned(),
        Cause::DifferentScene { objects } => format!(
            "The picture looks like another version of this scene: the outlines of {objects} objects differ and no factor or known bug explains most of the difference. Was it rendered from an older scene file (the camera or objects moved)? The verdicts below are weak until the two agree."
        ),
    }
}

/// Whether the node at `path` is a cut: a Difference's operand after the first.
fn is_cut(scene: &Scene, path: &[usize]) -> bool {
    let Some((&index, parent)) = path.split_last().filter(|(_, p)| !p.is_empty()) else {
        return false;
    };
    index > 0
        && object_at(&scene.objects, parent).is_some_and(|p| {
            matches!(
                p.shape,
                Shape::Csg {
                    op: CsgOp::Difference,
                    ..
                }
            )
        })
}

/// The sentence of an extra object: where, over what raylab sees there (`behind`:
/// scene objects, `None` the background), and what it looks like.
#[must_use]
pub fn extra_object_summary(
    e: &Explanation,
    shape: ShapeGuess,
    behind: &[Option<usize>],
    scene: &Scene,
) -> String {
    let at = e.bbox.map_or_else(String::new, |b| {
        format!(" at x {}..{}, y {}..{}", b.x0, b.x1, b.y0, b.y1)
    });
    let looks = match shape {
        ShapeGuess::Sphere => "its outline is an ellipse: a sphere?",
        ShapeGuess::Cube => "its outline is a quadrilateral or hexagon: a cube?",
        ShapeGuess::Unknown => "its shape is not a simple one",
    };
    let over = if behind.is_empty() {
        String::new()
    } else {
        let names: Vec<String> = behind
            .iter()
            .map(|o| match o.and_then(|o| scene.objects.get(o)) {
                Some(object) => format!("'{}'", object.name),
                None => "the background".to_owned(),
            })
            .collect();
        format!(" over {}", listed(&names))
    };
    let like = e.object_name.as_ref().map_or_else(String::new, |o| {
        format!(
            " Its colours are those of '{o}' nearby: is '{o}' larger or placed elsewhere there?"
        )
    });
    format!(
        "The other image draws an object raylab does not{at}{over}; {looks} Was it rendered from a scene with one more object, or does its tracer hit something where there is nothing?{like}"
    )
}

/// "a", "a and b", "a, b and c".
fn listed(names: &[String]) -> String {
    match names {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A missing part's sentence, for a scene of one plane, 'wall'.
    fn missing_part_sentence(part: Part) -> String {
        let mut scene = Scene::empty();
        scene.objects.push(crate::scene::Object {
            name: "wall".to_owned(),
            shape: Shape::Plane,
            transform: crate::scene::Transform::default(),
            material: String::new(),
        });
        let e = Explanation {
            term: ExplainedTerm::Geometry,
            light: None,
            object: Some(0),
            object_name: Some("wall".to_owned()),
            node: vec![0],
            factor: 0.0,
            share: 1.0,
            pixels: Vec::new(),
            bbox: None,
            fits_as_well: Vec::new(),
            cause: Cause::Missing(Some(part)),
            confidence: 1.0,
            summary: String::new(),
        };
        summary(&e, &scene)
    }

    #[test]
    fn a_missing_part_takes_its_verb_in_number() {
        let front = missing_part_sentence(Part::Front);
        assert!(
            front.starts_with("The front (normal side) of 'wall' is missing"),
            "{front}"
        );
        let caps = missing_part_sentence(Part::Caps);
        assert!(caps.starts_with("The caps of 'wall' are missing"), "{caps}");
    }
}
