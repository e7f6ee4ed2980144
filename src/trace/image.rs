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
        let rgb: Vec<u8> = self
            .pixels
            .iter()
            .flat_map(|p| p.to_array().map(encode_linear))
            .collect();
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

/// One channel: clamp to [0, 1], then round(255 c).
#[must_use]
pub fn encode_linear(c: f32) -> u8 {
    if c.is_finite() {
        (c.clamp(0.0, 1.0) * 255.0).round() as u8
    } else {
        0
    }
}
