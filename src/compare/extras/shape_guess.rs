//! A guess of the shape behind an outline of pixels, for an object the other picture
//! draws and raylab does not: a sphere projects to an ellipse, a cube to a convex
//! quadrilateral (seen face on) or hexagon (seen from a corner). Each is fitted simply
//! and judged by how well it covers the pixels (intersection over union of the pixel
//! centres); where none covers them well, the guess is "unknown" rather than a stretch.

use glam::{DMat2, DVec2};

/// The fitted outline must cover the pixels this well (intersection over union).
const MIN_FIT: f64 = 0.9;

/// Fewer pixels than this are too few to tell an ellipse from a polygon.
const MIN_PIXELS: usize = 30;

/// What an outline looks like.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShapeGuess {
    /// An ellipse: a sphere.
    Sphere,
    /// A convex quadrilateral or hexagon: a cube.
    Cube,
    /// No simple fit.
    Unknown,
}

impl ShapeGuess {
    /// The name used in JSON and text.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ShapeGuess::Sphere => "sphere",
            ShapeGuess::Cube => "cube",
            ShapeGuess::Unknown => "unknown",
        }
    }
}

/// The guess for the pixels (column, row) of one outline, holes included.
#[must_use]
pub fn guess(pixels: &[(i64, i64)]) -> ShapeGuess {
    if pixels.len() < MIN_PIXELS {
        return ShapeGuess::Unknown;
    }
    let centres: Vec<DVec2> = pixels
        .iter()
        .map(|&(x, y)| DVec2::new(x as f64 + 0.5, y as f64 + 0.5))
        .collect();
    let ellipse = moment_ellipse(&centres).map_or(0.0, |(mean, inverse)| {
        coverage(pixels, |p| (p - mean).dot(inverse * (p - mean)) <= 4.0)
    });
    let hull = convex_hull(pixels);
    let quad = largest_polygon(&hull, 4);
    let hexagon = largest_polygon(&hull, 6);
    let quad_fit = coverage(pixels, |p| inside(&quad, p));
    let hexagon_fit = coverage(pixels, |p| inside(&hexagon, p));
    if ellipse >= MIN_FIT && ellipse >= hexagon_fit {
        ShapeGuess::Sphere
    } else if quad_fit >= MIN_FIT || hexagon_fit >= MIN_FIT {
        ShapeGuess::Cube
    } else {
        ShapeGuess::Unknown
    }
}

/// Intersection over union of the pixels and the pixel centres `covers` accepts, over
/// the pixels' bounding box grown by a quarter of its size (an outline larger than the
/// pixels counts against it).
fn coverage(pixels: &[(i64, i64)], covers: impl Fn(DVec2) -> bool) -> f64 {
    let (x0, x1) = min_max(pixels.iter().map(|p| p.0));
    let (y0, y1) = min_max(pixels.iter().map(|p| p.1));
    let (gx, gy) = ((x1 - x0) / 4 + 1, (y1 - y0) / 4 + 1);
    let width = (x1 - x0 + 1 + 2 * gx) as usize;
    let mut mask = vec![false; width * (y1 - y0 + 1 + 2 * gy) as usize];
    let at = |x: i64, y: i64| (y - y0 + gy) as usize * width + (x - x0 + gx) as usize;
    for &(x, y) in pixels {
        mask[at(x, y)] = true;
    }
    let (mut both, mut either) = (0usize, 0usize);
    for y in y0 - gy..=y1 + gy {
        for x in x0 - gx..=x1 + gx {
            let covered = covers(DVec2::new(x as f64 + 0.5, y as f64 + 0.5));
            let set = mask[at(x, y)];
            both += usize::from(covered && set);
            either += usize::from(covered || set);
        }
    }
    both as f64 / either.max(1) as f64
}

fn min_max(values: impl Iterator<Item = i64>) -> (i64, i64) {
    values.fold((i64::MAX, i64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// The ellipse with the second moments of `centres`: a filled ellipse's covariance is a
/// quarter of its semi-axes squared, so it holds the points p with
/// (p - mu)^T C^-1 (p - mu) <= 4. Each pixel adds the variance of a unit square, 1/12,
/// on both axes. `None` for a degenerate one.
fn moment_ellipse(centres: &[DVec2]) -> Option<(DVec2, DMat2)> {
    let n = centres.len() as f64;
    let mean = centres.iter().copied().sum::<DVec2>() / n;
    let mut cov = DMat2::from_diagonal(DVec2::splat(1.0 / 12.0));
    for c in centres {
        let d = *c - mean;
        cov += DMat2::from_cols(d * d.x, d * d.y) * (1.0 / n);
    }
    (cov.determinant() > 0.0).then(|| (mean, cov.inverse()))
}

/// The convex hull (counter-clockwise) of the pixels' corners (Andrew's monotone chain).
fn convex_hull(pixels: &[(i64, i64)]) -> Vec<DVec2> {
    let mut points: Vec<(i64, i64)> = pixels
        .iter()
        .flat_map(|&(x, y)| [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)])
        .collect();
    points.sort_unstable();
    points.dedup();
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut hull: Vec<(i64, i64)> = Vec::new();
    for pass in [
        &points[..],
        &points.iter().rev().copied().collect::<Vec<_>>(),
    ] {
        let start = hull.len();
        for &p in pass.iter() {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop(); // the last point starts the other chain
    }
    hull.into_iter()
        .map(|(x, y)| DVec2::new(x as f64, y as f64))
        .collect()
}

/// Twice the signed area of the triangle (a, b, c).
fn area2(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// The largest-area polygon of at most `k` vertices among the hull's (counter-clockwise),
/// by dynamic programming over fans from each start vertex. Hulls are thinned to 48
/// vertices first: the search is cubic in their number.
fn largest_polygon(hull: &[DVec2], k: usize) -> Vec<DVec2> {
    let step = hull.len().div_ceil(48).max(1);
    let points: Vec<DVec2> = hull.iter().step_by(step).copied().collect();
    let n = points.len();
    if n <= k {
        return points;
    }
    let mut best = (0.0, Vec::new());
    for s in 0..n {
        let at = |i: usize| points[(s + i) % n];
        // area[m][j]: the largest fan s, ..., j with m + 1 vertices; from[m][j] its
        // previous vertex.
        let mut area = vec![vec![f64::NEG_INFINITY; n]; k];
        let mut from = vec![vec![0usize; n]; k];
        area[1][1..].fill(0.0);
        for m in 2..k {
            for j in m..n {
                for i in m - 1..j {
                    let a = area[m - 1][i] + area2(at(0), at(i), at(j));
                    if a > area[m][j] {
                        area[m][j] = a;
                        from[m][j] = i;
                    }
                }
            }
        }
        for (j, &last) in area[k - 1].iter().enumerate().skip(k - 1) {
            if last > best.0 {
                let mut vertices = vec![at(j)];
                let (mut m, mut i) = (k - 1, j);
                while m > 1 {
                    i = from[m][i];
                    m -= 1;
                    vertices.push(at(i));
                }
                vertices.push(at(0));
                vertices.reverse();
                best = (last, vertices);
            }
        }
    }
    best.1
}

/// Whether `point` lies in the convex polygon (counter-clockwise).
fn inside(polygon: &[DVec2], point: DVec2) -> bool {
    polygon.len() >= 3
        && (0..polygon.len()).all(|i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
            area2(a, b, point) >= 0.0
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filled(test: impl Fn(f64, f64) -> bool) -> Vec<(i64, i64)> {
        (0..60)
            .flat_map(|y| (0..60).map(move |x| (x, y)))
            .filter(|&(x, y)| test(x as f64 + 0.5, y as f64 + 0.5))
            .collect()
    }

    #[test]
    fn a_disc_and_an_ellipse_are_spheres() {
        let disc = filled(|x, y| (x - 30.0).powi(2) + (y - 30.0).powi(2) <= 100.0);
        assert_eq!(guess(&disc), ShapeGuess::Sphere);
        let ellipse =
            filled(|x, y| ((x - 30.0) / 20.0).powi(2) + ((y - 25.0) / 9.0).powi(2) <= 1.0);
        assert_eq!(guess(&ellipse), ShapeGuess::Sphere);
    }

    #[test]
    fn a_square_a_turned_quadrilateral_and_a_hexagon_are_cubes() {
        let square = filled(|x, y| (10.0..30.0).contains(&x) && (12.0..40.0).contains(&y));
        assert_eq!(guess(&square), ShapeGuess::Cube);
        // A square turned by 30 degrees.
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        let turned = filled(|x, y| {
            let (u, v) = (x - 30.0, y - 30.0);
            (c * u + s * v).abs() <= 12.0 && (-s * u + c * v).abs() <= 9.0
        });
        assert_eq!(guess(&turned), ShapeGuess::Cube);
        // A cube seen from a corner: a regular hexagon.
        let hexagon = filled(|x, y| {
            let (u, v) = (x - 30.0, y - 30.0);
            (0..3).all(|i| {
                let a = (60.0 * i as f64).to_radians();
                (u * a.cos() + v * a.sin()).abs() <= 15.0
            })
        });
        assert_eq!(guess(&hexagon), ShapeGuess::Cube);
    }

    #[test]
    fn a_ring_a_crescent_and_a_few_pixels_are_unknown() {
        let crescent = filled(|x, y| {
            (x - 30.0).powi(2) + (y - 30.0).powi(2) <= 225.0
                && (x - 38.0).powi(2) + (y - 30.0).powi(2) > 144.0
        });
        assert_eq!(guess(&crescent), ShapeGuess::Unknown);
        let l_shape =
            filled(|x, y| (x < 20.0 && y < 50.0) || ((40.0..50.0).contains(&y) && x < 50.0));
        assert_eq!(guess(&l_shape), ShapeGuess::Unknown);
        assert_eq!(guess(&[(1, 1), (2, 1), (1, 2)]), ShapeGuess::Unknown);
    }
}
