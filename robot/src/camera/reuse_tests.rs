//! A camera whose picture did not change reuses its render and layers: the vectors are
//! byte for byte those of a camera that makes every image from scratch.
use super::*;
use crate::model::{Part, RobotModel, POSTURE_PARTS, POSTURE_STAND};
use crate::render::{camera_pose, Ball, CameraWorld, PinholeCamera};
use crate::scene::Scene;

fn pinhole(pan_deg: f64) -> PinholeCamera {
    let mut b = crate::kinematics::Body::new(RobotModel::new(Design::Ers7));
    b.set_posture_deg(&POSTURE_PARTS, &POSTURE_STAND);
    b.set_posture_deg(&[Part::NeckPan], &[pan_deg]);
    PinholeCamera::new(Design::Ers7, camera_pose(&b, &Scene::default()))
}

/// The next image of `k` made by a camera with the same state and nothing to reuse.
fn from_scratch(k: &Camera, cam: &PinholeCamera, world: &CameraWorld, frame: u32) -> Vec<u8> {
    let mut fresh = Camera::new(k.design);
    (fresh.lut, fresh.settings, fresh.field_counter) = (k.lut.clone(), k.settings, k.field_counter);
    fresh.render_scene(cam, world, None);
    let mut out = vec![0; fresh.vector_size()];
    fresh.build_vector(7, frame, &mut out);
    out
}

fn next(k: &mut Camera, cam: &PinholeCamera, world: &CameraWorld, frame: u32) -> Vec<u8> {
    let want = from_scratch(k, cam, world, frame);
    k.render_scene(cam, world, None);
    let mut out = vec![0; k.vector_size()];
    k.build_vector(7, frame, &mut out);
    assert!(out == want, "image of frame {frame} differs from one made from scratch");
    out
}

#[test]
fn a_still_camera_gets_the_same_bytes_as_from_scratch() {
    let mut k = Camera::new(Design::Ers7);
    let world = CameraWorld { ball: Some(Ball { x_mm: 600.0, ..Ball::default() }), ..CameraWorld::default() };
    let cam = pinhole(0.0);
    let first = next(&mut k, &cam, &world, 1);
    assert!(k.reuse.layers.is_none(), "a new picture keeps no copy");
    next(&mut k, &cam, &world, 2);
    assert!(k.reuse.layers.is_some(), "a repeated picture keeps its layers");
    let third = next(&mut k, &cam, &world, 3);
    let layers = k.layout.layers[0].data_offset;
    assert_ne!(first[..layers], third[..layers], "the header has the frame number");
    // new tables, new settings, a moved head, a moved ball: each makes a new image
    k.lut.load(&CdtTable { channel: 0, entries: [cdt_entry(255, 150, 255, 129); 32] });
    let pink = next(&mut k, &cam, &world, 4);
    assert_ne!(pink[layers..], third[layers..], "the CDT layer shows the ball");
    assert_eq!(k.settings.control(CAM_SET_GAIN, 1), O_SUCCESS);
    next(&mut k, &cam, &world, 5);
    next(&mut k, &cam, &world, 6);
    next(&mut k, &pinhole(10.0), &world, 7);
    let moved = CameraWorld { ball: Some(Ball { x_mm: 700.0, ..Ball::default() }), ..world.clone() };
    next(&mut k, &pinhole(10.0), &moved, 8);
    next(&mut k, &pinhole(10.0), &moved, 9);
}

#[test]
fn file_and_outside_pictures_are_never_taken_for_the_scene() {
    let mut k = Camera::new(Design::Ers7);
    let (cam, world) = (pinhole(0.0), CameraWorld::default());
    k.render_scene(&cam, &world, None);
    let scene = k.rgb.data.clone();
    k.fill_from(&vec![9; scene.len()]);
    k.render_scene(&cam, &world, None);
    assert!(k.rgb.data == scene, "the scene is rendered again after an outside picture");
}
