//! The rendered picture: linear, unclamped RGB, and its 8-bit encoding.

use glam::Vec3;
use image::ImageEncoder as _;

/// A linear RGB image, unclamped, row-major from the top-left.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels.
    pub pixels: Vec<Vec3>,
}

impl Image {
    /// A black image.
    #[must_use]
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
        }
    }

    /// The pixel at column `x`, row `y`.
    #[must_use]
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// 8-bit RGBA, clamped to [0, 1] and written linearly as `round(255 c)`, which is
    /// what the legacy renderer does. Non-finite values (never produced) become 0.
    #[must_use]
    pub fn to_rgba8(&self) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(self.pixels.len() * 4);
        for p in &self.pixels {
            bytes.extend(p.to_array().map(encode_linear));
            bytes.push(255);
        }
        bytes
    }

    /// Encodes the image as PNG (8-bit RGB, linear `round(255 c)`).
    ///
    /// # Errors
    /// The encoder's error (only on I/O problems of the writer).
    pub fn write_png(&self, writer: impl std::io::Write) -> image::ImageResult<()> {
        let mut rgb = Vec::with_capacity(self.pixels.len() * 3);
        for p in &self.pixels {
            rgb.extend_from_slice(&p.to_array().map(encode_linear));
        }
        image::codecs::png::PngEncoder::new(writer).write_image(
            &rgb,
            self.width,
            self.height,
            image::ExtendedColorType::Rgb8,
        )
    }

    /// The PNG file's bytes.
    #[must_use]
    pub fn png_bytes(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        self.write_png(&mut bytes)
            .expect("encoding to memory cannot fail");
        bytes
    }
}

/// One channel: clamp to [0, 1], then round(255 c) (halves away from zero).
///
/// Rounds as `floor(x + 0.5)` in f64, where the sum is exact (x has 24 significant bits),
/// so it equals `f32::round` for every x in [0, 255] without the libm call that baseline
/// x86-64 makes of it (a third of the PNG encoding time).
#[must_use]
#[inline]
pub fn encode_linear(c: f32) -> u8 {
    if c.is_finite() {
        (f64::from(c.clamp(0.0, 1.0) * 255.0) + 0.5) as u8
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::encode_linear;

    #[test]
    fn encoding_rounds_exactly_like_f32_round_next_to_every_half() {
        // The thousand f32 either side of each c with 255 c = k + 1/2, where a rounding
        // shortcut such as (x + 0.5) in f32 goes wrong, and a sweep of [0, 1].
        let mut checked = 0;
        for k in 0..255 {
            let centre = ((k as f32 + 0.5) / 255.0).to_bits();
            for bits in centre - 1000..=centre + 1000 {
                let c = f32::from_bits(bits);
                assert_eq!(encode_linear(c), (c * 255.0).round() as u8, "c = {c:e}");
                checked += 1;
            }
        }
        for i in 0..=100_000 {
            let c = i as f32 / 100_000.0;
            assert_eq!(encode_linear(c), (c * 255.0).round() as u8, "c = {c:e}");
        }
        assert_eq!(checked, 255 * 2001);
        assert_eq!(encode_linear(-1.0), 0);
        assert_eq!(encode_linear(2.0), 255);
        assert_eq!(encode_linear(f32::NAN), 0);
    }
}
