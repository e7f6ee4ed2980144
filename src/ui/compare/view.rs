//! Zoom and pan of the comparison view: which part of the picture (in uv, 0 to 1) fills
//! a frame on screen, and which image pixel lies under a screen point. Both pictures
//! are shown through the same view, so they stay aligned in every mode.

use egui::{Pos2, Rect, Vec2};

/// The deepest zoom, relative to the whole picture fitting its frame.
pub const MAX_ZOOM: f32 = 64.0;

/// The visible part of the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZoomView {
    /// 1 shows the whole picture; 2 half its width and height; up to [`MAX_ZOOM`].
    pub zoom: f32,
    /// The centre of the visible part, in uv (0 to 1 across the picture).
    pub centre_uv: Pos2,
}

impl Default for ZoomView {
    fn default() -> Self {
        Self {
            zoom: 1.0,
            centre_uv: Pos2::new(0.5, 0.5),
        }
    }
}

impl ZoomView {
    /// The visible part of the picture in uv, inside `[0, 1]^2`.
    #[must_use]
    pub fn uv_rect(&self) -> Rect {
        let size = 1.0 / self.zoom.clamp(1.0, MAX_ZOOM);
        let half = size / 2.0;
        let centre = Pos2::new(
            self.centre_uv.x.clamp(half, 1.0 - half),
            self.centre_uv.y.clamp(half, 1.0 - half),
        );
        Rect::from_center_size(centre, Vec2::splat(size))
    }

    /// The uv under `pos` when the visible part fills `frame`.
    #[must_use]
    pub fn uv_at(&self, frame: Rect, pos: Pos2) -> Pos2 {
        let uv = self.uv_rect();
        let t = (pos - frame.min) / frame.size();
        uv.min + t * uv.size()
    }

    /// The image pixel (column, row) under `pos`, or `None` outside `frame` or the
    /// `width x height` image.
    #[must_use]
    pub fn pixel_at(&self, frame: Rect, pos: Pos2, width: u32, height: u32) -> Option<(u32, u32)> {
        if !frame.contains(pos) {
            return None;
        }
        let uv = self.uv_at(frame, pos);
        let x = (uv.x * width as f32).floor();
        let y = (uv.y * height as f32).floor();
        let inside = x >= 0.0 && y >= 0.0 && x < width as f32 && y < height as f32;
        inside.then_some((x as u32, y as u32))
    }

    /// Zooms by `factor` keeping the picture point under `pos` where it is.
    pub fn zoom_about(&mut self, frame: Rect, pos: Pos2, factor: f32) {
        let anchor = self.uv_at(frame, pos);
        let t = (pos - frame.min) / frame.size();
        self.zoom = (self.zoom * factor).clamp(1.0, MAX_ZOOM);
        let size = 1.0 / self.zoom;
        let min = anchor - t * size;
        self.centre_uv = min + Vec2::splat(size / 2.0);
        self.centre_uv = self.uv_rect().center();
    }

    /// Moves the picture with a drag of `delta` screen points over `frame`.
    pub fn pan(&mut self, frame: Rect, delta: Vec2) {
        let uv = self.uv_rect();
        self.centre_uv = uv.center() - delta / frame.size() * uv.size();
        self.centre_uv = self.uv_rect().center();
    }

    /// Screen points per image pixel across `frame` for a `width`-pixel image.
    #[must_use]
    pub fn points_per_pixel(&self, frame: Rect, width: u32) -> f32 {
        frame.width() / (self.uv_rect().width() * width.max(1) as f32)
    }
}

/// A frame cut at screen `x` into its left and right parts, each with the uv it shows.
#[must_use]
pub fn split_at(frame: Rect, uv: Rect, x: f32) -> [(Rect, Rect); 2] {
    let x = x.clamp(frame.min.x, frame.max.x);
    let t = (x - frame.min.x) / frame.width().max(f32::MIN_POSITIVE);
    let uv_x = uv.min.x + t * uv.width();
    let left = Rect::from_min_max(frame.min, Pos2::new(x, frame.max.y));
    let right = Rect::from_min_max(Pos2::new(x, frame.min.y), frame.max);
    let uv_left = Rect::from_min_max(uv.min, Pos2::new(uv_x, uv.max.y));
    let uv_right = Rect::from_min_max(Pos2::new(uv_x, uv.min.y), uv.max);
    [(left, uv_left), (right, uv_right)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame() -> Rect {
        Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(400.0, 300.0))
    }

    #[test]
    fn the_whole_picture_maps_corner_to_corner() {
        let view = ZoomView::default();
        assert_eq!(
            view.uv_rect(),
            Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0))
        );
        let f = frame();
        assert_eq!(view.pixel_at(f, f.min, 40, 30), Some((0, 0)));
        assert_eq!(
            view.pixel_at(f, f.max - Vec2::splat(0.01), 40, 30),
            Some((39, 29))
        );
        assert_eq!(view.pixel_at(f, f.min - Vec2::splat(1.0), 40, 30), None);
        assert!((view.points_per_pixel(f, 40) - 10.0).abs() < 1e-4);
    }

    #[test]
    fn zooming_keeps_the_point_under_the_pointer_and_stays_inside_the_picture() {
        let f = frame();
        let mut view = ZoomView::default();
        let pos = Pos2::new(180.0, 110.0);
        let before = view.pixel_at(f, pos, 40, 30);
        view.zoom_about(f, pos, 8.0);
        assert_eq!(view.zoom, 8.0);
        assert_eq!(view.pixel_at(f, pos, 40, 30), before);
        assert!((view.points_per_pixel(f, 40) - 80.0).abs() < 1e-3);
        // Panning far past the edge stops at it.
        view.pan(f, Vec2::new(1e5, 1e5));
        assert_eq!(view.uv_rect().min, Pos2::ZERO);
        view.zoom_about(f, pos, 1e6);
        assert_eq!(view.zoom, MAX_ZOOM);
        view.zoom_about(f, pos, 1e-6);
        assert_eq!(
            view.uv_rect(),
            Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0))
        );
    }

    #[test]
    fn a_split_shows_the_uv_under_each_part() {
        let f = frame();
        let uv = Rect::from_min_max(Pos2::new(0.2, 0.0), Pos2::new(0.6, 0.5));
        let [(left, uv_left), (right, uv_right)] = split_at(f, uv, 200.0);
        assert_eq!((left.max.x, right.min.x), (200.0, 200.0));
        assert!((uv_left.max.x - 0.3).abs() < 1e-6, "{uv_left:?}");
        assert_eq!((uv_left.min, uv_right.max), (uv.min, uv.max));
    }
}
