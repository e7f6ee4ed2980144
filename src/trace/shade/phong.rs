//! The contract's local terms for one light at one point: Lambert's diffuse term and the
//! Phong lobe. The shader and the compare module's models of other tracers share them,
//! so a model of a bug differs from the tracer only where the bug does.

use glam::DVec3;

/// One light at one point, as the local terms need it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalLight {
    /// The shading normal (facing the ray).
    pub n: DVec3,
    /// Unit vector to the light.
    pub to_light: DVec3,
    /// Unit vector to the viewer (minus the ray direction).
    pub view: DVec3,
    /// L_l(p).
    pub strength: DVec3,
}

impl LocalLight {
    /// `kd * L * n.l`, for a light with `n_dot_l = n.l > 0`.
    #[inline]
    #[must_use]
    pub fn diffuse(&self, kd: DVec3, n_dot_l: f64) -> DVec3 {
        diffuse_term(kd, self.strength, n_dot_l)
    }

    /// `ks * L * max(0, r.v)^s`, with r the light direction reflected about n (max before
    /// the power), for a light with `n_dot_l = n.l > 0`.
    #[inline]
    #[must_use]
    pub fn specular(&self, ks: DVec3, shininess: f64, n_dot_l: f64) -> DVec3 {
        specular_term(ks, self.strength, self.specular_lobe(shininess, n_dot_l))
    }

    /// `max(0, r.v)^s`, or `None` where `r.v <= 0` (no specular term at all), for a light
    /// with `n_dot_l = n.l > 0`: all of the specular term that depends on where the
    /// point, the light and the viewer are.
    #[inline]
    #[must_use]
    pub fn specular_lobe(&self, shininess: f64, n_dot_l: f64) -> Option<f64> {
        let r = 2.0 * n_dot_l * self.n - self.to_light;
        let r_dot_v = r.dot(self.view).max(0.0);
        (r_dot_v > 0.0).then(|| phong_power(r_dot_v, shininess))
    }
}

/// `kd * L * n.l`: the diffuse term from a light of strength `strength` at the point.
#[inline]
#[must_use]
pub fn diffuse_term(kd: DVec3, strength: DVec3, n_dot_l: f64) -> DVec3 {
    kd * strength * n_dot_l
}

/// `ks * L * lobe`, zero without a lobe ([`LocalLight::specular_lobe`]).
#[inline]
#[must_use]
pub fn specular_term(ks: DVec3, strength: DVec3, lobe: Option<f64>) -> DVec3 {
    match lobe {
        Some(lobe) => ks * strength * lobe,
        None => DVec3::ZERO,
    }
}

/// vis_l of a sphere light: the share of its `rays` shadow rays, `clear` of which reached
/// it (1 or 0 for a point light's one ray).
#[inline]
#[must_use]
pub fn visible_fraction(clear: u32, rays: u32) -> f64 {
    f64::from(clear) / f64::from(rays)
}

/// The diffuse and specular terms of a light the point sees `fraction` of (a sphere light
/// partly hidden; a point light is all or nothing, and a whole light is left as it is).
#[inline]
#[must_use]
pub fn seen_terms(fraction: f64, diffuse: DVec3, specular: DVec3) -> (DVec3, DVec3) {
    if fraction < 1.0 {
        (diffuse * fraction, specular * fraction)
    } else {
        (diffuse, specular)
    }
}

/// `x^s` for the Phong lobe; whole exponents (the usual case) by repeated squaring.
#[inline]
#[must_use]
pub fn phong_power(x: f64, s: f64) -> f64 {
    if s.fract() == 0.0 && s <= 1024.0 {
        x.powi(s as i32)
    } else {
        x.powf(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mirror_aligned_viewer_sees_the_whole_lobe_and_shininess_zero_is_a_step() {
        let light = LocalLight {
            n: DVec3::Z,
            to_light: DVec3::Z,
            view: DVec3::Z,
            strength: DVec3::splat(2.0),
        };
        assert_eq!(light.diffuse(DVec3::splat(0.5), 1.0), DVec3::ONE);
        assert_eq!(light.specular(DVec3::ONE, 50.0, 1.0), DVec3::splat(2.0));
        let grazing = LocalLight {
            view: DVec3::new(1.0, 0.0, 0.0),
            ..light
        };
        assert_eq!(
            grazing.specular(DVec3::ONE, 0.0, 1.0),
            DVec3::ZERO,
            "r.v = 0"
        );
        let tilted = LocalLight {
            view: DVec3::new(0.6, 0.0, 0.8),
            ..light
        };
        assert_eq!(
            tilted.specular(DVec3::ONE, 0.0, 1.0),
            DVec3::splat(2.0),
            "x^0 = 1"
        );
        assert!((phong_power(0.8, 2.5) - 0.8f64.powf(2.5)).abs() < 1e-15);
    }
}
