//! The progressive plan: which passes a preview renders, in order.

use crate::trace::RenderOptions;

/// Shortest long side of the coarse pass, in pixels.
pub const COARSE_MIN_LONG_SIDE: u32 = 64;
/// Largest resolution divider of the coarse pass.
pub const COARSE_MAX_DIVIDER: u32 = 8;

/// One pass of a progressive render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pass {
    /// The image at `1 / divider` of the target resolution, one sample per pixel.
    Coarse {
        /// Resolution divider (> 1).
        divider: u32,
    },
    /// Full resolution; `samples` of `target` anti-aliasing samples accumulated so far.
    /// `target == 1` is the one-sample pass through pixel centres.
    Full {
        /// Samples accumulated so far (the sum of this pass and the ones before).
        samples: u32,
        /// Stratification count: the samples come from a grid of this many cells.
        target: u32,
    },
}

impl Pass {
    /// The image size of this pass for a target of `width` x `height`.
    #[must_use]
    pub fn size(self, width: u32, height: u32) -> (u32, u32) {
        match self {
            Pass::Coarse { divider } => (
                width.div_ceil(divider).max(1),
                height.div_ceil(divider).max(1),
            ),
            Pass::Full { .. } => (width, height),
        }
    }
}

/// The coarse pass's divider: the largest of 8, 4, 2 that keeps the long side at least
/// 64 pixels; `None` when the target is already that small.
#[must_use]
pub fn coarse_divider(width: u32, height: u32) -> Option<u32> {
    let long = width.max(height);
    let mut divider = COARSE_MAX_DIVIDER;
    while divider > 1 && long / divider < COARSE_MIN_LONG_SIDE {
        divider /= 2;
    }
    (divider > 1).then_some(divider)
}

/// Every coarse pass's divider, coarsest first: 8, 4, 2 while the long side stays at least
/// 64 pixels (so the first is [`coarse_divider`]); empty when the target is that small.
#[must_use]
pub fn coarse_dividers(width: u32, height: u32) -> Vec<u32> {
    let Some(first) = coarse_divider(width, height) else {
        return Vec::new();
    };
    std::iter::successors(Some(first), |d| (*d > 2).then_some(d / 2)).collect()
}

/// The passes for `options`: coarse passes at dividers 8, 4, 2 (those whose long side is
/// at least 64 pixels), full resolution at one sample, then anti-aliasing samples in
/// doubling batches (4, 8, 16...) up to `options.samples_per_pixel`.
#[must_use]
pub fn plan_passes(options: &RenderOptions) -> Vec<Pass> {
    let mut passes: Vec<Pass> = coarse_dividers(options.width, options.height)
        .into_iter()
        .map(|divider| Pass::Coarse { divider })
        .collect();
    passes.push(Pass::Full {
        samples: 1,
        target: 1,
    });
    let target = options.samples_per_pixel;
    if target > 1 {
        let mut samples = 4.min(target);
        loop {
            passes.push(Pass::Full { samples, target });
            if samples == target {
                break;
            }
            samples = (samples * 2).min(target);
        }
    }
    passes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{Isolation, TermSwitches, View};

    fn options(width: u32, height: u32, samples_per_pixel: u32) -> RenderOptions {
        RenderOptions {
            width,
            height,
            samples_per_pixel,
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            isolation: Isolation::NONE,
        }
    }

    #[test]
    fn coarse_keeps_the_long_side_at_least_64() {
        assert_eq!(coarse_divider(800, 600), Some(8));
        assert_eq!(coarse_divider(300, 200), Some(4));
        assert_eq!(coarse_divider(130, 40), Some(2));
        assert_eq!(coarse_divider(64, 64), None);
    }

    #[test]
    fn coarse_passes_halve_the_divider_down_to_2() {
        assert_eq!(coarse_dividers(800, 600), vec![8, 4, 2]);
        assert_eq!(coarse_dividers(600, 800), vec![8, 4, 2]);
        assert_eq!(coarse_dividers(511, 300), vec![4, 2]);
        assert_eq!(coarse_dividers(300, 200), vec![4, 2]);
        assert_eq!(coarse_dividers(130, 40), vec![2]);
        assert_eq!(coarse_dividers(127, 40), Vec::<u32>::new());
        assert_eq!(coarse_dividers(64, 64), Vec::<u32>::new());
        assert_eq!(coarse_dividers(1, 1), Vec::<u32>::new());
    }

    #[test]
    fn plan_goes_coarse_full_then_doubling_samples() {
        let plan = plan_passes(&options(800, 600, 16));
        assert_eq!(
            plan,
            vec![
                Pass::Coarse { divider: 8 },
                Pass::Coarse { divider: 4 },
                Pass::Coarse { divider: 2 },
                Pass::Full {
                    samples: 1,
                    target: 1
                },
                Pass::Full {
                    samples: 4,
                    target: 16
                },
                Pass::Full {
                    samples: 8,
                    target: 16
                },
                Pass::Full {
                    samples: 16,
                    target: 16
                },
            ]
        );
        assert_eq!(Pass::Coarse { divider: 8 }.size(801, 600), (101, 75));
    }

    #[test]
    fn one_sample_target_ends_at_the_full_pass() {
        assert_eq!(
            plan_passes(&options(300, 200, 1)),
            vec![
                Pass::Coarse { divider: 4 },
                Pass::Coarse { divider: 2 },
                Pass::Full {
                    samples: 1,
                    target: 1
                },
            ]
        );
        let plan = plan_passes(&options(32, 32, 1));
        assert_eq!(
            plan,
            vec![Pass::Full {
                samples: 1,
                target: 1
            }]
        );
    }

    #[test]
    fn every_sample_prefix_the_plan_shows_covers_the_pixel_quadrants_evenly() {
        use crate::trace::sample_in_pixel;
        for target in [2, 4, 6, 12, 16, 48, 64, 1024, 4096] {
            for pass in plan_passes(&options(64, 64, target)) {
                let Pass::Full { samples, target } = pass else {
                    continue;
                };
                if target == 1 {
                    continue;
                }
                for (px, py) in [(0, 0), (5, 3), (63, 17), (40, 41)] {
                    let mut quadrants = [0u32; 4];
                    for index in 0..samples {
                        let s = sample_in_pixel(px, py, index, target);
                        quadrants[usize::from(s.y >= 0.5) * 2 + usize::from(s.x >= 0.5)] += 1;
                    }
                    let (least, most) = (quadrants.iter().min(), quadrants.iter().max());
                    let (least, most) = (*least.unwrap(), *most.unwrap());
                    if samples % 4 == 0 {
                        assert!(
                            least == most,
                            "{samples} of {target}, pixel ({px}, {py}): {quadrants:?}"
                        );
                    } else {
                        assert!(least >= samples / 4 && most <= samples / 4 + 2);
                    }
                }
            }
        }
    }
}
