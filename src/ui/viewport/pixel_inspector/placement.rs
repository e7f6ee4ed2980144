//! Where the pixel inspector window goes: beside each newly inspected pixel, until the
//! user moves it; from then on it stays where they put it (until it is closed).

use egui::{Id, Pos2, Rect, Vec2};

/// Space between the inspected pixel and the window.
const GAP: f32 = 28.0;

/// Where the inspected pixel is on screen, and the screen the window stays on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelAnchor {
    /// The pixel's screen position.
    pub pos: Pos2,
    /// The viewport's rectangle (the window prefers to stay over it).
    pub viewport: Rect,
    /// The whole window's content (the inspector may cover side panels rather than
    /// the pixel).
    pub screen: Rect,
}

impl PixelAnchor {
    /// The top-left corner of a window of `size`: right of the pixel when it fits in
    /// the viewport, else left of it when that fits, else on the side with more room,
    /// never over the pixel while the screen has room beside it.
    pub(super) fn window_pos(&self, size: Vec2) -> Pos2 {
        let right = self.pos.x + GAP;
        let left = self.pos.x - GAP - size.x;
        let x = if right + size.x <= self.viewport.max.x {
            right
        } else if left >= self.viewport.min.x {
            left
        } else if self.screen.max.x - self.pos.x >= self.pos.x - self.screen.min.x {
            right.min(self.screen.max.x - size.x)
        } else {
            left.max(self.screen.min.x)
        };
        let y = (self.pos.y - 80.0).min(self.screen.max.y - size.y);
        Pos2::new(x, y.max(self.screen.min.y))
    }
}

/// What the window's placement remembers between frames.
pub(super) struct Placement {
    id: Id,
    /// The pixel it was last put beside.
    placed_for: Option<(u32, u32)>,
    /// Whether the user has moved it since it opened.
    moved_by_user: bool,
}

impl Placement {
    /// The placement of window `id`.
    pub fn load(ctx: &egui::Context, id: Id) -> Self {
        Self {
            id,
            placed_for: ctx.data(|d| d.get_temp::<(u32, u32)>(id.with("placed"))),
            moved_by_user: ctx
                .data(|d| d.get_temp::<bool>(id.with("moved by the user")))
                .unwrap_or(false),
        }
    }

    /// `window`, put beside `pixel` when it is a new one and the user has not moved it;
    /// and whether it was.
    pub fn place<'a>(
        &self,
        ctx: &egui::Context,
        window: egui::Window<'a>,
        pixel: (u32, u32),
        anchor: Option<PixelAnchor>,
        opening_size: Vec2,
    ) -> (egui::Window<'a>, bool) {
        let id = self.id;
        let (Some(anchor), false) = (anchor, self.placed_for == Some(pixel) || self.moved_by_user)
        else {
            return (window, false);
        };
        // The size it has now (the user may have resized it), else the one it opens at.
        let size = ctx
            .memory(|m| m.area_rect(id))
            .map_or(opening_size, |r| r.size());
        let pos = anchor.window_pos(size);
        move_open_window(ctx, id, pos);
        ctx.data_mut(|d| d.insert_temp(id.with("placed"), pixel));
        (window.current_pos(pos), true)
    }

    /// The user moved window `id`: from now on it stays where they put it.
    pub fn moved_by_user(ctx: &egui::Context, id: Id) {
        ctx.data_mut(|d| d.insert_temp(id.with("moved by the user"), true));
    }

    /// Closed: the next window opens beside its pixel again.
    pub fn forget(ctx: &egui::Context, id: Id) {
        ctx.data_mut(|d| d.remove::<bool>(id.with("moved by the user")));
    }
}

/// Moves an already open window's area to `pos`. `current_pos` alone only places a window
/// that opens: egui 0.37's title-bar drag mode puts back the position the area had before
/// the pass, so an open window would stay where it was.
fn move_open_window(ctx: &egui::Context, id: Id, pos: Pos2) {
    if let Some(mut state) = egui::AreaState::load(ctx, id) {
        state.set_left_top_pos(pos);
        ctx.memory_mut(|m| {
            m.areas_mut()
                .set_state(egui::LayerId::new(egui::Order::Middle, id), state);
        });
    }
}
