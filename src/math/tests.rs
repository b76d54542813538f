//! Unit tests for the transforms in `math` (notes 01 chapter 2): each matrix
//! against glam's own and against results worked out by hand.

use super::*;
use glam::camera::rh::proj::opengl;
use glam::camera::rh::view::look_at_mat4;
use std::f32::consts::{FRAC_PI_2, FRAC_PI_3, PI};

fn close4(a: Mat4, b: Mat4) {
    assert!(a.abs_diff_eq(b, 1e-5), "\n{a}\n!=\n{b}");
}

fn close3(a: Vec3, b: Vec3) {
    assert!(a.abs_diff_eq(b, 1e-5), "{a} != {b}");
}

#[test]
fn from_rows_reads_like_paper() {
    let m = from_rows([
        [1.0, 2.0, 3.0, 4.0],
        [5.0, 6.0, 7.0, 8.0],
        [9.0, 10.0, 11.0, 12.0],
        [13.0, 14.0, 15.0, 16.0],
    ]);
    assert_eq!(m.row(0), Vec4::new(1.0, 2.0, 3.0, 4.0));
    assert_eq!(m.col(3), Vec4::new(4.0, 8.0, 12.0, 16.0));
}

#[test]
fn scale_and_translate_match_glam() {
    close4(
        scale(2.0, -3.0, 0.5),
        Mat4::from_scale(Vec3::new(2.0, -3.0, 0.5)),
    );
    close4(
        translate(1.0, 2.0, 3.0),
        Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)),
    );
    close3(
        translate(1.0, 2.0, 3.0).transform_point3(Vec3::new(1.0, 1.0, 1.0)),
        Vec3::new(2.0, 3.0, 4.0),
    );
    // Directions (w = 0) are not moved by a translation.
    close3(translate(1.0, 2.0, 3.0).transform_vector3(Vec3::X), Vec3::X);
}

#[test]
fn rotations_match_glam() {
    for theta in [0.0, 0.3, FRAC_PI_2, 2.0, -1.2, PI] {
        close4(rotate_x(theta), Mat4::from_rotation_x(theta));
        close4(rotate_y(theta), Mat4::from_rotation_y(theta));
        close4(rotate_z(theta), Mat4::from_rotation_z(theta));
    }
}

#[test]
fn rotations_by_hand() {
    // Counter-clockwise looking down each axis toward the origin.
    close3(rotate_z(FRAC_PI_2).transform_point3(Vec3::X), Vec3::Y);
    close3(rotate_x(FRAC_PI_2).transform_point3(Vec3::Y), Vec3::Z);
    close3(rotate_y(FRAC_PI_2).transform_point3(Vec3::Z), Vec3::X);
    close3(rotate_y(FRAC_PI_2).transform_point3(Vec3::X), -Vec3::Z);
}

#[test]
fn notes_rotations_are_row_vector_transposes() {
    // The notes' x and z matrices, typed in as printed, are our transposes.
    let t = 0.7f32;
    let (s, c) = t.sin_cos();
    let notes_x = from_rows([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, c, s, 0.0],
        [0.0, -s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    let notes_z = from_rows([
        [c, s, 0.0, 0.0],
        [-s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    close4(notes_x.transpose(), rotate_x(t));
    close4(notes_z.transpose(), rotate_z(t));
    // Row vector times the notes' matrix equals our matrix times the column.
    let v = Vec4::new(0.3, -1.0, 2.0, 1.0);
    let row_times = Vec4::new(
        v.dot(notes_z.col(0)),
        v.dot(notes_z.col(1)),
        v.dot(notes_z.col(2)),
        v.dot(notes_z.col(3)),
    );
    assert!(row_times.abs_diff_eq(rotate_z(t) * v, 1e-5));
}

#[test]
fn orthographic_matches_glam_and_gl() {
    let (l, r, b, t, n, f) = (-4.0, 2.0, -1.0, 3.0, 0.5, 20.0);
    close4(
        orthographic(l, r, b, t, n, f),
        opengl::orthographic(l, r, b, t, n, f),
    );
    let p = orthographic(l, r, b, t, n, f);
    // Camera looks down -z: z = -near -> -1, z = -far -> +1.
    close3(
        p.transform_point3(Vec3::new(l, b, -n)),
        Vec3::new(-1.0, -1.0, -1.0),
    );
    close3(
        p.transform_point3(Vec3::new(r, t, -f)),
        Vec3::new(1.0, 1.0, 1.0),
    );
}

#[test]
fn perspective_matches_glam() {
    for (fov, aspect, n, f) in [(FRAC_PI_3, 16.0 / 9.0, 0.1, 100.0), (1.2, 1.0, 1.0, 5.0)] {
        close4(
            perspective(fov, aspect, n, f),
            opengl::perspective(fov, aspect, n, f),
        );
    }
}

#[test]
fn perspective_near_far_to_ndc() {
    let (n, f) = (0.5, 50.0);
    let p = perspective(FRAC_PI_2, 1.0, n, f);
    let near_pt = perspective_divide(p * Vec4::new(0.2, -0.1, -n, 1.0));
    let far_pt = perspective_divide(p * Vec4::new(3.0, 7.0, -f, 1.0));
    assert!((near_pt.z + 1.0).abs() < 1e-5, "near -> {near_pt}");
    assert!((far_pt.z - 1.0).abs() < 1e-4, "far -> {far_pt}");
    // fov 90 degrees, aspect 1: the frustum edge x = -z maps to x_ndc = 1.
    let edge = perspective_divide(p * Vec4::new(4.0, 0.0, -4.0, 1.0));
    assert!((edge.x - 1.0).abs() < 1e-5);
    // w_clip = -z: the distance in front of the camera.
    assert_eq!((p * Vec4::new(0.0, 0.0, -7.0, 1.0)).w, 7.0);
}

#[test]
fn perspective_divide_by_hand() {
    // (2, -4, 6, 2) / 2 = (1, -2, 3).
    assert_eq!(
        perspective_divide(Vec4::new(2.0, -4.0, 6.0, 2.0)),
        Vec3::new(1.0, -2.0, 3.0)
    );
    // A point twice as far away lands twice as close to the centre.
    let p = perspective(1.0, 1.0, 0.1, 100.0);
    let a = perspective_divide(p * Vec4::new(1.0, 1.0, -5.0, 1.0));
    let b = perspective_divide(p * Vec4::new(1.0, 1.0, -10.0, 1.0));
    assert!((a.x - 2.0 * b.x).abs() < 1e-6);
}

#[test]
fn look_at_matches_glam() {
    let cases = [
        (Vec3::new(3.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y),
        (
            Vec3::new(-1.0, 4.0, 0.5),
            Vec3::new(2.0, 0.0, -3.0),
            Vec3::Y,
        ),
        (
            Vec3::new(0.0, 0.0, 5.0),
            Vec3::ZERO,
            Vec3::new(1.0, 1.0, 0.0).normalize(),
        ),
    ];
    for (eye, target, up) in cases {
        close4(look_at(eye, target, up), look_at_mat4(eye, target, up));
    }
    // The eye maps to the origin and the target lies straight ahead (-z).
    let v = look_at(Vec3::new(3.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y);
    close3(v.transform_point3(Vec3::new(3.0, 2.0, 5.0)), Vec3::ZERO);
    let t = v.transform_point3(Vec3::ZERO);
    assert!(t.z < 0.0 && t.x.abs() < 1e-5 && t.y.abs() < 1e-5);
}

#[test]
fn look_at_degenerate_is_finite() {
    // Straight down with up = +y (a directional light's shadow camera).
    let v = look_at(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, Vec3::Y);
    assert!(v.is_finite());
    close3(v.transform_point3(Vec3::ZERO), Vec3::new(0.0, 0.0, -10.0));
    assert!(look_at(Vec3::ONE, Vec3::ONE, Vec3::Y).is_finite());
    assert!(look_at(Vec3::ZERO, Vec3::X, Vec3::ZERO).is_finite());
    assert!(
        (Mat3::from_mat4(look_at(Vec3::ONE, Vec3::ONE, Vec3::Y)).determinant() - 1.0).abs() < 1e-5
    );
}

#[test]
fn normal_matrix_keeps_normals_perpendicular() {
    let model = translate(1.0, 2.0, 3.0) * rotate_y(0.4) * scale(3.0, 0.5, 1.0) * rotate_x(-0.9);
    let nm = normal_matrix(&model).expect("invertible");
    // A surface through the origin with normal n contains tangents t1, t2.
    let n = Vec3::new(1.0, 2.0, -0.5).normalize();
    let t1 = n.any_orthonormal_vector();
    let t2 = n.cross(t1);
    let n_world = nm * n;
    for t in [t1, t2] {
        let t_world = model.transform_vector3(t);
        assert!(n_world.normalize().dot(t_world.normalize()).abs() < 1e-5);
        // The plain model matrix does NOT keep them perpendicular.
    }
    let wrong = model.transform_vector3(n).normalize();
    assert!(wrong.dot(model.transform_vector3(t1).normalize()).abs() > 1e-2);
    // For a pure rotation the normal matrix is the rotation itself.
    let r = rotate_z(0.8) * rotate_x(0.3);
    assert!(
        normal_matrix(&r)
            .unwrap()
            .abs_diff_eq(Mat3::from_mat4(r), 1e-5)
    );
}

#[test]
fn normal_matrix_of_tiny_but_uniform_scale_is_fine() {
    // Relative threshold: a small but regular matrix is not "singular".
    let nm = normal_matrix(&scale(1e-3, 1e-3, 1e-3)).expect("invertible");
    assert!(nm.abs_diff_eq(Mat3::from_diagonal(Vec3::splat(1e3)), 1e-1));
}

#[test]
fn normal_matrix_singular_is_none() {
    assert!(normal_matrix(&scale(1.0, 0.0, 1.0)).is_none());
    assert!(normal_matrix(&(rotate_x(0.3) * scale(2.0, 2.0, 0.0))).is_none());
    assert!(normal_matrix(&Mat4::ZERO).is_none());
    assert!(normal_matrix(&scale(1.0, 1e-13, 1.0)).is_none());
    // Thin but not flat is still invertible.
    assert!(normal_matrix(&scale(1.0, 1e-9, 1.0)).is_some());
    assert!(normal_matrix(&scale(f32::NAN, 1.0, 1.0)).is_none());
    assert!(normal_matrix(&translate(5.0, 0.0, 0.0)).is_some());
}
