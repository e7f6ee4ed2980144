//! A second implementation of the lighting model, for the comparison tests only, with
//! switches for the ways real tracers go wrong. Unperturbed it writes raylab's bytes
//! (checked by a test), so every difference a test sees is the bug it switched on.
#![allow(dead_code)]

use glam::{DVec2, DVec3};
use raylab::compare::OtherImage;
use raylab::scene::{Light, Scene};
use raylab::trace::sample_in_pixel;
use raylab::trace::shapes::Primitive;
use raylab::trace::{PinholeCamera, Ray, SurfacePoint, World, WorldLight};
use raylab::trace::{spawn_ray, spawn_ray_to};

/// The bugs to switch on; the default is none.
#[derive(Clone, Debug, Default)]
pub struct Bugs {
    /// Scene index of a light left out.
    pub drop_light: Option<usize>,
    /// An object whose diffuse colour is scaled, and by how much.
    pub diffuse_scale: Option<(usize, f64)>,
    /// No specular term.
    pub specular_off: bool,
    /// No shadow rays.
    pub shadows_off: bool,
    /// `r = l - 2 (n.l) n`.
    pub negated_reflection: bool,
    /// `r = 2 (n.l) (n - l)`.
    pub n_minus_l: bool,
    /// Cone side normals lose their object-space z component.
    pub cone_normal_without_z: bool,
    /// An object (scene index) whose normal is left in object space: not taken to the
    /// world by the normal matrix (a bug the catalogue does not know).
    pub normal_in_object_space: Option<usize>,
    /// Each ray's local colour clamped before the reflection is added.
    pub clamp_before_reflection: bool,
    /// Planes cannot be hit from behind.
    pub one_sided_planes: bool,
    /// Directional lights add nothing.
    pub directional_never_lights: bool,
    /// Write floor(255 c) instead of round(255 c).
    pub truncate: bool,
    /// Scene index of a spot light whose strength does not fall off as 1/d^2.
    pub spot_no_falloff: Option<usize>,
    /// No ambient term.
    pub ambient_off: bool,
    /// Mirrors blended as the course skeleton does: `(1 - km) local + km reflected`.
    pub mirror_blend: bool,
    /// Every spot light lit as a point light whose strength does not fall off: no cone
    /// test and no division by d^2.
    pub spots_without_cone_or_falloff: bool,
    /// The shadow ray never meets the object it leaves (a tracer that skips it).
    pub no_self_shadow: bool,
    /// The mirror ray starts at `p - 1e-4 n`, under the surface it leaves.
    pub mirror_wrong_side: bool,
    /// Each reflected ray's colour is kept as bytes: `floor(255 c) / 255` per channel.
    pub truncate_each_ray: bool,
}

struct Shader<'a> {
    scene: &'a Scene,
    world: World,
    bugs: &'a Bugs,
}

impl Shader<'_> {
    fn intersect(&self, ray: &Ray) -> Option<SurfacePoint> {
        let mut ray = *ray;
        loop {
            let hit = self.world.intersect(&ray, f64::INFINITY)?;
            let plane = self.world.objects[hit.object].shape == Primitive::Plane;
            if self.bugs.one_sided_planes && plane && hit.n_outward.dot(ray.dir) > 0.0 {
                ray = spawn_ray(&hit, ray.dir); // through the plane's back, as if not there
                continue;
            }
            return Some(hit);
        }
    }

    fn normal(&self, hit: &SurfacePoint, dir: DVec3) -> DVec3 {
        let object = &self.world.objects[hit.object];
        if self.bugs.normal_in_object_space == Some(hit.object) {
            let n = (object.world_from_object.matrix3.transpose() * hit.n_outward).normalize();
            return if n.dot(dir) > 0.0 { -n } else { n };
        }
        if !(self.bugs.cone_normal_without_z && object.shape == Primitive::Cone) {
            return hit.n;
        }
        let mut n_object =
            (object.world_from_object.matrix3.transpose() * hit.n_outward).normalize();
        if n_object.z > 0.9 {
            return hit.n; // the cap is right
        }
        n_object.z = 0.0;
        let n = (object.normal_from_object * n_object).normalize();
        if n.dot(dir) > 0.0 { -n } else { n }
    }

    fn visible(&self, hit: &SurfacePoint, to_light: DVec3, position: Option<DVec3>) -> bool {
        if self.bugs.shadows_off {
            return true;
        }
        let plane = self.world.objects[hit.object].shape == Primitive::Plane;
        let leaves_outward = plane || hit.n_outward.dot(to_light) > 0.0;
        let except = (leaves_outward || self.bugs.no_self_shadow).then_some(hit.object);
        match position {
            Some(p) => {
                let (ray, t_max) = spawn_ray_to(hit, p);
                self.world.occluder_except(&ray, t_max, except).is_none()
            }
            None => self
                .world
                .occluder_except(&spawn_ray(hit, to_light), f64::INFINITY, except)
                .is_none(),
        }
    }

    fn radiance(&self, ray: &Ray, depth: u32) -> DVec3 {
        let Some(hit) = self.intersect(ray) else {
            return self.world.background;
        };
        let material = &self.world.materials[self.world.objects[hit.object].material];
        let n = self.normal(&hit, ray.dir);
        let mut colour = if self.bugs.ambient_off {
            DVec3::ZERO
        } else {
            material.ambient * self.world.ambient
        };
        let kd = match self.bugs.diffuse_scale {
            Some((object, scale)) if object == hit.object => material.diffuse * scale,
            _ => material.diffuse,
        };
        let view = -ray.dir;
        for (index, light) in self.world.lights.iter().enumerate() {
            let scene_index = self.world.light_scene_index[index];
            let directional = matches!(self.scene.lights[scene_index], Light::Directional { .. });
            if self.bugs.drop_light == Some(scene_index)
                || (self.bugs.directional_never_lights && directional)
            {
                continue;
            }
            let bare = match *light {
                WorldLight::Spot {
                    position, strength, ..
                } if self.bugs.spots_without_cone_or_falloff => {
                    WorldLight::Point { position, strength }
                        .sample(hit.p)
                        .map(|mut s| {
                            s.radiance = strength;
                            s
                        })
                }
                _ => None,
            };
            let Some(mut sample) = bare.or_else(|| light.sample(hit.p)) else {
                continue;
            };
            if self.bugs.spot_no_falloff == Some(scene_index) {
                sample.radiance = light.strength();
            }
            let n_dot_l = n.dot(sample.to_light);
            if n_dot_l <= 0.0 || !self.visible(&hit, sample.to_light, sample.light_position) {
                continue;
            }
            let diffuse = kd * sample.radiance * n_dot_l;
            let r = if self.bugs.negated_reflection {
                sample.to_light - 2.0 * n_dot_l * n
            } else if self.bugs.n_minus_l {
                2.0 * n_dot_l * (n - sample.to_light)
            } else {
                2.0 * n_dot_l * n - sample.to_light
            };
            let r_dot_v = r.dot(view).max(0.0);
            let mut specular = DVec3::ZERO;
            if r_dot_v > 0.0 && !self.bugs.specular_off {
                let s = material.shininess;
                let lobe = if s.fract() == 0.0 && s <= 1024.0 {
                    r_dot_v.powi(s as i32)
                } else {
                    r_dot_v.powf(s)
                };
                specular = material.specular * sample.radiance * lobe;
            }
            colour += diffuse + specular;
        }
        if self.bugs.clamp_before_reflection {
            colour = colour.clamp(DVec3::ZERO, DVec3::ONE);
        }
        if depth < self.world.max_depth && material.mirror != DVec3::ZERO {
            let d = ray.dir;
            let dir = d - 2.0 * d.dot(hit.n) * hit.n;
            let reflected = if self.bugs.mirror_wrong_side {
                Ray::new(hit.p - 1e-4 * hit.n, dir)
            } else {
                spawn_ray(&hit, dir)
            };
            let km = material.mirror;
            if self.bugs.mirror_blend {
                colour *= DVec3::ONE - km;
            }
            colour += km * self.radiance(&reflected, depth + 1);
        }
        if self.bugs.truncate_each_ray && depth > 0 {
            colour = (colour.clamp(DVec3::ZERO, DVec3::ONE) * 255.0).floor() / 255.0;
        }
        colour
    }
}

/// The scene rendered with `bugs` at its own size and `spp`, written as 8-bit RGB.
pub fn render(scene: &Scene, spp: u32, bugs: &Bugs) -> OtherImage {
    let shader = Shader {
        scene,
        world: World::new(scene).unwrap(),
        bugs,
    };
    let (w, h) = (scene.camera.width, scene.camera.height);
    let camera = PinholeCamera::new(&scene.camera, w, h);
    let mut rgb = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = DVec3::ZERO;
            for i in 0..spp {
                let point = DVec2::new(f64::from(x), f64::from(y)) + sample_in_pixel(x, y, i, spp);
                sum += shader.radiance(&camera.ray(point), 0);
            }
            let c = (sum * (1.0 / f64::from(spp))).as_vec3();
            rgb.push(c.to_array().map(|v| {
                let v = v.clamp(0.0, 1.0) * 255.0;
                (if bugs.truncate { v.floor() } else { v.round() }) as u8
            }));
        }
    }
    OtherImage::new(w, h, rgb)
}

/// The comparison tests' scene.
pub fn lab_scene() -> Scene {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/compare/lab.ron");
    raylab::scene::load_scene(std::path::Path::new(path)).unwrap()
}
