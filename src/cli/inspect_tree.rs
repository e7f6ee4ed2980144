//! The readable form of `raylab inspect`: the pixel's tree of rays, depth first, each
//! hit with its terms, its lights and their shadow rays, its mirror and transmitted rays
//! indented under it.

use std::fmt::Write as _;

use glam::DVec3;

use crate::scene::Scene;
use crate::trace::{
    HitSurface, Isolation, PixelReport, RayKind, RenderOptions, TracedRay, switches_text,
    traced_rays,
};

/// The scene's indices of the lights `isolation` switches off.
pub(super) fn lights_off(scene: &Scene, isolation: &Isolation) -> Vec<usize> {
    (0..scene.lights.len())
        .filter(|&i| !isolation.is_light_lit(i))
        .collect()
}

/// A tree leaf as the report names it: `"die/pip 3.1" (cut, surface 2 of 4 along the
/// line)`.
fn surface_text(surface: Option<&HitSurface>) -> Option<String> {
    let surface = surface?;
    let mut text = surface.path.clone();
    if let Some((k, n)) = surface.crossing {
        let cut = if surface.cut { "cut, " } else { "" };
        let _ = write!(text, " ({cut}surface {} of {n} along the line)", k + 1);
    }
    Some(text)
}

/// The name of the scene's object `index` (the record's indices are the scene's).
pub(super) fn object_name(scene: &Scene, index: usize) -> String {
    scene
        .objects
        .get(index)
        .map_or_else(|| format!("object {index}"), |o| o.name.clone())
}

/// The readable tree: the camera ray, then for each hit its terms, its lights with their
/// shadow rays, and its mirror bounce, indented by depth.
pub(super) fn tree_text(scene: &Scene, options: &RenderOptions, report: &PixelReport) -> String {
    let name = |i: usize| object_name(scene, i);
    let off = lights_off(scene, &options.isolation);
    let light_name = |i: usize| {
        scene.lights.get(i).map_or_else(
            || format!("light {}", i + 1),
            |l| format!("{} light {}", l.kind_name(), i + 1),
        )
    };
    let (x, y) = report.pixel;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "pixel ({x}, {y}) of {} x {}, centre ray, {}",
        options.width,
        options.height,
        switches_text(options.switches)
    );
    let _ = writeln!(
        out,
        "colour {}   before clamping {}",
        v(report.clamped),
        v(report.unclamped)
    );
    if !off.is_empty() {
        let names: Vec<String> = off.iter().map(|&i| light_name(i)).collect();
        let _ = writeln!(out, "off (muted or not solo): {}", names.join(", "));
    }
    if !options.isolation.hidden_objects.is_empty() {
        let names: Vec<String> = options
            .isolation
            .hidden_objects
            .iter()
            .map(|&i| name(i))
            .collect();
        let _ = writeln!(out, "hidden (rays pass through): {}", names.join(", "));
    }
    // The list holds each ray of the tree then its shadow rays, in the bounces' order:
    // split at each ray that is not a shadow ray, so rays of one depth stay apart.
    let rays = traced_rays(report);
    let mut groups: Vec<&[TracedRay]> = Vec::new();
    let mut start = 0;
    for end in 1..=rays.len() {
        if end == rays.len() || rays[end].kind != RayKind::Shadow {
            groups.push(&rays[start..end]);
            start = end;
        }
    }
    // Depth first, each ray's mirror ray then its transmitted ray under it, so the text
    // reads as the tree it is (the report keeps them breadth first).
    for index in depth_first(report) {
        let (bounce, group) = (&report.bounces[index], groups[index]);
        let pad = "  ".repeat(bounce.depth as usize);
        let own = group.first().filter(|r| r.kind != RayKind::Shadow);
        if let Some(ray) = own {
            let _ = writeln!(out, "{pad}{} ray {}", ray.kind.name(), ray_text(ray));
        }
        let Some(hit) = &bounce.hit else {
            let _ = writeln!(out, "{pad}  misses: background {}", v(bounce.background));
            continue;
        };
        let _ = writeln!(
            out,
            "{pad}  hits {} at t {:.6}: point {}, normal {}",
            surface_text(bounce.surface.as_ref()).unwrap_or_else(|| name(hit.object)),
            own.and_then(|r| r.t).unwrap_or(hit.t),
            v(hit.p),
            v(hit.n)
        );
        if let Some(triangle) = &bounce.triangle {
            let [a, b, c] = triangle.weights;
            let _ = writeln!(
                out,
                "{pad}  triangle {} of the file, barycentric ({a:.4}, {b:.4}, {c:.4})",
                triangle.triangle
            );
        }
        let _ = writeln!(out, "{pad}  ambient {}", v(bounce.ambient));
        for (light, outcome, record) in bounce.light_outcomes() {
            let mut line = format!("{pad}  {}: {}", light_name(light), outcome.text(&name));
            if let Some(record) = record {
                let _ = write!(
                    line,
                    ", n·l {:.4}, diffuse {}, specular {}",
                    record.n_dot_l,
                    v(record.diffuse),
                    v(record.specular)
                );
            }
            let _ = writeln!(out, "{line}");
            for ray in group
                .iter()
                .filter(|r| r.kind == RayKind::Shadow && r.light == Some(light))
            {
                let _ = writeln!(out, "{pad}    shadow ray {}", shadow_end(ray, &name));
            }
        }
        for &light in &off {
            let _ = writeln!(out, "{pad}  {}: off (muted or not solo)", light_name(light));
        }
        if let Some((km, reflected)) = bounce.reflection {
            let _ = writeln!(
                out,
                "{pad}  mirror: km {} × reflected {} = {}",
                v(km),
                v(reflected),
                v(km * reflected)
            );
        }
        if let Some((kt, transmitted)) = bounce.transmission {
            let _ = writeln!(
                out,
                "{pad}  transmission: kt {} × transmitted {} = {}",
                v(kt),
                v(transmitted),
                v(kt * transmitted)
            );
        }
        if let Some(unclamped) = bounce.unclamped {
            let _ = writeln!(
                out,
                "{pad}  clamped to [0, 1] (each ray) from {}",
                v(unclamped)
            );
        }
        let _ = writeln!(out, "{pad}  colour {}", v(bounce.colour));
    }
    out
}

/// The report's rays in depth-first order: each ray, then its rays in the order they
/// were cast (the mirror ray before the transmitted one).
fn depth_first(report: &PixelReport) -> Vec<usize> {
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); report.bounces.len()];
    for (index, bounce) in report.bounces.iter().enumerate() {
        if let Some((parent, _)) = bounce.from {
            children[parent].push(index);
        }
    }
    let mut order = Vec::with_capacity(report.bounces.len());
    let mut stack: Vec<usize> = (!report.bounces.is_empty())
        .then_some(0)
        .into_iter()
        .collect();
    while let Some(index) = stack.pop() {
        order.push(index);
        stack.extend(children[index].iter().rev());
    }
    order
}

fn ray_text(ray: &TracedRay) -> String {
    format!("from {} along {}", v(ray.origin), v(ray.direction))
}

fn shadow_end(ray: &TracedRay, name: &dyn Fn(usize) -> String) -> String {
    let start = ray_text(ray);
    match (ray.blocked_by, ray.t, ray.t_max) {
        (Some(blocker), Some(t), _) => format!("{start}: blocked by {} at t {t:.6}", name(blocker)),
        (Some(blocker), None, _) => format!("{start}: blocked by {}", name(blocker)),
        (None, _, Some(t_max)) => format!("{start}: reaches the light at t {t_max:.6}"),
        (None, _, None) => format!("{start}: nothing in the way"),
    }
}

pub(super) fn v(c: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}
