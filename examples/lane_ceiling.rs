//! How much SIMD across rays can buy the tracer's exact tests: the unit-sphere test of
//! `raylab::trace::shapes` against the same arithmetic written branch-free over lanes
//! (eight rays at a time in AVX-512, four in AVX2), on rays that stay in the L1 cache
//! as a 16x16 tile's camera rays would.
//!
//! ```sh
//! cargo run --release --example lane_ceiling
//! ```
//!
//! The lane kernel does the operations of `sphere::intersect` (through
//! `unit_ball_roots`, `solve_quadratic` and `in_range`) in the same order, so its hits
//! are the scalar test's bit for bit; the program checks that. A second kernel takes the
//! divisions and square roots out (its answers are wrong; it only shows what they cost).
//! Issue 18 part 1 and docs/BENCHMARKS.md ("The ceiling of SIMD across rays") use it.

#![cfg_attr(not(target_arch = "x86_64"), allow(dead_code, unused_imports))]

use std::hint::black_box;
use std::time::Instant;

use glam::DVec3;
use raylab::trace::Ray;
use raylab::trace::shapes::{self, gamma};

/// Rays per batch: a 16x16 tile's camera rays, twice over.
const RAYS: usize = 512;
/// Batches timed per round, and rounds (the best round counts).
const BATCHES: usize = 4000;
const ROUNDS: usize = 7;

/// A tile's rays, one array per coordinate.
struct Lanes {
    origin: [Vec<f64>; 3],
    dir: [Vec<f64>; 3],
}

/// `gamma(3)` and `gamma(8)` of the error bounds.
struct Gammas {
    three: f64,
    eight: f64,
}

/// One answer per ray: the hit's t and its re-projected point, or NaN for a miss.
type Answers = Vec<[f64; 4]>;

#[cfg(not(target_arch = "x86_64"))]
fn main() {
    println!("lane_ceiling measures x86-64 SIMD: nothing to measure on this target");
}

#[cfg(target_arch = "x86_64")]
fn main() {
    let rays = tile_rays();
    let lanes = Lanes {
        origin: std::array::from_fn(|axis| rays.iter().map(|r| r.origin[axis]).collect()),
        dir: std::array::from_fn(|axis| rays.iter().map(|r| r.dir[axis]).collect()),
    };
    let mut scalar = vec![[0.0; 4]; RAYS];
    let scalar_ns = best_ns(|| {
        for (ray, out) in rays.iter().zip(scalar.iter_mut()) {
            *out = shapes::intersect(shapes::Primitive::Sphere, black_box(ray), f64::INFINITY)
                .map_or([f64::NAN; 4], |hit| [hit.t, hit.p.x, hit.p.y, hit.p.z]);
        }
    });
    let hits = scalar.iter().filter(|a| !a[0].is_nan()).count();
    println!(
        "{RAYS} rays from one eye against a unit sphere, {hits} hits; ns per ray, best of {ROUNDS}:"
    );
    println!("  scalar `shapes::intersect` (branches, calls):   {scalar_ns:6.2}");
    let mut out = vec![[0.0; 4]; RAYS];
    let plain_ns = best_ns(|| exact_plain(&lanes, &mut out));
    report("lanes, baseline x86-64 (SSE2)", plain_ns, &out, &scalar);
    if is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2 (checked just above).
        let ns = best_ns(|| unsafe { exact_avx2(&lanes, &mut out) });
        report("lanes, AVX2 (4 lanes)", ns, &out, &scalar);
    }
    if is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512dq") {
        // SAFETY: the CPU has AVX-512F and DQ (checked just above).
        let ns = best_ns(|| unsafe { exact_avx512(&lanes, &mut out) });
        report("lanes, AVX-512 (8 lanes)", ns, &out, &scalar);
        // SAFETY: as above.
        let ns = best_ns(|| unsafe { no_divisions_avx512(&lanes, &mut out) });
        println!(
            "  lanes, AVX-512, divisions and roots taken out: {ns:6.2}  (wrong answers: cost only)"
        );
    }
}

/// Rays from one eye through a 16x32 grid around the sphere (as a camera tile's), in the
/// sphere's object space.
fn tile_rays() -> Vec<Ray> {
    let eye = DVec3::new(0.3, 0.4, -5.0);
    (0..RAYS)
        .map(|i| {
            let (u, v) = ((i % 16) as f64 / 15.0, (i / 16) as f64 / 31.0);
            let target = DVec3::new(-1.0 + 2.0 * u, -1.0 + 2.0 * v, 0.0);
            Ray::new(eye, (target - eye).normalize())
        })
        .collect()
}

fn report(name: &str, ns: f64, out: &Answers, scalar: &Answers) {
    let same = out
        .iter()
        .zip(scalar)
        .all(|(a, b)| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits()));
    println!("  {name:<46} {ns:6.2}  (bit for bit the scalar answers: {same})");
}

/// Runs `work` (one batch of RAYS rays) BATCHES times per round; the best round's time
/// per ray.
fn best_ns(mut work: impl FnMut()) -> f64 {
    (0..ROUNDS)
        .map(|_| {
            let started = Instant::now();
            for _ in 0..BATCHES {
                work();
            }
            started.elapsed().as_secs_f64() * 1e9 / (BATCHES * RAYS) as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn exact_plain(lanes: &Lanes, out: &mut Answers) {
    each_ray::<true>(lanes, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn exact_avx2(lanes: &Lanes, out: &mut Answers) {
    each_ray::<true>(lanes, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl")]
unsafe fn exact_avx512(lanes: &Lanes, out: &mut Answers) {
    each_ray::<true>(lanes, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl")]
unsafe fn no_divisions_avx512(lanes: &Lanes, out: &mut Answers) {
    each_ray::<false>(lanes, out);
}

/// The loop the compiler turns into lanes: straight-line arithmetic per ray, no branch.
/// (The kernel is named, not passed: a closure's call is not inlined into the
/// target-feature functions, and the loop then stays scalar.)
#[inline(always)]
fn each_ray<const EXACT: bool>(lanes: &Lanes, out: &mut Answers) {
    // gamma() is a call into the library: worked out once, not per lane.
    let gammas = Gammas {
        three: gamma(3),
        eight: gamma(8),
    };
    let [ox, oy, oz] = &lanes.origin;
    let [dx, dy, dz] = &lanes.dir;
    let n = out.len();
    let (ox, oy, oz, dx, dy, dz) = (&ox[..n], &oy[..n], &oz[..n], &dx[..n], &dy[..n], &dz[..n]);
    for i in 0..n {
        let (o, d) = ([ox[i], oy[i], oz[i]], [dx[i], dy[i], dz[i]]);
        out[i] = if EXACT {
            sphere_lane(o, d, &gammas)
        } else {
            sphere_lane_without_divisions(o, d, &gammas)
        };
    }
}

#[inline(always)]
fn pick(take_a: bool, a: f64, b: f64) -> f64 {
    if take_a { a } else { b }
}

#[inline(always)]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `sphere::intersect` branch-free: every case worked out, the right one picked.
#[inline(always)]
fn sphere_lane(o: [f64; 3], d: [f64; 3], gammas: &Gammas) -> [f64; 4] {
    let a = dot(d, d);
    let h = dot(o, d);
    let c = dot(o, o) - 1.0;
    // An origin on the boundary: the roots 0 and -2h/a.
    let on_boundary = c.abs() <= gammas.three * (c + 1.0);
    let linear = -2.0 * h / a;
    let boundary = [
        pick(0.0 <= linear, 0.0, linear),
        pick(0.0 <= linear, linear, 0.0),
    ];
    // Otherwise the cancellation-free discriminant and q = -(h + sign(h) sqrt(disc)).
    let s = h / a;
    let closest = [o[0] - d[0] * s, o[1] - d[1] * s, o[2] - d[2] * s];
    let disc = a * (1.0 - dot(closest, closest));
    let q = -(h + disc.sqrt().copysign(h));
    let (r0, r1) = (q / a, c / q);
    let general = [pick(r0 <= r1, r0, r1), pick(r0 <= r1, r1, r0)];
    let general = pick_pair(q == 0.0, [0.0, 0.0], general);
    let [t0, t1] = pick_pair(on_boundary, boundary, general);
    let real = a != 0.0 && (on_boundary || !(disc < 0.0 || disc.is_nan()));
    // in_range: past the origin's own rounding, before t_max (infinite here).
    let origin_rounding = gammas.eight * o[0].abs().max(o[1].abs()).max(o[2].abs()).max(1.0);
    let floor = origin_rounding * origin_rounding;
    let in0 = t0 > 0.0 && t0 < f64::INFINITY && t0 * t0 * a > floor;
    let in1 = t1 > 0.0 && t1 < f64::INFINITY && t1 * t1 * a > floor;
    let t = pick(in0, t0, t1);
    let p = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
    let length = dot(p, p).sqrt();
    let hit = real && (in0 || in1);
    [
        pick(hit, t, f64::NAN),
        pick(hit, p[0] / length, f64::NAN),
        pick(hit, p[1] / length, f64::NAN),
        pick(hit, p[2] / length, f64::NAN),
    ]
}

#[inline(always)]
fn pick_pair(take_a: bool, a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [pick(take_a, a[0], b[0]), pick(take_a, a[1], b[1])]
}

/// [`sphere_lane`] with each division a multiplication and each root left out.
#[inline(always)]
fn sphere_lane_without_divisions(o: [f64; 3], d: [f64; 3], gammas: &Gammas) -> [f64; 4] {
    let a = dot(d, d);
    let h = dot(o, d);
    let c = dot(o, o) - 1.0;
    let s = h * a;
    let closest = [o[0] - d[0] * s, o[1] - d[1] * s, o[2] - d[2] * s];
    let disc = a * (1.0 - dot(closest, closest));
    let q = -(h + disc.copysign(h));
    let (r0, r1) = (q * a, c * q);
    let (t0, t1) = (pick(r0 <= r1, r0, r1), pick(r0 <= r1, r1, r0));
    let in0 = t0 > 0.0 && t0 * t0 * a > gammas.eight;
    let t = pick(in0, t0, t1);
    let p = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
    let length = dot(p, p);
    let hit = disc >= 0.0 && (in0 || t1 > 0.0);
    [
        pick(hit, t, f64::NAN),
        pick(hit, p[0] * length, f64::NAN),
        pick(hit, p[1] * length, f64::NAN),
        pick(hit, p[2] * length, f64::NAN),
    ]
}
