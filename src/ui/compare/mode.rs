//! The ways of looking at two pictures of one scene: a swipe line between them, the two
//! side by side, their difference as a heatmap, or one at a time, flipped.

/// How the comparison view shows raylab's picture and the other one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CompareMode {
    /// raylab's picture left of a movable line, the other picture right of it.
    #[default]
    Swipe,
    /// The two pictures next to each other, zoomed and panned together.
    SideBySide,
    /// The largest channel difference per pixel as a heatmap.
    Difference,
    /// One picture at a time; flipping shows the other in the same place.
    Flip,
}

impl CompareMode {
    /// Every mode, in the toolbar's order.
    pub const ALL: [CompareMode; 4] = [
        CompareMode::Swipe,
        CompareMode::SideBySide,
        CompareMode::Difference,
        CompareMode::Flip,
    ];

    /// The toolbar button's text (also its accessible name).
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            CompareMode::Swipe => "Swipe",
            CompareMode::SideBySide => "Side by side",
            CompareMode::Difference => "Difference",
            CompareMode::Flip => "Flip",
        }
    }

    /// What the mode shows, for the button's tooltip.
    #[must_use]
    pub fn hint(self) -> &'static str {
        match self {
            CompareMode::Swipe => "raylab left of the line, the other image right; drag to move it",
            CompareMode::SideBySide => "raylab left, the other image right, zoomed together",
            CompareMode::Difference => "the largest channel difference per pixel (white = most)",
            CompareMode::Flip => "one picture at a time; Flip (or Space) shows the other",
        }
    }
}

/// Which picture a single-picture view shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Side {
    /// raylab's picture.
    #[default]
    Raylab,
    /// The other renderer's picture.
    Other,
}

impl Side {
    /// The other side.
    #[must_use]
    pub fn flipped(self) -> Self {
        match self {
            Side::Raylab => Side::Other,
            Side::Other => Side::Raylab,
        }
    }

    /// "raylab" or "other image".
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Side::Raylab => "raylab",
            Side::Other => "other image",
        }
    }
}
