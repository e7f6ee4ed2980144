//! What anti-aliasing may do to a pixel. Another renderer samples a pixel elsewhere, or
//! more often, than raylab: where the pixel's footprint holds an edge (a silhouette, a
//! shadow's or a spot cone's border, a reflected outline), its value is some blend of
//! what the pixel and its neighbours show, and a correct picture differs there by whole
//! colours. Inside smooth regions the blend moves a pixel by a level or two at most.
//!
//! So each pixel may lie anywhere in the range of raylab's values over its 3x3
//! neighbourhood, widened by half that range (raylab's own picture may itself be a
//! blend whose pure colours lie beyond its neighbours'); and the linear fit, which aims
//! at each pixel's value, gives such a pixel less weight the wider its range is.
//! Measured on raylab's own pictures at 1, 2 and 4 samples per pixel against each
//! other (docs/COMPARE.md, "Anti-aliasing"): all but about 1% of the pixels that differ
//! by more than 2 levels fall inside.
//!
//! The allowance costs sight where every pixel is an edge (a small mirror ball's
//! reflections, highlights), so it is made only where the sampling differs: raylab
//! samples more than once a pixel, or the other picture blends colours across
//! raylab's outlines clearly more often than raylab's own picture does
//! ([`samples_otherwise`]). A tracer that takes one sample at the pixel's centre, as
//! raylab at 1 sample does, keeps outlines sharp and is compared pixel for pixel.

/// How far the range reaches past the neighbourhood's, as a share of its width.
const WIDEN: f64 = 0.5;

/// The width of range, in 8-bit levels, at which a pixel's weight in the linear fit
/// halves.
const HALF_WEIGHT_LEVELS: f64 = 4.0;

/// A pixel blends its neighbours across an outline when, between two opposite
/// neighbours this many levels apart (in some channel)...
const BLEND_CONTRAST: i32 = 24;

/// ...it lies inside their range by at least this share of it from either end.
const BLEND_MARGIN: f64 = 0.15;

/// The other picture samples otherwise when it blends at least this many times as many
/// outline pixels as raylab's...
const BLEND_RATIO: f64 = 1.8;

/// ...and more by at least this share of the outline pixels.
const BLEND_EXCESS: f64 = 0.02;

/// Per pixel and channel, how far below and above raylab's value a correct picture
/// with other sampling may be, and the weight the linear fit gives the channel.
#[derive(Clone, Debug)]
pub struct SamplingSpread {
    /// Per pixel and channel, `(below, above)` in linear units.
    pub reach: Vec<[(f64, f64); 3]>,
    /// Per pixel and channel, the linear fit's weight, in (0, 1].
    pub weight: Vec<[f64; 3]>,
}

impl SamplingSpread {
    /// The spread of raylab's `width`-wide linear picture `own` (clamped to [0, 1] as it
    /// is written).
    #[must_use]
    pub fn of(own: &[[f64; 3]], width: u32) -> Self {
        let width = width.max(1) as usize;
        let height = own.len() / width;
        let clamped: Vec<[f64; 3]> = own.iter().map(|p| p.map(|v| v.clamp(0.0, 1.0))).collect();
        let mut reach = Vec::with_capacity(own.len());
        let mut weight = Vec::with_capacity(own.len());
        for y in 0..height {
            for x in 0..width {
                let centre = clamped[y * width + x];
                let mut low = centre;
                let mut high = centre;
                for ny in y.saturating_sub(1)..(y + 2).min(height) {
                    for nx in x.saturating_sub(1)..(x + 2).min(width) {
                        let n = clamped[ny * width + nx];
                        for c in 0..3 {
                            low[c] = low[c].min(n[c]);
                            high[c] = high[c].max(n[c]);
                        }
                    }
                }
                let mut r = [(0.0, 0.0); 3];
                let mut w = [1.0; 3];
                for c in 0..3 {
                    let range = high[c] - low[c];
                    r[c] = (
                        centre[c] - low[c] + WIDEN * range,
                        high[c] - centre[c] + WIDEN * range,
                    );
                    w[c] = 1.0 / (1.0 + (255.0 * range / HALF_WEIGHT_LEVELS).powi(2));
                }
                reach.push(r);
                weight.push(w);
            }
        }
        Self { reach, weight }
    }
}

impl SamplingSpread {
    /// No allowance: every pixel compared as raylab samples it.
    #[must_use]
    pub fn none(pixels: usize) -> Self {
        Self {
            reach: vec![[(0.0, 0.0); 3]; pixels],
            weight: vec![[1.0; 3]; pixels],
        }
    }
}

/// Whether `other` (bytes) was sampled otherwise than raylab's `own` (bytes, at one
/// sample a pixel): it blends colours across the `outline` pixels (where raylab's
/// objects meet) clearly more often than `own` does. Measured on the example scenes:
/// raylab's pictures at 2 and 4 samples blend 2.5 to 3.7 times as many outline pixels
/// as at 1; pictures with a bug at 1 sample, 0.3 to 1.2 times.
#[must_use]
pub fn samples_otherwise(own: &[[u8; 3]], other: &[[u8; 3]], outline: &[bool], width: u32) -> bool {
    let outlines = outline.iter().filter(|&&o| o).count();
    let own_blends = blended_outline_pixels(own, outline, width) as f64;
    let other_blends = blended_outline_pixels(other, outline, width) as f64;
    other_blends >= BLEND_RATIO * own_blends
        && other_blends - own_blends >= BLEND_EXCESS * outlines as f64
}

/// The `outline` pixels of `rgb` that lie strictly between two opposite neighbours of
/// high contrast: colours blended across an edge.
fn blended_outline_pixels(rgb: &[[u8; 3]], outline: &[bool], width: u32) -> usize {
    let width = width.max(1) as usize;
    let height = rgb.len() / width;
    let between = |p: [u8; 3], a: [u8; 3], b: [u8; 3]| {
        (0..3).any(|c| {
            let (lo, hi) = (i32::from(a[c].min(b[c])), i32::from(a[c].max(b[c])));
            let margin = BLEND_MARGIN * f64::from(hi - lo);
            let v = f64::from(p[c]);
            hi - lo >= BLEND_CONTRAST && v > f64::from(lo) + margin && v < f64::from(hi) - margin
        })
    };
    let mut count = 0;
    for y in 1..height.saturating_sub(1) {
        for x in 1..width - 1 {
            let p = y * width + x;
            if outline[p]
                && (between(rgb[p], rgb[p - 1], rgb[p + 1])
                    || between(rgb[p], rgb[p - width], rgb[p + width]))
            {
                count += 1;
            }
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_edge_reaches_both_sides_and_a_flat_region_nothing() {
        // A 4x3 picture: black left half, white right half.
        let own: Vec<[f64; 3]> = (0..12)
            .map(|i| if i % 4 < 2 { [0.0; 3] } else { [1.0; 3] })
            .collect();
        let spread = SamplingSpread::of(&own, 4);
        // Pixel (1, 1) is black beside white: it may be any grey, and beyond.
        let (below, above) = spread.reach[5][0];
        assert!((below - 0.5).abs() < 1e-12 && (above - 1.5).abs() < 1e-12);
        assert!(spread.weight[5][0] < 0.01);
        // A flat 3x3 picture reaches nowhere and keeps its full weight.
        let flat = SamplingSpread::of(&[[0.3; 3]; 9], 3);
        assert!(flat.reach.iter().all(|r| r[1] == (0.0, 0.0)));
        assert!(flat.weight.iter().all(|w| w[2] == 1.0));
    }

    #[test]
    fn a_blended_outline_is_sampled_otherwise_and_a_sharp_one_is_not() {
        // 8x3: black | white, the outline between columns 3 and 4.
        let sharp: Vec<[u8; 3]> = (0..24)
            .map(|i| if i % 8 < 4 { [0; 3] } else { [255; 3] })
            .collect();
        let outline: Vec<bool> = (0..24).map(|i| matches!(i % 8, 3 | 4)).collect();
        let mut blended = sharp.clone();
        blended[8 + 3] = [128; 3];
        assert!(samples_otherwise(&sharp, &blended, &outline, 8));
        assert!(!samples_otherwise(&sharp, &sharp, &outline, 8));
        assert!(!samples_otherwise(&blended, &sharp, &outline, 8));
    }
}
