//! What the viewport's gizmos are made of: light markers, the translate, rotate and scale
//! gizmos of the selection, and the spotlight's cone, built as screen-space elements
//! (each maybe a grabbable handle); `gizmo_paint.rs` paints them. The math is in
//! [`crate::gizmo`]; this file only projects.

use egui::emath::RectTransform;
use egui::{Color32, Pos2, Rect, Vec2};
use glam::{DVec2, DVec3};

use super::commands::Selection;
use crate::gizmo::handles::HandleShape;
use crate::gizmo::spot::{rim_handle, rim_points, rim_radial, tip_point};
use crate::gizmo::transform_drag::{TranslateHandle, euler_ring_axes, world_axis};
use crate::gizmo::view::{object_axes, world_per_pixel};
use crate::scene::{Light, Scene, Transform};
use crate::trace::{PinholeCamera, Ray};

/// Length of the translate and scale arrows, in screen points.
const ARROW_PX: f64 = 84.0;
/// Radius of the rotate rings, in screen points.
const RING_PX: f64 = 72.0;
/// Length of a directional light's arrow, in screen points.
const SUN_ARROW_PX: f64 = 70.0;
/// The spotlight cone's slant length, as a fraction of the camera's distance to its
/// target (constant while the light is aimed, so handles do not run from the cursor).
const CONE_FRACTION: f64 = 0.3;

/// Colours of the x, y and z handles.
pub const AXIS_COLOURS: [Color32; 3] = [
    Color32::from_rgb(236, 72, 80),
    Color32::from_rgb(118, 206, 62),
    Color32::from_rgb(66, 140, 246),
];
/// The spotlight cone and its handles.
pub const CONE_COLOUR: Color32 = Color32::from_rgb(255, 196, 64);
/// A handle under the pointer or being dragged.
pub const HOT_COLOUR: Color32 = Color32::from_rgb(255, 240, 120);

/// Which gizmo the selected object shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GizmoMode {
    /// Axis arrows and plane handles.
    #[default]
    Translate,
    /// Rings about the Euler axes.
    Rotate,
    /// Handles along the object's own axes.
    Scale,
}

/// A grabbable part of a gizmo.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HandleId {
    /// Moves the selected object or light.
    Translate(TranslateHandle),
    /// Changes Euler angle 0, 1 or 2 of the selected object.
    Ring(usize),
    /// Changes scale component 0, 1 or 2 of the selected object.
    Scale(usize),
    /// Re-aims the selected spotlight.
    SpotTip,
    /// Changes the selected spotlight's angle.
    SpotRim,
    /// Re-aims the selected directional light.
    Aim,
    /// The marker of light `i` (a click selects it).
    Marker(usize),
}

/// How an element is drawn (screen points).
#[derive(Clone, Debug)]
pub enum Part {
    /// A line.
    Line(Pos2, Pos2),
    /// An arrow from the first point to the second.
    Arrow(Pos2, Pos2),
    /// A closed line through the points.
    Loop(Vec<Pos2>),
    /// A filled dot with an outline.
    Dot(Pos2, f32),
    /// A filled quadrilateral.
    Quad([Pos2; 4]),
}

/// One drawn piece of a gizmo, grabbable when it has a handle.
#[derive(Clone, Debug)]
pub struct Element {
    /// What to draw.
    pub part: Part,
    /// Its colour.
    pub colour: Color32,
    /// The handle it belongs to.
    pub handle: Option<HandleId>,
}

/// Maps between the world, the scene's image pixels and the screen.
pub struct ViewMapping {
    /// The tracer's camera for the scene's output size.
    pub camera: PinholeCamera,
    /// Scene image pixels to screen points (the letterboxed picture).
    pub screen_from_image: RectTransform,
    /// Screen points to scene image pixels.
    pub image_from_screen: RectTransform,
    /// The scene's image height over the picture's height on screen.
    pub image_px_per_point: f64,
}

impl ViewMapping {
    /// The mapping for `scene` shown in `picture`.
    #[must_use]
    pub fn new(scene: &Scene, picture: Rect) -> Self {
        let (width, height) = (scene.camera.width.max(1), scene.camera.height.max(1));
        let image = Rect::from_min_size(Pos2::ZERO, Vec2::new(width as f32, height as f32));
        let screen_from_image = RectTransform::from_to(image, picture);
        Self {
            camera: PinholeCamera::new(&scene.camera, width, height),
            image_from_screen: screen_from_image.inverse(),
            screen_from_image,
            image_px_per_point: f64::from(height) / f64::from(picture.height().max(1.0)),
        }
    }

    /// Where a world point is on screen; `None` behind the eye.
    #[must_use]
    pub fn project(&self, p_world: DVec3) -> Option<Pos2> {
        let p = self.camera.project(p_world)?;
        let pos = self
            .screen_from_image
            .transform_pos(Pos2::new(p.x as f32, p.y as f32));
        pos.is_finite().then_some(pos)
    }

    /// The primary ray through a screen point.
    #[must_use]
    pub fn ray(&self, pos: Pos2) -> Ray {
        let p = self.image_from_screen.transform_pos(pos);
        self.camera.ray(DVec2::new(f64::from(p.x), f64::from(p.y)))
    }

    /// World units per screen point at `p_world`.
    #[must_use]
    pub fn world_per_point(&self, scene: &Scene, p_world: DVec3) -> f64 {
        world_per_pixel(
            &scene.camera,
            p_world,
            f64::from(scene.camera.height.max(1)),
        ) * self.image_px_per_point
    }
}

/// The slant length of a spotlight's drawn cone.
#[must_use]
pub fn cone_length(scene: &Scene) -> f64 {
    (scene.camera.position - scene.camera.look_at).length() * CONE_FRACTION
}

/// Where a directional light's arrow points to, and its length in world units.
#[must_use]
pub fn sun_anchor(scene: &Scene, view: &ViewMapping) -> (DVec3, f64) {
    let anchor = scene.camera.look_at;
    (anchor, view.world_per_point(scene, anchor) * SUN_ARROW_PX)
}

/// The tail of a directional light's arrow (its aim handle).
#[must_use]
pub fn sun_tail(anchor: DVec3, length: f64, direction: DVec3) -> DVec3 {
    anchor - direction.normalize_or_zero() * length
}

/// Every element of the viewport's gizmos for this scene, selection and mode, in
/// painting order.
#[must_use]
pub fn gizmo_elements(
    scene: &Scene,
    selection: &Selection,
    mode: GizmoMode,
    view: &ViewMapping,
) -> Vec<Element> {
    let mut out = Vec::new();
    let selected_light = match selection {
        Selection::Light(i) => Some(*i),
        _ => None,
    };
    for (index, light) in scene.lights.iter().enumerate() {
        light_elements(
            &mut out,
            scene,
            view,
            index,
            light,
            selected_light == Some(index),
        );
    }
    match selection {
        Selection::Object(index) => {
            if let Some(Transform::Trs(trs)) = scene.objects.get(*index).map(|o| &o.transform) {
                let size = view.world_per_point(scene, trs.translate);
                match mode {
                    GizmoMode::Translate => translate_elements(&mut out, view, trs.translate, size),
                    GizmoMode::Rotate => rotate_elements(&mut out, view, trs, size),
                    GizmoMode::Scale => scale_elements(&mut out, view, trs, size),
                }
            }
        }
        Selection::Light(index) => {
            if let Some(Light::Point { position, .. } | Light::Spot { position, .. }) =
                scene.lights.get(*index)
            {
                let size = view.world_per_point(scene, *position);
                translate_elements(&mut out, view, *position, size);
            }
            if let Some(Light::Spot {
                position,
                direction,
                angle_deg,
                ..
            }) = scene.lights.get(*index)
            {
                spot_handles(&mut out, scene, view, *position, *direction, *angle_deg);
            }
        }
        _ => {}
    }
    out
}

/// The marker of one light; a selected spotlight's cone (its handles come later, on top).
fn light_elements(
    out: &mut Vec<Element>,
    scene: &Scene,
    view: &ViewMapping,
    index: usize,
    light: &Light,
    selected: bool,
) {
    let colour = light_colour(light);
    match *light {
        Light::Ambient { .. } => {}
        Light::Point { position, .. } => {
            if let Some(p) = view.project(position) {
                dot(out, p, 6.0, colour, Some(HandleId::Marker(index)));
            }
        }
        Light::Spot {
            position,
            direction,
            angle_deg,
            ..
        } => {
            if selected {
                cone_wireframe(out, scene, view, position, direction, angle_deg);
            } else if let (Some(p), Some(q)) = (
                view.project(position),
                view.project(
                    position
                        + direction.normalize_or_zero()
                            * view.world_per_point(scene, position)
                            * 22.0,
                ),
            ) {
                line(out, p, q, colour.gamma_multiply(0.8), None);
            }
            if let Some(p) = view.project(position) {
                dot(out, p, 6.0, colour, Some(HandleId::Marker(index)));
            }
        }
        Light::Directional { direction, .. } => {
            let (anchor, length) = sun_anchor(scene, view);
            let tail = sun_tail(anchor, length, direction);
            if let (Some(from), Some(to)) = (view.project(tail), view.project(anchor)) {
                out.push(Element {
                    part: Part::Arrow(from, to),
                    colour: colour.gamma_multiply(if selected { 1.0 } else { 0.7 }),
                    handle: Some(HandleId::Marker(index)),
                });
                if selected {
                    dot(out, from, 6.5, CONE_COLOUR, Some(HandleId::Aim));
                }
            }
        }
    }
}

/// A light's colour as a marker colour: its hue, bright enough to see.
fn light_colour(light: &Light) -> Color32 {
    let c = light.colour();
    let peak = c.max_element();
    let c = if peak > 0.0 { c / peak } else { DVec3::ONE };
    let channel = |v: f64| (155.0 + 100.0 * v.clamp(0.0, 1.0)) as u8;
    Color32::from_rgb(channel(c.x), channel(c.y), channel(c.z))
}

/// Three axis arrows and three plane handles at `origin`; `size` is world units per point.
fn translate_elements(out: &mut Vec<Element>, view: &ViewMapping, origin: DVec3, size: f64) {
    let length = ARROW_PX * size;
    for (normal, colour) in AXIS_COLOURS.iter().enumerate() {
        let (a, b) = (world_axis(normal + 1), world_axis(normal + 2));
        let corners = [(0.28, 0.28), (0.5, 0.28), (0.5, 0.5), (0.28, 0.5)]
            .map(|(s, t)| view.project(origin + (a * s + b * t) * length));
        if let [Some(p0), Some(p1), Some(p2), Some(p3)] = corners
            && quad_area([p0, p1, p2, p3]) > 30.0
        {
            out.push(Element {
                part: Part::Quad([p0, p1, p2, p3]),
                colour: *colour,
                handle: Some(HandleId::Translate(TranslateHandle::Plane(normal))),
            });
        }
    }
    for (axis, colour) in AXIS_COLOURS.iter().enumerate() {
        let direction = world_axis(axis);
        if let (Some(from), Some(to)) = (
            view.project(origin + direction * length * 0.18),
            view.project(origin + direction * length),
        ) && from.distance(to) > 10.0
        {
            out.push(Element {
                part: Part::Arrow(from, to),
                colour: *colour,
                handle: Some(HandleId::Translate(TranslateHandle::Axis(axis))),
            });
        }
    }
    if let Some(p) = view.project(origin) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

/// Three rings about the Euler axes of `trs`.
fn rotate_elements(out: &mut Vec<Element>, view: &ViewMapping, trs: &crate::scene::Trs, size: f64) {
    let radius = RING_PX * size;
    for (i, axis) in euler_ring_axes(trs.rotate_deg).iter().enumerate() {
        let u = crate::gizmo::spot::perpendicular(*axis);
        let v = axis.normalize().cross(u);
        let points: Option<Vec<Pos2>> = (0..72)
            .map(|k| {
                let phi = f64::from(k) * std::f64::consts::TAU / 72.0;
                view.project(trs.translate + (u * phi.cos() + v * phi.sin()) * radius)
            })
            .collect();
        if let Some(points) = points {
            out.push(Element {
                part: Part::Loop(points),
                colour: AXIS_COLOURS[i],
                handle: Some(HandleId::Ring(i)),
            });
        }
    }
    if let Some(p) = view.project(trs.translate) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

/// Handles along the object's own axes, ending in squares.
fn scale_elements(out: &mut Vec<Element>, view: &ViewMapping, trs: &crate::scene::Trs, size: f64) {
    let length = ARROW_PX * size;
    for (i, axis) in object_axes(trs.rotate_deg).iter().enumerate() {
        if let (Some(from), Some(to)) = (
            view.project(trs.translate + *axis * length * 0.18),
            view.project(trs.translate + *axis * length),
        ) && from.distance(to) > 10.0
        {
            line(out, from, to, AXIS_COLOURS[i], Some(HandleId::Scale(i)));
            out.push(Element {
                part: Part::Quad(square(to, 5.0)),
                colour: AXIS_COLOURS[i],
                handle: Some(HandleId::Scale(i)),
            });
        }
    }
    if let Some(p) = view.project(trs.translate) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

/// The cone of a selected spotlight: rim circle, silhouette and axis.
fn cone_wireframe(
    out: &mut Vec<Element>,
    scene: &Scene,
    view: &ViewMapping,
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
) {
    let length = cone_length(scene);
    let rim: Option<Vec<Pos2>> = rim_points(position, direction, angle_deg, length, 64)
        .into_iter()
        .map(|p| view.project(p))
        .collect();
    let Some(apex) = view.project(position) else {
        return;
    };
    if let Some(rim) = rim {
        for k in [0, 16, 32, 48] {
            line(out, apex, rim[k], CONE_COLOUR.gamma_multiply(0.45), None);
        }
        out.push(Element {
            part: Part::Loop(rim),
            colour: CONE_COLOUR,
            handle: None,
        });
    }
    let radial = rim_radial(direction, position - scene.camera.position);
    for side in [radial, -radial] {
        if let Some(edge) = view.project(rim_handle(position, direction, side, angle_deg, length)) {
            line(out, apex, edge, CONE_COLOUR, None);
        }
    }
    if let Some(tip) = view.project(tip_point(position, direction, length)) {
        line(out, apex, tip, CONE_COLOUR.gamma_multiply(0.6), None);
    }
}

/// The tip and rim handles of a selected spotlight, drawn over everything else.
fn spot_handles(
    out: &mut Vec<Element>,
    scene: &Scene,
    view: &ViewMapping,
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
) {
    let length = cone_length(scene);
    let radial = rim_radial(direction, position - scene.camera.position);
    if let Some(rim) = view.project(rim_handle(position, direction, radial, angle_deg, length)) {
        dot(out, rim, 6.5, CONE_COLOUR, Some(HandleId::SpotRim));
    }
    if let Some(tip) = view.project(tip_point(position, direction, length)) {
        dot(out, tip, 6.5, CONE_COLOUR, Some(HandleId::SpotTip));
    }
}

fn dot(out: &mut Vec<Element>, p: Pos2, radius: f32, colour: Color32, handle: Option<HandleId>) {
    out.push(Element {
        part: Part::Dot(p, radius),
        colour,
        handle,
    });
}

fn line(out: &mut Vec<Element>, a: Pos2, b: Pos2, colour: Color32, handle: Option<HandleId>) {
    out.push(Element {
        part: Part::Line(a, b),
        colour,
        handle,
    });
}

fn square(centre: Pos2, half: f32) -> [Pos2; 4] {
    [
        centre + Vec2::new(-half, -half),
        centre + Vec2::new(half, -half),
        centre + Vec2::new(half, half),
        centre + Vec2::new(-half, half),
    ]
}

fn quad_area(q: [Pos2; 4]) -> f32 {
    let cross = |a: Pos2, b: Pos2| a.x * b.y - a.y * b.x;
    0.5 * (0..4)
        .map(|i| cross(q[i], q[(i + 1) % 4]))
        .sum::<f32>()
        .abs()
}

fn dvec(p: Pos2) -> DVec2 {
    DVec2::new(f64::from(p.x), f64::from(p.y))
}

/// The grabbable shapes of `elements`, each with its handle, for
/// [`crate::gizmo::handles::pick_handle`].
#[must_use]
pub fn handle_shapes(elements: &[Element]) -> Vec<(HandleShape, HandleId)> {
    let mut shapes = Vec::new();
    for element in elements {
        let Some(handle) = element.handle else {
            continue;
        };
        match &element.part {
            Part::Line(a, b) | Part::Arrow(a, b) => {
                shapes.push((HandleShape::Segment(dvec(*a), dvec(*b)), handle));
            }
            Part::Loop(points) => {
                for (k, a) in points.iter().enumerate() {
                    let b = points[(k + 1) % points.len()];
                    shapes.push((HandleShape::Segment(dvec(*a), dvec(b)), handle));
                }
            }
            Part::Dot(p, _) => shapes.push((HandleShape::Point(dvec(*p)), handle)),
            Part::Quad(q) => {
                let centre =
                    (q[0].to_vec2() + q[1].to_vec2() + q[2].to_vec2() + q[3].to_vec2()) / 4.0;
                shapes.push((HandleShape::Point(dvec(centre.to_pos2())), handle));
            }
        }
    }
    shapes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::MatrixRows;

    fn scene_and_view() -> (Scene, ViewMapping) {
        let scene = super::super::files::default_scene();
        let picture = Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(400.0, 300.0));
        let view = ViewMapping::new(&scene, picture);
        (scene, view)
    }

    fn handles(elements: &[Element]) -> Vec<HandleId> {
        elements.iter().filter_map(|e| e.handle).collect()
    }

    #[test]
    fn the_ray_through_a_projected_point_passes_through_it() {
        let (_, view) = scene_and_view();
        for p in [DVec3::new(0.3, 1.2, -0.5), DVec3::new(-2.0, 0.1, 1.5)] {
            let pos = view.project(p).unwrap();
            assert!(view.screen_from_image.to().contains(pos), "{pos:?}");
            let ray = view.ray(pos);
            let to_p = p - ray.origin;
            let miss = (to_p - ray.dir * to_p.dot(ray.dir)).length();
            assert!(miss < 1e-5 * to_p.length(), "{miss}");
        }
    }

    #[test]
    fn a_selected_spotlight_has_tip_and_rim_handles_and_lights_have_markers() {
        let (scene, view) = scene_and_view();
        let elements = gizmo_elements(&scene, &Selection::Light(3), GizmoMode::Rotate, &view);
        let handles = handles(&elements);
        for wanted in [
            HandleId::SpotTip,
            HandleId::SpotRim,
            HandleId::Marker(1),
            HandleId::Marker(2),
            HandleId::Marker(3),
            HandleId::Translate(TranslateHandle::Axis(0)),
        ] {
            assert!(handles.contains(&wanted), "{wanted:?}");
        }
        assert!(
            !handles.contains(&HandleId::Marker(0)),
            "ambient has no place"
        );
        assert!(!handles.contains(&HandleId::Ring(0)), "lights only move");
    }

    #[test]
    fn each_mode_shows_its_handles_and_a_matrix_transform_none() {
        let (mut scene, view) = scene_and_view();
        let select = Selection::Object(1);
        let only = |mode| {
            let elements = gizmo_elements(&scene, &select, mode, &view);
            handles(&elements)
                .into_iter()
                .filter(|h| !matches!(h, HandleId::Marker(_)))
                .collect::<Vec<_>>()
        };
        assert!(
            only(GizmoMode::Translate).contains(&HandleId::Translate(TranslateHandle::Plane(1)))
        );
        assert!(only(GizmoMode::Rotate).contains(&HandleId::Ring(2)));
        assert!(only(GizmoMode::Scale).contains(&HandleId::Scale(0)));
        let rows: MatrixRows = scene.objects[1].transform.to_rows();
        scene.objects[1].transform = Transform::Matrix(rows);
        let elements = gizmo_elements(&scene, &select, GizmoMode::Translate, &view);
        assert!(
            handles(&elements)
                .iter()
                .all(|h| matches!(h, HandleId::Marker(_)))
        );
    }
}
