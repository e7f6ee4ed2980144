//! The rendered picture: linear, unclamped RGB, and its 8-bit encoding.

use glam::Vec3;
use image::ImageEncoder as _;

use crate::scene::Quantise;

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

    /// Encodes the image as PNG (8-bit RGB, linear, each channel clamped to [0, 1] and
    /// made a byte as `quantise` says: `round(255 c)` or the course's `int(255 c)`).
    ///
    /// # Errors
    /// The encoder's error (only on I/O problems of the writer).
    pub fn write_png(
        &self,
        writer: impl std::io::Write,
        quantise: Quantise,
    ) -> image::ImageResult<()> {
        let mut rgb = Vec::with_capacity(self.pixels.len() * 3);
        for p in &self.pixels {
            rgb.extend_from_slice(&p.to_array().map(|c| encode(c, quantise)));
        }
        image::codecs::png::PngEncoder::new(writer).write_image(
            &rgb,
            self.width,
            self.height,
            image::ExtendedColorType::Rgb8,
        )
    }

    /// The PNG file's bytes, rounded (`round(255 c)`).
    #[must_use]
    pub fn png_bytes(&self) -> Vec<u8> {
        self.png_bytes_as(Quantise::Round)
    }

    /// The PNG file's bytes, each channel made a byte as `quantise` says.
    #[must_use]
    pub fn png_bytes_as(&self, quantise: Quantise) -> Vec<u8> {
        let mut bytes = Vec::new();
        self.write_png(&mut bytes, quantise)
            .expect("encoding to memory cannot fail");
        bytes
    }
}

/// One channel as `quantise` says: clamped to [0, 1], then rounded ([`encode_linear`])
/// or truncated (`floor(255 c)`, the course's `int(255 c)`). Non-finite values become 0.
#[must_use]
#[inline]
pub fn encode(c: f32, quantise: Quantise) -> u8 {
    match quantise {
        Quantise::Round => encode_linear(c),
        // The cast truncates and is exact: 255 c has at most 24 significant bits.
        Quantise::Truncate if c.is_finite() => (f64::from(c.clamp(0.0, 1.0)) * 255.0) as u8,
        Quantise::Truncate => 0,
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
    use super::{Quantise, encode, encode_linear};

    #[test]
    fn truncation_floors_and_rounding_rounds_at_every_byte() {
        for k in 0..255u8 {
            let just_below_next = ((f64::from(k) + 0.99) / 255.0) as f32;
            assert_eq!(encode(just_below_next, Quantise::Truncate), k);
            assert_eq!(encode(just_below_next, Quantise::Round), k + 1);
        }
        assert_eq!(encode(1.0, Quantise::Truncate), 255);
        assert_eq!(encode(7.5, Quantise::Truncate), 255);
        assert_eq!(encode(-0.2, Quantise::Truncate), 0);
        assert_eq!(encode(f32::NAN, Quantise::Truncate), 0);
    }

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
