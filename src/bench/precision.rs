//! What double precision costs: the core of the tracer's inner loop (ray to object space,
//! the cancellation-free sphere test, re-projection) written once and compiled for `f32`
//! and for `f64`, timed on the same rays.

use std::hint::black_box;
use std::time::Instant;

use serde::Serialize;

/// Timing of the kernel in both precisions.
#[derive(Clone, Debug, Serialize)]
pub struct PrecisionCost {
    /// Rays timed.
    pub rays: u64,
    /// Nanoseconds per ray in f32.
    pub f32_ns_per_ray: f64,
    /// Nanoseconds per ray in f64.
    pub f64_ns_per_ray: f64,
    /// f64 time over f32 time.
    pub f64_over_f32: f64,
}

/// One kernel per float type: the same source, glam's matching vector and affine types.
macro_rules! sphere_kernel {
    ($name:ident, $float:ty, $vec:ty, $affine:ty) => {
        /// Sums the hit distances of `rays` against `objects` unit spheres.
        fn $name(objects: &[$affine], rays: &[([f64; 3], [f64; 3])]) -> f64 {
            let mut total = 0.0;
            for (origin, dir) in rays {
                let o = <$vec>::new(
                    origin[0] as $float,
                    origin[1] as $float,
                    origin[2] as $float,
                );
                let d = <$vec>::new(dir[0] as $float, dir[1] as $float, dir[2] as $float);
                let mut nearest = <$float>::INFINITY;
                let mut nearest_point = <$vec>::ZERO;
                for object_from_world in objects {
                    let o = object_from_world.transform_point3(o);
                    let d = object_from_world.transform_vector3(d);
                    let a = d.length_squared();
                    let h = o.dot(d);
                    let c = o.length_squared() - 1.0;
                    let closest = o - (h / a) * d;
                    let disc = a * (1.0 - closest.length_squared());
                    if disc < 0.0 {
                        continue;
                    }
                    let q = -(h + disc.sqrt().copysign(h));
                    let (t0, t1) = (q / a, c / q);
                    let t = if t0.min(t1) > 0.0 {
                        t0.min(t1)
                    } else {
                        t0.max(t1)
                    };
                    if t > 0.0 && t < nearest {
                        nearest = t;
                        let p = o + t * d;
                        nearest_point = p / p.length();
                    }
                }
                if nearest.is_finite() {
                    total += f64::from(nearest) + f64::from(nearest_point.x);
                }
            }
            total
        }
    };
}

sphere_kernel!(kernel_f32, f32, glam::Vec3, glam::Affine3A);
sphere_kernel!(kernel_f64, f64, glam::DVec3, glam::DAffine3);

/// Times both kernels on `ray_count` rays against 8 spheres, best of `runs`.
#[must_use]
pub fn precision_cost(ray_count: usize, runs: u32) -> PrecisionCost {
    // Eight spheres in a ring, rays from a camera-like fan: about half of them hit.
    let spheres_f64: Vec<glam::DAffine3> = (0..8)
        .map(|i| {
            let angle = f64::from(i) * std::f64::consts::TAU / 8.0;
            glam::DAffine3::from_scale_rotation_translation(
                glam::DVec3::splat(0.7),
                glam::DQuat::from_rotation_y(angle),
                glam::DVec3::new(3.0 * angle.cos(), 0.0, 3.0 * angle.sin()),
            )
            .inverse()
        })
        .collect();
    let spheres_f32: Vec<glam::Affine3A> = spheres_f64.iter().map(|m| m.as_affine3a()).collect();
    let rays: Vec<([f64; 3], [f64; 3])> = (0..ray_count)
        .map(|i| {
            let u = (i % 1000) as f64 / 1000.0 - 0.5;
            let v = (i / 1000 % 1000) as f64 / 1000.0 - 0.5;
            let dir = glam::DVec3::new(u * 2.0, v, -1.0).normalize();
            ([0.0, 0.5, 8.0], dir.to_array())
        })
        .collect();
    let time = |kernel: &dyn Fn() -> f64| {
        (0..runs.max(1))
            .map(|_| {
                let started = Instant::now();
                black_box(kernel());
                started.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let f32_seconds = time(&|| kernel_f32(black_box(&spheres_f32), black_box(&rays)));
    let f64_seconds = time(&|| kernel_f64(black_box(&spheres_f64), black_box(&rays)));
    let per_ray = |s: f64| s * 1e9 / ray_count as f64;
    PrecisionCost {
        rays: ray_count as u64,
        f32_ns_per_ray: per_ray(f32_seconds),
        f64_ns_per_ray: per_ray(f64_seconds),
        f64_over_f32: f64_seconds / f32_seconds,
    }
}
