//! The other renderer's picture: an 8-bit RGB image read from PNG or PPM (the older
//! course framework writes PPM), kept as the bytes the file holds.

use std::path::Path;

use image::{DynamicImage, ImageReader};

use super::error::CompareError;

/// An 8-bit RGB image, row-major from the top-left, as another renderer wrote it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OtherImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels, each `[r, g, b]` as stored in the file.
    pub rgb: Vec<[u8; 3]>,
}

impl OtherImage {
    /// An image from its pixels.
    ///
    /// # Panics
    /// When `rgb` does not hold `width * height` pixels.
    #[must_use]
    pub fn new(width: u32, height: u32, rgb: Vec<[u8; 3]>) -> Self {
        assert_eq!(rgb.len(), width as usize * height as usize, "pixel count");
        Self { width, height, rgb }
    }

    /// The pixel at column `x`, row `y`.
    #[must_use]
    pub fn get(&self, x: u32, y: u32) -> [u8; 3] {
        self.rgb[y as usize * self.width as usize + x as usize]
    }

    /// Decodes PNG or PPM bytes (the format is found from the content, not the name).
    ///
    /// # Errors
    /// [`CompareError::NotAnImage`] for bytes no decoder accepts, and
    /// [`CompareError::NotEightBit`] for 16-bit or floating-point images.
    pub fn from_bytes(bytes: &[u8], path: &Path) -> Result<Self, CompareError> {
        let not_an_image = |message: String| CompareError::NotAnImage {
            path: path.to_owned(),
            message,
        };
        let reader = ImageReader::new(std::io::Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| not_an_image(e.to_string()))?;
        if reader.format().is_none() {
            return Err(not_an_image(
                "the content is neither PNG nor PPM".to_owned(),
            ));
        }
        let decoded = reader.decode().map_err(|e| not_an_image(e.to_string()))?;
        let rgb = match decoded {
            DynamicImage::ImageLuma8(_)
            | DynamicImage::ImageLumaA8(_)
            | DynamicImage::ImageRgb8(_)
            | DynamicImage::ImageRgba8(_) => decoded.to_rgb8(),
            other => {
                return Err(CompareError::NotEightBit {
                    path: path.to_owned(),
                    detail: format!("{:?} channels", other.color()),
                });
            }
        };
        let (width, height) = rgb.dimensions();
        let pixels = rgb.pixels().map(|p| p.0).collect();
        Ok(Self::new(width, height, pixels))
    }

    /// The image as PNG bytes.
    #[must_use]
    pub fn png_bytes(&self) -> Vec<u8> {
        let raw = self.rgb.iter().flatten().copied().collect();
        let image =
            image::RgbImage::from_raw(self.width, self.height, raw).expect("width * height pixels");
        let mut bytes = Vec::new();
        image
            .write_to(
                &mut std::io::Cursor::new(&mut bytes),
                image::ImageFormat::Png,
            )
            .expect("encoding to memory cannot fail");
        bytes
    }

    /// Reads a PNG or PPM file.
    ///
    /// # Errors
    /// [`CompareError::Read`] when the file cannot be read, otherwise as
    /// [`OtherImage::from_bytes`].
    pub fn load(path: &Path) -> Result<Self, CompareError> {
        let bytes = std::fs::read(path).map_err(|source| CompareError::Read {
            path: path.to_owned(),
            source,
        })?;
        Self::from_bytes(&bytes, path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_ppm_and_rejects_text() {
        let ppm = b"P6\n2 1\n255\n\x01\x02\x03\xff\x00\x80";
        let image = OtherImage::from_bytes(ppm, Path::new("a.ppm")).unwrap();
        assert_eq!((image.width, image.height), (2, 1));
        assert_eq!(image.rgb, vec![[1, 2, 3], [255, 0, 128]]);
        let error = OtherImage::from_bytes(b"hello", Path::new("a.png")).unwrap_err();
        assert!(
            error.to_string().contains("a.png is not a readable"),
            "{error}"
        );
    }
}
