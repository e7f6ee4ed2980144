//! Handle drags as edits: snapping, lights, the camera, and parts of object trees
//! moved in their parent's space.

use super::*;
use crate::trace::PinholeCamera;

fn scene() -> Scene {
    crate::ui::document::files::default_scene()
}

fn geometry(scene: &Scene) -> DragGeometry {
    DragGeometry {
        eye: scene.camera.position,
        cone_length: (scene.camera.position - scene.camera.look_at).length() * 0.3,
        sun: (scene.camera.look_at, 1.0),
    }
}

#[test]
fn snapped_translate_lands_on_whole_units_of_the_moved_axis_only() {
    let scene = scene();
    let camera = PinholeCamera::new(&scene.camera, 800, 600);
    let Transform::Trs(trs) = scene.objects[1].transform else {
        panic!("red ball has a TRS transform");
    };
    let grabbed = Grabbed::Object(1, scene.objects[1].clone(), trs);
    let a = camera.ray(camera.project(trs.translate + DVec3::X * 0.5).unwrap());
    let b = camera.ray(camera.project(trs.translate + DVec3::X * 1.8).unwrap());
    let handle = HandleId::Translate(TranslateHandle::Axis(0));
    let edit = drag_edit(handle, &grabbed, &geometry(&scene), &a, &b, true).unwrap();
    let SceneEdit::SetObject(1, object) = edit.edit else {
        panic!("an object edit");
    };
    let Transform::Trs(moved) = object.transform else {
        panic!("still TRS");
    };
    // -1.7 + 1.3 = -0.4 snaps to 0; y and z stay.
    assert_eq!(moved.translate.x, 0.0);
    assert_eq!(moved.translate.y, trs.translate.y);
    assert_eq!(moved.translate.z, trs.translate.z);
}

#[test]
fn snapped_rotation_and_scale_use_their_steps() {
    let scene = scene();
    let camera = PinholeCamera::new(&scene.camera, 800, 600);
    let Transform::Trs(trs) = scene.objects[2].transform else {
        panic!("mirror ball has a TRS transform");
    };
    let grabbed = Grabbed::Object(2, scene.objects[2].clone(), trs);
    let ray_at = |p: DVec3| camera.ray(camera.project(p).unwrap());
    let c = trs.translate;
    let (a, b) = (ray_at(c + DVec3::X), ray_at(c + DVec3::new(0.8, 0.0, -0.6)));
    let edit = drag_edit(HandleId::Ring(1), &grabbed, &geometry(&scene), &a, &b, true);
    assert!(edit.unwrap().readout.contains("rotate y 30.0°"));
    let (a, b) = (ray_at(c + DVec3::X), ray_at(c + DVec3::X * 1.73));
    let edit = drag_edit(
        HandleId::Scale(0),
        &grabbed,
        &geometry(&scene),
        &a,
        &b,
        true,
    );
    assert_eq!(edit.unwrap().readout, "scale x 1.70");
}

#[test]
fn aiming_a_directional_light_puts_its_tail_under_the_cursor() {
    let scene = scene();
    let camera = PinholeCamera::new(&scene.camera, 800, 600);
    let light = scene.lights[2].clone();
    let Light::Directional { direction: d0, .. } = light else {
        panic!("light 3 is directional");
    };
    let grabbed = Grabbed::Light(2, light);
    let geometry = geometry(&scene);
    let (anchor, length) = geometry.sun;
    // The cursor over a point of the plane through the tail where the drag started,
    // facing the eye, off the sphere the tail sits on between drags.
    let start_tail = anchor - d0.normalize() * length;
    let (u, v) = (geometry.eye - start_tail)
        .normalize()
        .any_orthonormal_pair();
    let tail = start_tail + 0.4 * length * u - 0.7 * length * v;
    let wanted = -(tail - anchor).normalize();
    let ray = camera.ray(camera.project(tail).unwrap());
    let edit = drag_edit(HandleId::Aim, &grabbed, &geometry, &ray, &ray, false);
    let Some(DragEdit {
        edit: SceneEdit::SetLight(2, Light::Directional { direction, .. }),
        ..
    }) = edit
    else {
        panic!("a directional light edit");
    };
    assert!(
        (direction.normalize() - wanted).length() < 1e-6,
        "{direction}"
    );
}

#[test]
fn a_part_moves_in_its_parents_space_with_the_grabbed_point_under_the_cursor() {
    use crate::scene::tree::world_from_parent;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    let scene = crate::scene::load_scene(&path).expect("example");
    // A pip of the die, which is turned and scaled: its parent's axes are not the
    // world's.
    let die = scene.objects.iter().position(|o| o.name == "die").unwrap();
    let part = vec![die, 3];
    let selection = Selection::Part(part.clone());
    let handle = HandleId::Translate(TranslateHandle::Plane(2));
    let grabbed = grab(&scene, &selection, handle).expect("a part with a TRS");
    let Grabbed::Part(_, _, trs, _) = &grabbed else {
        panic!("{grabbed:?}");
    };
    let parent = world_from_parent(&scene.objects, &part);
    let origin = parent.transform_point3(trs.translate);
    let camera = PinholeCamera::new(&scene.camera, 800, 600);
    let at = camera.project(origin).unwrap();
    let start = camera.ray(at);
    let now = camera.ray(at + glam::DVec2::new(40.0, -25.0));
    let edit = drag_edit(handle, &grabbed, &geometry(&scene), &start, &now, false).unwrap();
    let SceneEdit::SetPart(edited_path, object) = edit.edit else {
        panic!("a part edit");
    };
    assert_eq!(edited_path, part);
    let Transform::Trs(moved) = object.transform else {
        panic!("still TRS");
    };
    // It slid in the die's face plane (its parent's z = const)...
    assert!((moved.translate.z - trs.translate.z).abs() < 1e-12);
    assert!((moved.translate - trs.translate).length() > 0.05);
    // ...and its origin, grabbed, is under the pointer now.
    let p = parent.transform_point3(moved.translate);
    let off_ray = (p - now.origin).cross(now.dir.normalize()).length();
    assert!(off_ray < 1e-9, "{off_ray}");
}
