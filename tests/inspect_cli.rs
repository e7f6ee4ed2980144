//! `raylab inspect`: the JSON record of a pixel on a scene with known answers (a mirror
//! bounce that hits a known object, a shadow ray blocked by a known object, a light
//! outside its spot cone, a miss), the readable tree, and a pixel outside the image.

mod common;
mod known_scenes;

use std::path::PathBuf;
use std::process::{Command, Output};

use glam::DVec3;
use known_scenes::mirror_scene;
use raylab::scene::{Scene, save_scene};
use raylab::trace::{RenderOptions, RenderProgress, World, render};
use serde_json::Value;

fn scene_file(name: &str, scene: &Scene) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-inspect-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    save_scene(scene, &path).unwrap();
    path
}

fn raylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raylab"))
        .args(args)
        .output()
        .unwrap()
}

fn inspect_json(path: &std::path::Path, pixel: &str) -> Value {
    let out = raylab(&[
        "inspect",
        path.to_str().unwrap(),
        "--pixel",
        pixel,
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

fn vec3(value: &Value) -> DVec3 {
    let a: Vec<f64> = value
        .as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    DVec3::new(a[0], a[1], a[2])
}

fn close(value: &Value, expected: DVec3) -> bool {
    (vec3(value) - expected).length() < 1e-9
}

#[test]
fn the_mirror_bounce_and_the_blocked_shadow_ray_hit_the_known_objects() {
    let scene = mirror_scene();
    let path = scene_file("mirror.ron", &scene);
    let json = inspect_json(&path, "16,16");
    assert_eq!(json["pixel"], serde_json::json!([16, 16]));
    let rays = json["rays"].as_array().unwrap();
    let kinds: Vec<(&str, u64)> = rays
        .iter()
        .map(|r| (r["kind"].as_str().unwrap(), r["depth"].as_u64().unwrap()))
        .collect();
    // The centre ray hits the mirror; its shadow ray to the point light; the bounce hits
    // the target, whose side facing the mirror has the light behind it: no shadow ray.
    assert_eq!(
        kinds,
        vec![("primary", 0), ("shadow", 0), ("reflection", 1)]
    );

    let primary = &rays[0];
    assert!(close(&primary["origin"], scene.camera.position));
    assert!(
        close(&primary["direction"], -DVec3::Z),
        "the exact view direction"
    );
    assert!((primary["t"].as_f64().unwrap() - 5.0).abs() < 1e-9);
    assert_eq!(primary["hit"]["object"], "mirror");
    assert!(close(&primary["hit"]["point"], DVec3::ZERO));
    assert!(close(&primary["hit"]["normal"], DVec3::Z));
    assert_eq!(primary["light"], Value::Null);
    assert_eq!(primary["blocked_by"], Value::Null);

    let shadow = &rays[1];
    assert_eq!(
        shadow["light"], 1,
        "the point light's index in the scene's list"
    );
    assert_eq!(shadow["blocked_by"], "target");
    assert_eq!(shadow["hit"]["object"], "target");
    assert!(close(&shadow["hit"]["point"], DVec3::new(0.0, 0.0, 7.0)));
    assert!((shadow["t"].as_f64().unwrap() - 7.0).abs() < 1e-9);
    assert!(
        (shadow["t_max"].as_f64().unwrap() - 20.0).abs() < 1e-6,
        "it looked to the light"
    );
    assert!(close(&shadow["direction"], DVec3::Z));

    let bounce = &rays[2];
    assert!(close(&bounce["direction"], DVec3::Z));
    assert_eq!(bounce["hit"]["object"], "target");
    assert!(close(&bounce["hit"]["point"], DVec3::new(0.0, 0.0, 7.0)));
    assert!(close(&bounce["hit"]["normal"], -DVec3::Z));
    assert!((bounce["t"].as_f64().unwrap() - 7.0).abs() < 1e-9);

    let outcomes: Vec<(u64, u64, &str)> = json["lights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            (
                l["depth"].as_u64().unwrap(),
                l["light"].as_u64().unwrap(),
                l["outcome"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        outcomes,
        vec![
            (0, 1, "shadowed by target"),
            (0, 2, "outside the spot cone"),
            (1, 1, "behind the surface"),
            (1, 2, "outside the spot cone"),
        ]
    );

    // One record: the colour is the rendered pixel's.
    let world = World::new(&scene).unwrap();
    let (image, _) = render(
        &world,
        &RenderOptions::from_scene(&scene),
        &RenderProgress::default(),
    )
    .unwrap();
    let unclamped = vec3(&json["unclamped"]);
    assert_eq!(unclamped.as_vec3(), image.get(16, 16));
    assert_eq!(
        vec3(&json["colour"]),
        unclamped.clamp(DVec3::ZERO, DVec3::ONE)
    );
}

#[test]
fn a_miss_is_one_primary_ray_that_meets_nothing() {
    let path = scene_file("miss.ron", &mirror_scene());
    let json = inspect_json(&path, "0,0");
    let rays = json["rays"].as_array().unwrap();
    assert_eq!(rays.len(), 1, "{rays:?}");
    assert_eq!(rays[0]["kind"], "primary");
    assert_eq!(rays[0]["t"], Value::Null);
    assert_eq!(rays[0]["hit"], Value::Null);
    assert!(
        close(&json["colour"], DVec3::new(0.1, 0.2, 0.3)),
        "the background"
    );
    assert!(json["lights"].as_array().unwrap().is_empty());
}

#[test]
fn the_tree_tells_the_same_story_and_a_pixel_outside_is_a_clear_error() {
    let path = scene_file("tree.ron", &mirror_scene());
    let out = raylab(&["inspect", path.to_str().unwrap(), "--pixel", "16,16"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for wanted in [
        "pixel (16, 16) of 33 x 33",
        "primary ray from (0.0000, 0.0000, 5.0000)",
        "hits mirror at t 5.000000",
        "Point light 2: shadowed by target",
        "blocked by target at t 7.0000",
        "Spot light 3: outside the spot cone",
        "  reflection ray",
        "    hits target",
        "    Point light 2: behind the surface",
    ] {
        assert!(text.contains(wanted), "missing {wanted:?} in\n{text}");
    }

    let out = raylab(&["inspect", path.to_str().unwrap(), "--pixel", "33,0"]);
    assert!(!out.status.success());
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(
        error.contains("pixel (33, 0) is outside the 33 x 33 image"),
        "{error}"
    );
    let out = raylab(&["inspect", path.to_str().unwrap(), "--pixel", "3"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("X,Y"));
}

#[test]
fn the_isolation_flags_leave_out_what_they_name_and_say_so() {
    let scene = mirror_scene();
    let path = scene_file("isolated.ron", &scene);
    let file = path.to_str().unwrap();
    let run = |extra: &[&str]| {
        let mut args = vec!["inspect", file, "--pixel", "16,16", "--json"];
        args.extend_from_slice(extra);
        let out = raylab(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<Value>(&out.stdout).unwrap()
    };

    // Hidden, the target neither blocks the shadow ray nor meets the mirror's bounce.
    let hidden = run(&["--hide", "target"]);
    assert_eq!(hidden["hidden_objects"], serde_json::json!(["target"]));
    let rays = hidden["rays"].as_array().unwrap();
    let shadow = rays.iter().find(|r| r["kind"] == "shadow").unwrap();
    assert_eq!(shadow["blocked_by"], Value::Null);
    let bounce = rays.iter().find(|r| r["kind"] == "reflection").unwrap();
    assert_eq!(bounce["hit"], Value::Null, "the bounce runs off");
    // The same pixel as a render with the same switches.
    let isolation = raylab::trace::Isolation {
        hidden_objects: [scene
            .objects
            .iter()
            .position(|o| o.name == "target")
            .unwrap()]
        .into(),
        ..raylab::trace::Isolation::NONE
    };
    let world = World::isolated(&scene, &isolation).unwrap();
    let options = RenderOptions {
        isolation,
        ..RenderOptions::from_scene(&scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    assert_eq!(vec3(&hidden["unclamped"]).as_vec3(), image.get(16, 16));

    // Muted, the point light casts no shadow ray and is named as off.
    let muted = run(&["--mute-light", "1"]);
    assert_eq!(muted["lights_off"], serde_json::json!([1]));
    let rays = muted["rays"].as_array().unwrap();
    assert!(rays.iter().all(|r| r["light"] != 1), "{rays:?}");
    let out = raylab(&["inspect", file, "--pixel", "16,16", "--mute-light", "1"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("off (muted or not solo): Point light 2")
            && text.contains("  Point light 2: off (muted or not solo)"),
        "{text}"
    );

    let out = raylab(&["inspect", file, "--pixel", "16,16", "--mute-light", "9"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("there is no light 9"));
}

#[test]
fn a_pixel_through_glass_shows_its_refracted_rays_as_a_tree() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/glass.ron");
    // A pixel on the glass ball.
    let json = inspect_json(&path, "270,260");
    let kinds: Vec<&str> = json["rays"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["kind"].as_str().unwrap())
        .collect();
    assert!(
        kinds.iter().filter(|k| **k == "refraction").count() >= 2,
        "in and out of the ball: {kinds:?}"
    );
    let out = raylab(&["inspect", path.to_str().unwrap(), "--pixel", "270,260"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("transmission: kt (0.9200, 0.9500, 0.9400)"),
        "{text}"
    );
    // Depth first: the camera ray's reflection ray comes first, its refraction ray after
    // the reflection ray's own lines, both two spaces in.
    let lines: Vec<&str> = text.lines().collect();
    let at = |prefix: &str| lines.iter().position(|l| l.starts_with(prefix));
    let reflection = at("  reflection ray").expect("the camera ray's mirror ray");
    let refraction = at("  refraction ray").expect("the camera ray's refracted ray");
    assert!(reflection < refraction, "{text}");
    assert!(
        lines[refraction + 1].starts_with("    hits glass ball"),
        "the refracted ray meets the ball's inside next: {text}"
    );
}
