//! Drawing the ray paths: the world-space segments of each traced pixel
//! ([`crate::gizmo::ray_paths`]) clipped in front of the shown camera and projected
//! through the same [`ViewMapping`] as the gizmos, painted by kind, with the segment
//! under the pointer highlighted and its numbers in a card beside it.

use egui::{Align2, Color32, FontId, Id, Pos2, Shape, Stroke, Vec2};
use glam::DVec3;

use crate::gizmo::handles::distance_to_segment;
use crate::gizmo::ray_paths::{
    PathSegment, SegmentEnd, SegmentKind, SegmentLengths, clip_in_front, path_segments,
};
use crate::scene::Scene;
use crate::trace::{LightOutcome, LightSkip, RayKind, traced_rays};
use crate::ui::gizmo::hit::dvec;
use crate::ui::gizmo::projection::ViewMapping;
use crate::ui::state::RayPathSettings;
use crate::ui::state::light_label;
use crate::ui::viewport::pixel_inspector::{PixelInspection, isolation_lines};

/// How close (points) the pointer must be to a segment to show its numbers.
const HOVER_PX: f64 = 6.0;
/// A normal's drawn length, in screen points at its hit.
const NORMAL_PX: f64 = 30.0;

/// One segment on screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenSegment {
    /// The pixel it belongs to.
    pub pixel: (u32, u32),
    /// Whether that is the inspected pixel (the others are drawn fainter).
    pub inspected: bool,
    /// The world-space segment.
    pub segment: PathSegment,
    /// Its start on screen.
    pub from: Pos2,
    /// Its end on screen.
    pub to: Pos2,
}

/// The segment under the pointer.
#[derive(Clone, Debug, PartialEq)]
pub struct HoveredRay {
    /// The segment.
    pub segment: ScreenSegment,
    /// Its numbers, one line each.
    pub lines: Vec<String>,
}

/// The segments of every inspection that the settings show, projected through `view`.
#[must_use]
pub fn screen_segments(
    view: &ViewMapping,
    scene: &Scene,
    inspections: &[PixelInspection],
    settings: &RayPathSettings,
    inspected: Option<(u32, u32)>,
) -> Vec<ScreenSegment> {
    let eye = view.eye();
    let forward = (view.shown.look_at - eye).normalize_or_zero();
    let reach = (view.shown.look_at - eye).length().max(1e-9);
    let run_off = reach.max((scene.camera.look_at - scene.camera.position).length()) * 4.0;
    let mut out = Vec::new();
    for inspection in inspections {
        let Ok(pixel) = &inspection.result else {
            continue;
        };
        let normal_at = pixel.report.bounces[0].hit.map_or(eye + forward, |h| h.p);
        let lengths = SegmentLengths {
            run_off,
            normal: view.world_per_point(normal_at) * NORMAL_PX,
        };
        for segment in path_segments(&pixel.report, &scene.lights, lengths) {
            if !shown(settings, segment.kind) {
                continue;
            }
            let Some((a, b)) = clip_in_front(segment.from, segment.to, eye, forward, reach * 1e-4)
            else {
                continue;
            };
            if let (Some(from), Some(to)) = (view.project(a), view.project(b)) {
                out.push(ScreenSegment {
                    pixel: inspection.pixel,
                    inspected: Some(inspection.pixel) == inspected,
                    segment,
                    from,
                    to,
                });
            }
        }
    }
    out
}

fn shown(settings: &RayPathSettings, kind: SegmentKind) -> bool {
    match kind {
        SegmentKind::Ray(RayKind::Primary) => settings.primary,
        SegmentKind::Ray(RayKind::Shadow) | SegmentKind::Unreached(_) => settings.shadow,
        SegmentKind::Ray(RayKind::Reflection) => settings.reflection,
        SegmentKind::Ray(RayKind::Refraction | RayKind::InternalReflection) => {
            settings.transmission
        }
        SegmentKind::Normal => settings.normals,
    }
}

/// Paints the ray paths and, when the pointer is near a segment, its numbers; returns
/// the hovered segment.
pub fn ray_paths_ui(
    ui: &egui::Ui,
    painter: &egui::Painter,
    segments: &[ScreenSegment],
    scene: &Scene,
    inspections: &[PixelInspection],
    pointer: Option<Pos2>,
) -> Option<HoveredRay> {
    let hovered = pointer.and_then(|p| {
        segments
            .iter()
            .map(|s| (s, distance_to_segment(dvec(p), dvec(s.from), dvec(s.to))))
            .filter(|(_, d)| *d <= HOVER_PX)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(s, _)| *s)
    });
    for segment in segments {
        paint_segment(painter, segment, Some(*segment) == hovered, scene);
    }
    let hovered = hovered.map(|segment| HoveredRay {
        lines: hover_lines(&segment, scene, inspections),
        segment,
    });
    if let (Some(hovered), Some(pointer)) = (&hovered, pointer) {
        hover_card_ui(ui, pointer, &hovered.lines);
    }
    hovered
}

fn colour(segment: &ScreenSegment) -> Color32 {
    let c = match (segment.segment.kind, segment.segment.end) {
        (SegmentKind::Ray(RayKind::Primary), _) => Color32::from_rgb(245, 245, 245),
        (SegmentKind::Ray(RayKind::Reflection), _) => Color32::from_rgb(80, 220, 255),
        (SegmentKind::Ray(RayKind::Refraction), _) => Color32::from_rgb(200, 130, 255),
        (SegmentKind::Ray(RayKind::InternalReflection), _) => Color32::from_rgb(255, 120, 220),
        (SegmentKind::Ray(RayKind::Shadow), SegmentEnd::Blocked) => Color32::from_rgb(255, 85, 75),
        (SegmentKind::Ray(RayKind::Shadow), _) => Color32::from_rgb(255, 214, 80),
        (SegmentKind::Unreached(_), _) => Color32::from_gray(165),
        (SegmentKind::Normal, _) => Color32::from_rgb(120, 235, 120),
    };
    if segment.inspected {
        c
    } else {
        c.gamma_multiply(0.6)
    }
}

fn paint_segment(painter: &egui::Painter, s: &ScreenSegment, hot: bool, scene: &Scene) {
    let colour = if hot {
        Color32::from_rgb(255, 240, 120)
    } else {
        colour(s)
    };
    let width = if hot { 3.0 } else { 2.0 };
    let shadow = Stroke::new(width + 1.5, Color32::from_black_alpha(150));
    let stroke = Stroke::new(width, colour);
    let points = [s.from, s.to];
    if matches!(s.segment.kind, SegmentKind::Unreached(_)) {
        painter.add(Shape::dashed_line(&points, stroke, 5.0, 4.0));
    } else {
        painter.line_segment(points, shadow);
        painter.line_segment(points, stroke);
    }
    let along = (s.to - s.from).normalized();
    let small = FontId::proportional(11.0);
    match (s.segment.kind, s.segment.end) {
        (SegmentKind::Normal, _) | (SegmentKind::Ray(_), SegmentEnd::RunsOff) => {
            arrow_head(painter, s.to, along, colour);
        }
        (SegmentKind::Ray(RayKind::Shadow), SegmentEnd::Blocked) => {
            // A cross on the blocker, and its name.
            for d in [Vec2::new(5.0, 5.0), Vec2::new(5.0, -5.0)] {
                painter.line_segment([s.to - d, s.to + d], Stroke::new(2.5, colour));
            }
            if s.inspected
                && let Some(blocker) = s.segment.object.and_then(|i| scene.objects.get(i))
            {
                chip(
                    painter,
                    s.to + Vec2::new(8.0, 4.0),
                    &blocker.name,
                    colour,
                    &small,
                );
            }
        }
        (SegmentKind::Ray(_), SegmentEnd::Hit) => {
            painter.circle(
                s.to,
                3.5,
                colour,
                Stroke::new(1.5, Color32::from_black_alpha(170)),
            );
        }
        (SegmentKind::Unreached(outcome), _) if s.inspected => {
            chip(painter, s.to, short_reason(outcome), colour, &small);
        }
        _ => {}
    }
}

fn arrow_head(painter: &egui::Painter, tip: Pos2, along: Vec2, colour: Color32) {
    let across = along.rot90();
    let base = tip - along * 9.0;
    painter.add(Shape::convex_polygon(
        vec![tip, base + across * 4.0, base - across * 4.0],
        colour,
        Stroke::NONE,
    ));
}

/// A small text on a dark chip, left-aligned at `at`.
fn chip(painter: &egui::Painter, at: Pos2, text: &str, colour: Color32, font: &FontId) {
    let galley = painter.layout_no_wrap(text.to_owned(), font.clone(), colour);
    let rect = Align2::LEFT_CENTER.anchor_size(at + Vec2::new(4.0, 0.0), galley.size());
    painter.rect_filled(rect.expand(2.0), 2.0, Color32::from_black_alpha(170));
    painter.galley(rect.min, galley, colour);
}

/// Why a light has no shadow ray, in a word or two for the stub's end.
#[must_use]
pub fn short_reason(outcome: LightOutcome) -> &'static str {
    match outcome {
        LightOutcome::BehindSurface => "behind",
        LightOutcome::Skipped(LightSkip::OutsideSpotCone) => "outside cone",
        LightOutcome::Skipped(LightSkip::AtTheLight) => "at the light",
        LightOutcome::Skipped(LightSkip::NoDiffuseOrSpecular) => "no kd, ks",
        LightOutcome::Skipped(LightSkip::TermsOff) => "terms off",
        LightOutcome::Lit | LightOutcome::AddsNothing | LightOutcome::Shadowed(_) => "shadows off",
    }
}

/// The numbers of a hovered segment, as the pixel inspector shows them, and what the
/// isolation switches left out of its pixel (muted lights cast no ray, hidden objects
/// are not met: said, so that their absence is not taken for the tracer's).
fn hover_lines(s: &ScreenSegment, scene: &Scene, inspections: &[PixelInspection]) -> Vec<String> {
    let object = |i: usize| scene.objects.get(i).map_or("?", |o| o.name.as_str());
    let light = |i: usize| {
        scene
            .lights
            .get(i)
            .map_or_else(String::new, |l| light_label(l, i))
    };
    let (x, y) = s.pixel;
    let head = format!("pixel ({x}, {y}) · depth {}", s.segment.depth);
    let pixel = inspections
        .iter()
        .find(|i| i.pixel == s.pixel)
        .and_then(|i| i.result.as_ref().ok());
    let report = pixel.map(|p| &p.report);
    let mut lines = Vec::new();
    match s.segment.kind {
        SegmentKind::Ray(kind) => {
            let Some(ray) = report.and_then(|r| traced_rays(r).get(s.segment.ray?).copied()) else {
                return vec![head];
            };
            lines.push(format!("{} ray · {head}", kind.name()));
            if let Some(l) = ray.light {
                lines.push(format!("towards {}", light(l)));
            }
            lines.push(format!("origin {}", v(ray.origin)));
            lines.push(format!("direction {}", v(ray.direction)));
            match (ray.t, ray.hit) {
                (Some(t), Some(hit)) => {
                    let verb = if kind == RayKind::Shadow {
                        "blocked by"
                    } else {
                        "hits"
                    };
                    // The leaf of a tree the ray met: a bounce's surface, or where a
                    // shadow ray met its blocker.
                    let leaf = report.and_then(|r| {
                        let mut bounces = r.bounces.iter();
                        if kind == RayKind::Shadow {
                            bounces.find_map(|b| b.blocker_surface_at(hit.point))
                        } else {
                            bounces
                                .find(|b| b.hit.is_some_and(|h| h.p == hit.point))
                                .and_then(|b| b.surface.as_ref())
                        }
                        .map(|s| s.path.clone())
                    });
                    let name = leaf.unwrap_or_else(|| object(hit.object).to_owned());
                    lines.push(format!("{verb} {name} at t {t:.6}"));
                    lines.push(format!("point {}", v(hit.point)));
                    lines.push(format!("normal {}", v(hit.normal)));
                }
                _ => match ray.t_max {
                    Some(t_max) => lines.push(format!("reaches the light at t {t_max:.6}")),
                    None => lines.push("meets nothing".to_owned()),
                },
            }
        }
        SegmentKind::Unreached(outcome) => {
            let name = s.segment.light.map(light).unwrap_or_default();
            lines.push(format!("{name} · {head}"));
            lines.push(format!(
                "no shadow ray: {}",
                outcome.text(&|i| object(i).to_owned())
            ));
        }
        SegmentKind::Normal => {
            lines.push(format!("normal · {head}"));
            lines.push(format!("at {}", v(s.segment.from)));
            lines.push(format!(
                "n {}",
                v((s.segment.to - s.segment.from).normalize_or_zero())
            ));
        }
    }
    lines.extend(pixel.map(isolation_lines).unwrap_or_default());
    lines
}

/// The hovered segment's numbers beside the pointer, as labels (readable by AccessKit).
fn hover_card_ui(ui: &egui::Ui, pointer: Pos2, lines: &[String]) {
    egui::Area::new(Id::unique("raylab ray hover"))
        .order(egui::Order::Tooltip)
        .fixed_pos(pointer + Vec2::new(16.0, 16.0))
        .interactable(false)
        .show(ui.ctx(), |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                for line in lines {
                    ui.label(egui::RichText::new(line).monospace().size(11.5));
                }
            });
        });
}

fn v(p: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", p.x, p.y, p.z)
}

#[cfg(test)]
mod tests;
