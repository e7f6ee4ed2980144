//! A perceptual difference beside PSNR: LDR-FLIP (Andersson et al., "FLIP: A Difference
//! Evaluator for Alternating Images", HPG 2020), computed by NVIDIA's reference
//! implementation through the `nv-flip` crate (docs/COMPARE.md says why a binding and not
//! a port). FLIP models how a viewer at a given distance from a monitor sees the two
//! pictures flipped back and forth: 0 is no visible difference, 1 the largest.
//!
//! raylab's picture is the reference and the other picture the test image, both read as
//! sRGB-encoded 8-bit bytes, as the FLIP tool reads PNGs.

use image::RgbImage;

/// Pixels per degree of visual angle of the default viewing set-up (a 0.7 m wide 4K
/// monitor seen from 0.7 m), as the FLIP tool assumes when told nothing else.
pub const PIXELS_PER_DEGREE: f32 = nv_flip::DEFAULT_PIXELS_PER_DEGREE;

/// The percentile reported beside the mean: the error the worst 1% of pixels exceed.
pub const PERCENTILE: f64 = 0.99;

/// The FLIP error of one pair of pictures: per pixel and pooled.
#[derive(Clone, Debug, PartialEq)]
pub struct Perceptual {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Per pixel, row-major from the top-left, the FLIP error, 0 to 1.
    pub errors: Vec<f32>,
    /// The mean error over every pixel (the number the FLIP tool prints as "Mean").
    pub mean: f64,
    /// The 99th percentile of the per-pixel errors (linear interpolation between the
    /// two nearest ranks, as numpy's default).
    pub p99: f64,
}

/// LDR-FLIP of `test` against `reference`, both `width * height` 8-bit sRGB pixels.
///
/// # Panics
/// When either picture does not hold `width * height` pixels.
#[must_use]
pub fn ldr_flip(width: u32, height: u32, reference: &[[u8; 3]], test: &[[u8; 3]]) -> Perceptual {
    let pixels = width as usize * height as usize;
    assert_eq!(reference.len(), pixels, "reference pixel count");
    assert_eq!(test.len(), pixels, "test pixel count");
    let flat = |rgb: &[[u8; 3]]| rgb.iter().flatten().copied().collect::<Vec<u8>>();
    let reference_image = nv_flip::FlipImageRgb8::with_data(width, height, &flat(reference));
    let test_image = nv_flip::FlipImageRgb8::with_data(width, height, &flat(test));
    let map = nv_flip::flip(reference_image, test_image, PIXELS_PER_DEGREE);
    let errors = map.to_vec();
    let mean = errors.iter().map(|&e| f64::from(e)).sum::<f64>() / pixels.max(1) as f64;
    let p99 = percentile(&errors, PERCENTILE);
    Perceptual {
        width,
        height,
        errors,
        mean,
        p99,
    }
}

/// The `q` quantile (0 to 1) of `values`, interpolating linearly between ranks; 0 for
/// no values.
#[must_use]
pub fn percentile(values: &[f32], q: f64) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    let mut sorted: Vec<f32> = values.to_vec();
    sorted.sort_by(f32::total_cmp);
    let rank = q.clamp(0.0, 1.0) * (sorted.len() - 1) as f64;
    let below = rank.floor() as usize;
    let above = rank.ceil() as usize;
    let t = rank - below as f64;
    f64::from(sorted[below]) * (1.0 - t) + f64::from(sorted[above]) * t
}

impl Perceptual {
    /// The error map in the FLIP tool's colours (magma: black for no error, through
    /// purple and orange, to pale yellow for the largest).
    #[must_use]
    pub fn map_rgb(&self) -> Vec<[u8; 3]> {
        let errors = nv_flip::FlipImageFloat::with_data(self.width, self.height, &self.errors);
        errors
            .apply_color_lut(&nv_flip::magma_lut())
            .to_vec()
            .chunks_exact(3)
            .map(|p| [p[0], p[1], p[2]])
            .collect()
    }

    /// The error map as PNG bytes.
    ///
    /// # Errors
    /// The encoder's message.
    pub fn map_png(&self) -> Result<Vec<u8>, String> {
        let bytes = self.map_rgb().into_iter().flatten().collect();
        let image = RgbImage::from_raw(self.width, self.height, bytes).ok_or("FLIP map size")?;
        let mut png = Vec::new();
        image
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .map_err(|e| format!("FLIP map: {e}"))?;
        Ok(png)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_pictures_have_no_error_and_a_changed_one_has() {
        let (w, h) = (32, 24);
        let grey: Vec<[u8; 3]> = (0..w * h).map(|i| [(i % 200) as u8; 3]).collect();
        let same = ldr_flip(w, h, &grey, &grey);
        assert_eq!(same.mean, 0.0);
        assert_eq!(same.p99, 0.0);
        let mut changed = grey.clone();
        for p in &mut changed[..(w * h / 4) as usize] {
            *p = [255, 0, 0];
        }
        let different = ldr_flip(w, h, &grey, &changed);
        assert!(different.mean > 0.05, "{}", different.mean);
        assert!(different.p99 > different.mean, "{different:?}");
    }

    #[test]
    fn the_percentile_interpolates_between_ranks() {
        let values = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(percentile(&values, 0.5), 2.0);
        assert!((percentile(&values, 0.99) - 3.96).abs() < 1e-12);
        assert_eq!(percentile(&[], 0.99), 0.0);
    }
}
