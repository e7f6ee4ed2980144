//! The comparison's pictures as textures: raylab's, the other one, the difference
//! heatmap and the highlighted explanation's pixels, all sampled nearest-pixel so a
//! zoomed view shows single pixels as squares.

use egui::{Color32, ColorImage, TextureHandle, TextureOptions};

use crate::compare::{Comparison, difference_heatmap};

/// The highlight's colour (premultiplied orange at 45%): plain to see at a glance, and
/// thin enough that a zoomed pixel's own colour still shows through.
pub const HIGHLIGHT_COLOUR: Color32 = Color32::from_rgba_premultiplied(115, 66, 0, 115);

/// The textures of one comparison.
pub struct CompareTextures {
    /// raylab's picture as it writes it.
    pub raylab: TextureHandle,
    /// The other picture's bytes.
    pub other: TextureHandle,
    /// The difference heatmap (white = the largest difference).
    pub difference: TextureHandle,
    /// Levels of difference shown as white.
    pub difference_most: u8,
    /// The highlighted explanation and its mask.
    highlight: Option<(usize, TextureHandle)>,
}

impl CompareTextures {
    /// Uploads the pictures of `comparison`.
    #[must_use]
    pub fn new(ctx: &egui::Context, comparison: &Comparison) -> Self {
        let size = [comparison.width as usize, comparison.height as usize];
        let load = |name: &str, rgb: &[[u8; 3]]| {
            ctx.load_texture(name, rgb_image(size, rgb), TextureOptions::NEAREST)
        };
        let (heatmap, most) = difference_heatmap(comparison);
        Self {
            raylab: load("compare raylab", &comparison.raylab_rgb),
            other: load("compare other", &comparison.other.rgb),
            difference: load("compare difference", &heatmap),
            difference_most: most,
            highlight: None,
        }
    }

    /// The mask of explanation `index` (uploaded when it changes), or `None`.
    pub fn highlight(
        &mut self,
        ctx: &egui::Context,
        comparison: &Comparison,
        index: Option<usize>,
    ) -> Option<&TextureHandle> {
        let Some(index) = index.filter(|&i| i < comparison.explanations.len()) else {
            self.highlight = None;
            return None;
        };
        if self
            .highlight
            .as_ref()
            .is_none_or(|(shown, _)| *shown != index)
        {
            let size = [comparison.width as usize, comparison.height as usize];
            let mut pixels = vec![Color32::TRANSPARENT; size[0] * size[1]];
            for &p in &comparison.explanations[index].pixels {
                if let Some(pixel) = pixels.get_mut(p as usize) {
                    *pixel = HIGHLIGHT_COLOUR;
                }
            }
            let image = ColorImage::new(size, pixels);
            let texture = ctx.load_texture("compare highlight", image, TextureOptions::NEAREST);
            self.highlight = Some((index, texture));
        }
        self.highlight.as_ref().map(|(_, texture)| texture)
    }
}

/// An opaque image from 8-bit RGB pixels.
fn rgb_image(size: [usize; 2], rgb: &[[u8; 3]]) -> ColorImage {
    let pixels = rgb
        .iter()
        .map(|&[r, g, b]| Color32::from_rgb(r, g, b))
        .collect();
    ColorImage::new(size, pixels)
}
