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

pub mod reflection;
mod scene_graph;
pub use scene_graph::chain_globals;
pub mod shadow;

use glam::{Mat3, Mat4, Vec3, Vec4};

pub mod bump;
pub mod cascades;
pub mod cube_map;
pub mod depth;
pub mod frustum;
pub mod gaussian;
pub mod gbuffer_encoding;
pub mod height_field;
pub mod interpolation;
pub mod keyframes;
pub(crate) mod lcg;
pub mod octahedral;
pub mod preetham;
pub mod skinning;
pub mod slerp;
pub mod sphere_light;
pub mod texture_mapping;

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

/// The cofactor matrix of `m`'s upper 3x3, det x inverse-transpose: its
/// columns are c1 x c2, c2 x c0, c0 x c1. It carries normals like the normal
/// matrix (up to the determinant's scale and sign) and stays defined when
/// `m` is singular, where it gives a flattened surface's normal.
pub fn cofactor(m: &Mat4) -> Mat3 {
    let m = Mat3::from_mat4(*m);
    let (c0, c1, c2) = (m.x_axis, m.y_axis, m.z_axis);
    Mat3::from_cols(c1.cross(c2), c2.cross(c0), c0.cross(c1))
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
mod tests;
