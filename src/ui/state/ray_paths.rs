//! What the ray-path overlay draws: which rays, which pixels (the inspected one, its row
//! or column spread out, the pinned ones). Editor state, not part of the scene.

/// At most this many pixels of a row or column are traced and drawn.
pub const MAX_SPAN_PIXELS: u32 = 24;

/// Which pixels around the inspected one are drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RaySpan {
    /// The inspected pixel only.
    #[default]
    Pixel,
    /// Pixels spread along its row.
    Row,
    /// Pixels spread along its column.
    Column,
}

/// What the overlay draws (editor state, not part of the scene, not undoable).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RayPathSettings {
    /// Draw the camera rays.
    pub primary: bool,
    /// Draw the shadow rays and the stubs towards lights without one.
    pub shadow: bool,
    /// Draw the mirror bounces.
    pub reflection: bool,
    /// Draw the transmitted rays (refracted and internally reflected).
    pub transmission: bool,
    /// Draw the normals at the hits.
    pub normals: bool,
    /// The inspected pixel, or its row or column.
    pub span: RaySpan,
    /// Pixels whose rays stay drawn, in the order they were pinned.
    pub pinned: Vec<(u32, u32)>,
}

impl Default for RayPathSettings {
    fn default() -> Self {
        Self {
            primary: true,
            shadow: true,
            reflection: true,
            transmission: true,
            normals: true,
            span: RaySpan::Pixel,
            pinned: Vec::new(),
        }
    }
}

impl RayPathSettings {
    /// The pixels to trace: the inspected one first, then its row or column spread out
    /// (at most [`MAX_SPAN_PIXELS`]), then the pinned ones; each once, all inside the
    /// `width` x `height` image.
    #[must_use]
    pub fn pixels(
        &self,
        inspected: Option<(u32, u32)>,
        width: u32,
        height: u32,
    ) -> Vec<(u32, u32)> {
        let mut out: Vec<(u32, u32)> = Vec::new();
        let mut add = |p: (u32, u32)| {
            if p.0 < width && p.1 < height && !out.contains(&p) {
                out.push(p);
            }
        };
        if let Some((x, y)) = inspected {
            add((x, y));
            match self.span {
                RaySpan::Pixel => {}
                RaySpan::Row => spread(width).for_each(|sx| add((sx, y))),
                RaySpan::Column => spread(height).for_each(|sy| add((x, sy))),
            }
        }
        for pin in &self.pinned {
            add(*pin);
        }
        out
    }

    /// Pins `pixel`, or unpins it if it is pinned.
    pub fn toggle_pin(&mut self, pixel: (u32, u32)) {
        if let Some(at) = self.pinned.iter().position(|p| *p == pixel) {
            self.pinned.remove(at);
        } else {
            self.pinned.push(pixel);
        }
    }
}

/// Up to [`MAX_SPAN_PIXELS`] indices spread evenly over `0..length`, at cell centres.
fn spread(length: u32) -> impl Iterator<Item = u32> {
    let count = length.min(MAX_SPAN_PIXELS);
    (0..count).map(move |i| {
        ((u64::from(i) * 2 + 1) * u64::from(length) / (2 * u64::from(count.max(1)))) as u32
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_is_spread_and_capped_and_pins_follow() {
        let mut settings = RayPathSettings {
            span: RaySpan::Row,
            ..RayPathSettings::default()
        };
        settings.toggle_pin((5, 5));
        settings.toggle_pin((999, 0));
        let pixels = settings.pixels(Some((3, 7)), 800, 600);
        assert_eq!(pixels[0], (3, 7), "the inspected pixel first");
        let row: Vec<_> = pixels.iter().filter(|p| p.1 == 7).collect();
        assert_eq!(row.len(), MAX_SPAN_PIXELS as usize + 1);
        assert!(row.iter().all(|p| p.0 < 800));
        assert_eq!(
            pixels.last(),
            Some(&(5, 5)),
            "pinned, and the one outside dropped"
        );
        settings.toggle_pin((5, 5));
        assert_eq!(settings.pinned, vec![(999, 0)]);
        let column = RayPathSettings {
            span: RaySpan::Column,
            ..RayPathSettings::default()
        };
        assert_eq!(
            column.pixels(Some((1, 1)), 4, 3),
            vec![(1, 1), (1, 0), (1, 2)]
        );
        assert!(column.pixels(None, 4, 3).is_empty());
    }
}
