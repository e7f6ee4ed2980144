//! Sets of pixels on the picture's grid: connected regions of a mask, a region grown by
//! a pixel, its holes filled, its bounding box. Pixels are row-major indices.

use serde::Serialize;

/// The 8 neighbours of a pixel.
const AROUND: [(i64, i64); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

/// A picture's size, for walking its grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl Grid {
    /// The pixel at column `x`, row `y`, if it is on the grid.
    #[must_use]
    pub fn at(self, x: i64, y: i64) -> Option<usize> {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        (x >= 0 && y >= 0 && x < w && y < h).then(|| (y * w + x) as usize)
    }

    /// The column and row of pixel `p`.
    #[must_use]
    pub fn xy(self, p: usize) -> (i64, i64) {
        let w = self.width as usize;
        ((p % w) as i64, (p / w) as i64)
    }

    /// The pixels around `p` (8 of them inside the picture).
    pub fn around(self, p: usize) -> impl Iterator<Item = usize> {
        let (x, y) = self.xy(p);
        AROUND
            .iter()
            .filter_map(move |&(dx, dy)| self.at(x + dx, y + dy))
    }

    /// The pixels left, right, above and below `p`.
    pub fn beside(self, p: usize) -> impl Iterator<Item = usize> {
        let (x, y) = self.xy(p);
        [(-1, 0), (1, 0), (0, -1), (0, 1)]
            .into_iter()
            .filter_map(move |(dx, dy)| self.at(x + dx, y + dy))
    }

    /// The 8-connected regions of `mask`, each ascending.
    #[must_use]
    pub fn regions(self, mask: &[bool]) -> Vec<Vec<u32>> {
        let mut seen = vec![false; mask.len()];
        let mut out = Vec::new();
        for start in 0..mask.len() {
            if !mask[start] || seen[start] {
                continue;
            }
            seen[start] = true;
            let mut region = vec![start as u32];
            let mut next = 0;
            while next < region.len() {
                let p = region[next] as usize;
                next += 1;
                for q in self.around(p) {
                    if mask[q] && !seen[q] {
                        seen[q] = true;
                        region.push(q as u32);
                    }
                }
            }
            region.sort_unstable();
            out.push(region);
        }
        out
    }

    /// `pixels` with the pixels of their bounding box that no path outside them
    /// reaches from the box's border (their holes), ascending.
    #[must_use]
    pub fn filled(self, pixels: &[u32]) -> Vec<u32> {
        let Some(bbox) = PixelBox::of(pixels, self.width) else {
            return Vec::new();
        };
        let (w, h) = (bbox.x1 - bbox.x0 + 1, bbox.y1 - bbox.y0 + 1);
        let local = Grid {
            width: w,
            height: h,
        };
        let to_local = |p: u32| {
            let (x, y) = self.xy(p as usize);
            local.at(x - i64::from(bbox.x0), y - i64::from(bbox.y0))
        };
        let mut inside = vec![false; (w * h) as usize];
        for &p in pixels {
            if let Some(q) = to_local(p) {
                inside[q] = true;
            }
        }
        // Flood the outside from the border; what it does not reach is filled.
        let mut outside = vec![false; inside.len()];
        let mut work: Vec<usize> = (0..inside.len())
            .filter(|&q| {
                let (x, y) = local.xy(q);
                !inside[q] && (x == 0 || y == 0 || x == i64::from(w) - 1 || y == i64::from(h) - 1)
            })
            .collect();
        for &q in &work {
            outside[q] = true;
        }
        while let Some(q) = work.pop() {
            for r in local.beside(q) {
                if !inside[r] && !outside[r] {
                    outside[r] = true;
                    work.push(r);
                }
            }
        }
        (0..inside.len())
            .filter(|&q| !outside[q])
            .map(|q| {
                let (x, y) = local.xy(q);
                ((y + i64::from(bbox.y0)) * i64::from(self.width) + x + i64::from(bbox.x0)) as u32
            })
            .collect()
    }

    /// `pixels` and the pixels around them, ascending.
    #[must_use]
    pub fn grown(self, pixels: &[u32]) -> Vec<u32> {
        let mut out: Vec<u32> = pixels
            .iter()
            .flat_map(|&p| std::iter::once(p).chain(self.around(p as usize).map(|q| q as u32)))
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// The bounding box of some pixels, inclusive: columns `x0..=x1`, rows `y0..=y1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct PixelBox {
    /// The leftmost column.
    pub x0: u32,
    /// The top row.
    pub y0: u32,
    /// The rightmost column.
    pub x1: u32,
    /// The bottom row.
    pub y1: u32,
}

impl PixelBox {
    /// The box of row-major `pixels` of a picture `width` wide; `None` for no pixels.
    #[must_use]
    pub fn of(pixels: &[u32], width: u32) -> Option<Self> {
        let first = *pixels.first()?;
        let start = Self {
            x0: first % width,
            y0: first / width,
            x1: first % width,
            y1: first / width,
        };
        Some(pixels.iter().fold(start, |b, &p| {
            let (x, y) = (p % width, p / width);
            Self {
                x0: b.x0.min(x),
                y0: b.y0.min(y),
                x1: b.x1.max(x),
                y1: b.y1.max(y),
            }
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_touching_at_a_corner_are_one_and_holes_are_filled() {
        let grid = Grid {
            width: 6,
            height: 5,
        };
        let drawn = [
            "###...", //
            "#.#...", "###...", "...#..", ".....#",
        ];
        let mask: Vec<bool> = drawn.concat().chars().map(|c| c == '#').collect();
        let regions = grid.regions(&mask);
        assert_eq!(regions.len(), 2);
        assert_eq!(regions[0].len(), 9, "the ring and its corner neighbour");
        assert_eq!(regions[1], vec![29]);
        let ring: Vec<u32> = regions[0].iter().copied().filter(|&p| p != 21).collect();
        assert!(grid.filled(&ring).contains(&7), "the ring's hole");
        assert_eq!(grid.filled(&ring).len(), 9);
        let bbox = PixelBox::of(&regions[0], 6).unwrap();
        assert_eq!((bbox.x0, bbox.y0, bbox.x1, bbox.y1), (0, 0, 3, 3));
        assert_eq!(grid.grown(&[29]), vec![22, 23, 28, 29]);
    }
}
