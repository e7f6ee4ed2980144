//! Checks that a parsed scene describes something renderable, with a message that names
//! the offending field.

use glam::DVec3;

mod failure;
mod objects;

use super::error::SceneError;
use super::light::{Light, LightSource};
use super::model::{Camera, Material, RenderSettings, Scene};
use failure::{invalid, prefixed};

/// The largest accepted image width or height, in pixels.
pub const MAX_IMAGE_SIDE: u32 = 16384;
/// The largest accepted number of samples per pixel.
pub const MAX_SAMPLES_PER_PIXEL: u32 = 65536;
/// The largest accepted mirror depth (`render.max_depth`). The tracer follows a mirror
/// chain in a loop, so depth costs no stack; the limit only bounds the time one pixel can
/// take between two facing mirrors. It is ten times the 1000 the contract asks a renderer
/// to handle; legacy files asking for more are imported at this depth, with a warning.
pub const MAX_DEPTH: u32 = 10_000;
/// The widest spot light: a half-angle of 180 degrees lights every direction. Half-angles
/// are in (0, `MAX_SPOT_ANGLE_DEG`].
pub const MAX_SPOT_ANGLE_DEG: f64 = 180.0;
/// The largest accepted index of refraction: above every real material (diamond is
/// about 2.4), low enough that Snell's law stays well conditioned.
pub const MAX_IOR: f64 = 10.0;
/// The most shadow rays a sphere light may ask for per shading point.
pub const MAX_LIGHT_SAMPLES: u32 = 1024;
pub use objects::MAX_TREE_DEPTH;

/// Checks every rule of the contract that parsing alone does not enforce.
///
/// # Errors
/// The first problem found, as [`SceneError::Invalid`] naming the field.
pub fn validate(scene: &Scene) -> Result<(), SceneError> {
    if scene.format != super::model::FORMAT_VERSION {
        return invalid(format!(
            "format {} is not supported (this raylab reads format 1)",
            scene.format
        ));
    }
    check_camera(&scene.camera)?;
    check_render(&scene.render)?;
    for (name, material) in &scene.materials {
        check_material(material).map_err(|e| prefixed(&format!("material \"{name}\""), e))?;
    }
    objects::check_objects(&scene.objects, &scene.materials)?;
    for (index, light) in scene.lights.iter().enumerate() {
        check_light(light)
            .and_then(|()| check_light_strength(light))
            .map_err(|e| prefixed(&format!("lights[{index}] ({})", light.kind_name()), e))?;
    }
    Ok(())
}

fn finite(field: &str, value: f64) -> Result<(), SceneError> {
    if value.is_finite() {
        Ok(())
    } else {
        invalid(format!("{field} is {value}, not a finite number"))
    }
}

fn finite_vec(field: &str, value: DVec3) -> Result<(), SceneError> {
    if value.is_finite() {
        Ok(())
    } else {
        invalid(format!("{field} is {value}, which is not finite"))
    }
}

fn non_negative_colour(field: &str, value: DVec3) -> Result<(), SceneError> {
    finite_vec(field, value)?;
    if value.min_element() < 0.0 {
        return invalid(format!("{field} is {value}; colours cannot be negative"));
    }
    Ok(())
}

fn check_camera(camera: &Camera) -> Result<(), SceneError> {
    let at = |field: &str| format!("camera.{field}");
    finite_vec(&at("position"), camera.position)?;
    finite_vec(&at("look_at"), camera.look_at)?;
    finite_vec(&at("up"), camera.up)?;
    finite(&at("fov_deg"), camera.fov_deg)?;
    for (field, side) in [("width", camera.width), ("height", camera.height)] {
        if side == 0 || side > MAX_IMAGE_SIDE {
            return invalid(format!(
                "{} is {side}; it must be between 1 and {MAX_IMAGE_SIDE} pixels",
                at(field)
            ));
        }
    }
    if !(camera.fov_deg > 0.0 && camera.fov_deg < 180.0) {
        return invalid(format!(
            "camera.fov_deg is {}; the vertical field of view must be between 0 and 180 degrees",
            camera.fov_deg
        ));
    }
    let forward = camera.look_at - camera.position;
    if forward.length_squared() == 0.0 || !forward.length_squared().is_finite() {
        return invalid(
            "camera.look_at equals camera.position, so there is no view direction".into(),
        );
    }
    if forward
        .normalize()
        .cross(camera.up.normalize_or_zero())
        .length_squared()
        < 1e-20
    {
        return invalid(format!(
            "camera.up {} is zero or parallel to the view direction",
            camera.up
        ));
    }
    Ok(())
}

fn check_render(render: &RenderSettings) -> Result<(), SceneError> {
    non_negative_colour("render.background", render.background)?;
    if render.samples_per_pixel == 0 || render.samples_per_pixel > MAX_SAMPLES_PER_PIXEL {
        return invalid(format!(
            "render.samples_per_pixel is {}; it must be between 1 and {MAX_SAMPLES_PER_PIXEL}",
            render.samples_per_pixel
        ));
    }
    if render.max_depth > MAX_DEPTH {
        return invalid(format!(
            "render.max_depth is {}; at most {MAX_DEPTH} mirror bounces are supported",
            render.max_depth
        ));
    }
    Ok(())
}

fn check_material(material: &Material) -> Result<(), SceneError> {
    non_negative_colour("ambient", material.ambient)?;
    non_negative_colour("diffuse", material.diffuse)?;
    non_negative_colour("specular", material.specular)?;
    non_negative_colour("mirror", material.mirror)?;
    non_negative_colour("transmission", material.transmission)?;
    finite("ior", material.ior)?;
    if !(material.ior > 0.0 && material.ior <= MAX_IOR) {
        return invalid(format!(
            "ior is {}; an index of refraction must be in (0, {MAX_IOR}]",
            material.ior
        ));
    }
    finite("shininess", material.shininess)?;
    // 0 is allowed: max(0, r.v)^0 is 1 where r.v > 0 and 0 elsewhere.
    if material.shininess < 0.0 {
        return invalid(format!(
            "shininess is {}; the Phong exponent cannot be negative",
            material.shininess
        ));
    }
    Ok(())
}

/// Each field checked once, whichever kinds hold it, in the order a Spot lists them.
fn check_light(light: &Light) -> Result<(), SceneError> {
    non_negative_colour("colour", light.colour())?;
    check_intensity(light.intensity())?;
    if let Light::Point { position, .. } | Light::Spot { position, .. } = *light {
        finite_vec("position", position)?;
    }
    if let Light::Directional { direction, .. } | Light::Spot { direction, .. } = *light {
        check_direction(direction)?;
    }
    if let Light::Spot { angle_deg, .. } = *light {
        finite("angle_deg", angle_deg)?;
        if !(angle_deg > 0.0 && angle_deg <= MAX_SPOT_ANGLE_DEG) {
            return invalid(format!(
                "angle_deg is {angle_deg}; a spot light's half-angle must be in \
                 (0, {MAX_SPOT_ANGLE_DEG}] degrees"
            ));
        }
    }
    match *light {
        Light::Point { source, .. } | Light::Spot { source, .. } => check_sphere(source),
        Light::Ambient { .. } | Light::Directional { .. } => Ok(()),
    }
}

/// A sphere light's radius and shadow-ray count (both ignored on a point).
fn check_sphere(source: LightSource) -> Result<(), SceneError> {
    let LightSource {
        radius, samples, ..
    } = source;
    finite("radius", radius)?;
    if radius < 0.0 {
        return invalid(format!("radius is {radius}; it cannot be negative"));
    }
    if samples == 0 || samples > MAX_LIGHT_SAMPLES {
        return invalid(format!(
            "samples is {samples}; a light takes 1 to {MAX_LIGHT_SAMPLES} shadow rays"
        ));
    }
    Ok(())
}

fn check_direction(direction: DVec3) -> Result<(), SceneError> {
    finite_vec("direction", direction)?;
    if direction.length_squared() == 0.0 || !direction.length_squared().is_normal() {
        return invalid(format!(
            "direction {direction} is zero (or too short to normalise)"
        ));
    }
    Ok(())
}

fn check_intensity(intensity: f64) -> Result<(), SceneError> {
    finite("intensity", intensity)?;
    if intensity < 0.0 {
        return invalid(format!("intensity is {intensity}; it cannot be negative"));
    }
    Ok(())
}

/// A light whose colour and intensity are each finite can still have a product that is
/// not: it would shade to infinity or NaN (and black pixels), so it is refused by name.
fn check_light_strength(light: &Light) -> Result<(), SceneError> {
    let strength = light.strength();
    if strength.is_finite() {
        return Ok(());
    }
    invalid(format!(
        "colour {} * intensity {} overflows to {strength}; lower one of them",
        light.colour(),
        light.intensity()
    ))
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::check_light;
    use crate::scene::{Light, LightSource};

    /// Why `light` is refused, or a panic where it passes.
    fn refusal(light: &Light) -> String {
        check_light(light).expect_err("refused").to_string()
    }

    #[test]
    fn each_light_field_is_checked_on_every_kind_that_holds_it_in_file_order() {
        let nan = DVec3::new(0.0, f64::NAN, 0.0);
        let source = LightSource::point(DVec3::ONE, 1.0);
        let spot = |position, direction, angle_deg, source| Light::Spot {
            position,
            direction,
            angle_deg,
            source,
        };
        let wide = LightSource {
            radius: -1.0,
            ..source
        };
        let down = -DVec3::Y;
        for (light, field) in [
            (
                Light::Point {
                    position: nan,
                    source,
                },
                "position",
            ),
            (spot(nan, DVec3::ZERO, 0.0, wide), "position"),
            (spot(DVec3::ZERO, DVec3::ZERO, 0.0, wide), "direction"),
            (spot(DVec3::ZERO, down, 0.0, wide), "angle_deg"),
            (spot(DVec3::ZERO, down, 20.0, wide), "radius"),
            (
                Light::Point {
                    position: DVec3::ZERO,
                    source: wide,
                },
                "radius",
            ),
            (
                Light::Directional {
                    direction: DVec3::ZERO,
                    colour: DVec3::ONE,
                    intensity: 1.0,
                },
                "direction",
            ),
        ] {
            let message = refusal(&light);
            assert!(message.contains(field), "{light:?}: {message}");
        }
        assert!(check_light(&spot(DVec3::ZERO, down, 20.0, source)).is_ok());
    }
}
