//! Notes 01 chapter 2: transformations, written to be read next to the notes.
//!
//! # Row vectors in the notes, column vectors here
//!
//! OpenGL, GLSL and glam multiply a matrix by a COLUMN vector on its right:
//! `v' = M * v`, so the translation sits in the last column and a chain of
//! transforms reads right to left (`P * V * M * v`). Every function below
//! returns a [`glam::Mat4`] in that column-vector convention.
//!
//! The notes mix conventions in §2.4 Rotation:
//!
//! * their rotations about x and z are written for ROW vectors (`v' = v * R`):
//!   they are the transposes of the column-vector matrices used here. Read as
//!   column-vector matrices they would turn the wrong way (clockwise);
//! * their rotation about y already is the column-vector matrix (read as a
//!   row-vector matrix it would turn clockwise), so it is used unchanged;
//! * §2.2 Scale, §2.3 Translation (translation in the last column), §2.5.2
//!   Perspective and §2.6 Object definition are column-vector matrices already.
//!
//! §2.5.1 Orthographic has a sign error for OpenGL: see [`orthographic`].
//!
//! Each function writes its matrix row by row exactly as it would be printed
//! on paper (through [`from_rows`]); glam stores matrices column by column, so
//! `from_rows` transposes the array it is given.
//!
//! Rotations are right-handed: a positive angle turns counter-clockwise when
//! you look down the axis from its positive end toward the origin (x→y about
//! z, y→z about x, z→x about y), as glam's `Mat4::from_rotation_*` do.

use glam::{Mat3, Mat4, Vec3, Vec4};

/// Builds a matrix from its four rows, written as they appear on paper.
/// glam stores columns, so this is `from_cols_array_2d(rows).transpose()`.
pub fn from_rows(rows: [[f32; 4]; 4]) -> Mat4 {
    Mat4::from_cols_array_2d(&rows).transpose()
}

/// §2.2 Scale by `x`, `y` and `z` along each axis.
///
/// Notes (diagonal, so the same in either convention):
/// ```text
/// | x 0 0 0 |
/// | 0 y 0 0 |
/// | 0 0 z 0 |
/// | 0 0 0 1 |
/// ```
pub fn scale(x: f32, y: f32, z: f32) -> Mat4 {
    from_rows([
        [x, 0.0, 0.0, 0.0],
        [0.0, y, 0.0, 0.0],
        [0.0, 0.0, z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.3 Translation by `(x, y, z)`.
///
/// Notes (already column-vector form: the offset is in the last column):
/// ```text
/// | 1 0 0 x |
/// | 0 1 0 y |
/// | 0 0 1 z |
/// | 0 0 0 1 |
/// ```
pub fn translate(x: f32, y: f32, z: f32) -> Mat4 {
    from_rows([
        [1.0, 0.0, 0.0, x],
        [0.0, 1.0, 0.0, y],
        [0.0, 0.0, 1.0, z],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.4 Rotation about the x axis by `theta` radians (y turns toward z).
///
/// Notes (ROW-vector form, `v' = v * R`):
/// ```text
/// | 1   0     0    0 |
/// | 0  cos   sin   0 |
/// | 0 -sin   cos   0 |
/// | 0   0     0    1 |
/// ```
/// Changed: transposed for column vectors, so `sin` moves below the diagonal
/// and `-sin` above it.
pub fn rotate_x(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    from_rows([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, c, -s, 0.0],
        [0.0, s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.4 Rotation about the y axis by `theta` radians (z turns toward x).
///
/// Notes:
/// ```text
/// |  cos  0  sin  0 |
/// |   0   1   0   0 |
/// | -sin  0  cos  0 |
/// |   0   0   0   1 |
/// ```
/// Unchanged: unlike the notes' x and z rotations this one is already the
/// column-vector matrix (the notes are inconsistent here; as a row-vector
/// matrix it would turn clockwise).
pub fn rotate_y(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    from_rows([
        [c, 0.0, s, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [-s, 0.0, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.4 Rotation about the z axis by `theta` radians (x turns toward y).
///
/// Notes (ROW-vector form, `v' = v * R`):
/// ```text
/// |  cos  sin  0  0 |
/// | -sin  cos  0  0 |
/// |   0    0   1  0 |
/// |   0    0   0  1 |
/// ```
/// Changed: transposed for column vectors, so `-sin` moves above the diagonal.
pub fn rotate_z(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    from_rows([
        [c, -s, 0.0, 0.0],
        [s, c, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.5.1 Orthographic projection of the box (left, bottom, -near) ..
/// (right, top, -far) in camera space onto the NDC cube [-1, 1]^3.
///
/// OpenGL convention: the camera looks down -z, `near` and `far` are positive
/// distances in front of it, z = -near maps to z_ndc = -1 and z = -far to +1
/// (the same matrix as glOrtho).
///
/// Notes:
/// ```text
/// | 2/(r-l)    0        0       -(r+l)/(r-l) |
/// |   0      2/(t-b)    0       -(t+b)/(t-b) |
/// |   0        0      2/(f-n)   -(f+n)/(f-n) |
/// |   0        0        0             1      |
/// ```
/// Changed: the z row uses `-2/(f-n)`. The notes' `+2/(f-n)` maps z = +near
/// and z = +far, i.e. points BEHIND a camera that looks down -z; with it
/// everything in front of the camera is clipped (or depth is reversed).
pub fn orthographic(left: f32, right: f32, bottom: f32, top: f32, near: f32, far: f32) -> Mat4 {
    let (rl, tb, fnr) = (right - left, top - bottom, far - near);
    from_rows([
        [2.0 / rl, 0.0, 0.0, -(right + left) / rl],
        [0.0, 2.0 / tb, 0.0, -(top + bottom) / tb],
        [0.0, 0.0, -2.0 / fnr, -(far + near) / fnr],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.5.2 Perspective projection: `fov_y` is the vertical field of view in
/// radians, `aspect` is width / height, `near` and `far` are positive distances
/// down -z. After the divide (§2.5.3) z = -near gives z_ndc = -1 and z = -far
/// gives +1 (the same matrix as gluPerspective).
///
/// Notes (already column-vector form), with f = 1 / tan(fov / 2):
/// ```text
/// | f/aspect  0        0                  0           |
/// |    0      f        0                  0           |
/// |    0      0  (near+far)/(near-far)  2*near*far/(near-far) |
/// |    0      0       -1                  0           |
/// ```
/// Unchanged. The last row makes w_clip = -z: the distance in front of the camera.
pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / (fov_y / 2.0).tan();
    from_rows([
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [
            0.0,
            0.0,
            (near + far) / (near - far),
            2.0 * near * far / (near - far),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// §2.5.3 Perspective divide: clip coordinates (x, y, z, w) to normalised
/// device coordinates (x/w, y/w, z/w). The GPU does this after the vertex
/// shader; this is the CPU version for tests and picking.
///
/// w = 0 (a point in the camera's own plane) gives non-finite components; the
/// pipeline never divides such a point because clipping (§3.3) removes it first.
pub fn perspective_divide(v: Vec4) -> Vec3 {
    Vec3::new(v.x / v.w, v.y / v.w, v.z / v.w)
}

/// §8.1.1 Normal matrix: the transpose of the inverse of the model matrix's
/// upper-left 3x3, `transpose(inverse(mat3(model)))` in the notes' GLSL.
/// Normals transformed by it stay perpendicular to transformed surface
/// tangents even under non-uniform scale. Renormalise after use: it keeps
/// directions, not lengths.
///
/// Returns `None` when the 3x3 part is singular (a zero scale flattens the
/// object and it has no normals), or not finite. Singular means
/// |det| < 1e-12 * s^3, where s is the largest element magnitude, so the test
/// does not depend on the overall size of the matrix.
pub fn normal_matrix(model: &Mat4) -> Option<Mat3> {
    let m = Mat3::from_mat4(*model).as_dmat3();
    let s = m
        .to_cols_array()
        .iter()
        .fold(0.0f64, |acc, x| acc.max(x.abs()));
    if !s.is_finite() || s == 0.0 {
        return None;
    }
    // Work on m / s so that the threshold is relative to the matrix scale.
    let unit = m * (1.0 / s);
    if unit.determinant().abs() < 1e-12 {
        return None;
    }
    let n = (unit.inverse() * (1.0 / s)).transpose();
    let n = n.as_mat3();
    n.is_finite().then_some(n)
}

/// §2.7 View matrix: world space to camera space for a camera at `eye`
/// looking at `target`, with `up` giving the rough up direction. Camera space
/// is right-handed: x right, y up, the camera looks down -z (as gluLookAt and
/// glam's `camera::rh::view::look_at_mat4`).
///
/// The camera's axes in world space, as in §2.6 Object definition, are
/// `right = normalize(forward x up)`, `up' = right x forward` and
/// `back = -forward`. The view matrix is the inverse of that object matrix:
/// the rotation transposed (the axes become ROWS) and the translation
/// rotated and negated:
/// ```text
/// |  right.x   right.y   right.z  -dot(right, eye) |
/// |    up'.x     up'.y     up'.z  -dot(up', eye)   |
/// |   back.x    back.y    back.z  -dot(back, eye)  |
/// |     0         0         0            1         |
/// ```
/// Degenerate input never gives NaN: if `target == eye` the camera looks down
/// -z, and if `up` is zero or parallel to the view direction another world
/// axis is used as up (so looking straight down with up = +y works).
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let forward = (target - eye).try_normalize().unwrap_or(Vec3::NEG_Z);
    let r = forward.cross(up.normalize_or_zero());
    let right = if r.length() > 1e-6 {
        r.normalize()
    } else {
        // up is zero or parallel to forward: use the world axis least
        // parallel to forward instead.
        let a = forward.abs();
        let fallback = if a.y < 0.9 {
            Vec3::Y
        } else if a.z < 0.9 {
            Vec3::Z
        } else {
            Vec3::X
        };
        forward.cross(fallback).normalize()
    };
    let true_up = right.cross(forward);
    let back = -forward;
    from_rows([
        [right.x, right.y, right.z, -right.dot(eye)],
        [true_up.x, true_up.y, true_up.z, -true_up.dot(eye)],
        [back.x, back.y, back.z, -back.dot(eye)],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

#[cfg(test)]
mod tests {
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
            (Mat3::from_mat4(look_at(Vec3::ONE, Vec3::ONE, Vec3::Y)).determinant() - 1.0).abs()
                < 1e-5
        );
    }

    #[test]
    fn normal_matrix_keeps_normals_perpendicular() {
        let model =
            translate(1.0, 2.0, 3.0) * rotate_y(0.4) * scale(3.0, 0.5, 1.0) * rotate_x(-0.9);
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
}
