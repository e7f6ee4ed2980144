//! Where the pixel inspector window goes: beside each newly inspected pixel, until the
//! user moves it; from then on it stays where they put it (until it is closed).

use egui::{Id, Pos2, Vec2};

use super::window::PixelAnchor;

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
