//! Reflection about a plane (notes 05, "Reflecting Objects"): "if the mirror
//! passes through the origin, and is aligned with a coordinate axis, then
//! just negate appropriate coordinate. Otherwise, transform into mirror space,
//! reflect, transform back."
//!
//! [`reflection`] builds the matrix exactly that way; [`reflection_closed_form`]
//! is the textbook closed form `x' = x - 2 ((x - p) . n) n`, i.e. the
//! upper 3x3 `I - 2 n n^T` and the translation `2 (p . n) n`, kept as the
//! test's independent reference.

use super::{from_rows, translate};
use glam::{Mat4, Vec3, Vec4};

/// A plane `n . x = d` with unit normal `n`, stored as `(n, -d)` so that
/// `plane.dot((x, 1))` is the signed distance of `x` from it.
pub fn plane(point: Vec3, normal: Vec3) -> Option<Vec4> {
    let n = unit_normal(normal)?;
    Some(n.extend(-n.dot(point)))
}

/// `normal`, normalised; None for a zero (or non-finite) normal, which
/// defines no plane.
pub fn unit_normal(normal: Vec3) -> Option<Vec3> {
    let n = normal.try_normalize()?;
    n.is_finite().then_some(n)
}

/// Two unit vectors that make `(t, b, n)` a right-handed orthonormal basis:
/// mirror space's x and y axes, lying in the mirror.
fn tangents(n: Vec3) -> (Vec3, Vec3) {
    // Cross with the world axis least parallel to n: never near zero.
    let a = n.abs();
    let axis = if a.x <= a.y && a.x <= a.z {
        Vec3::X
    } else if a.y <= a.z {
        Vec3::Y
    } else {
        Vec3::Z
    };
    let t = axis.cross(n).normalize();
    (t, n.cross(t))
}

/// The reflection about the plane through `point` with normal `normal`
/// (any length; None when it is zero), built as the notes say:
///
/// 1. into mirror space: move `point` to the origin, then rotate the plane's
///    basis `(t, b, n)` onto `(x, y, z)`: `to_mirror = B^T * T(-point)`;
/// 2. reflect: the mirror is now the plane z = 0, "just negate" z:
///    `scale(1, 1, -1)`;
/// 3. back: `from_mirror = T(point) * B`.
///
/// `reflection = from_mirror * scale(1, 1, -1) * to_mirror`. Its determinant
/// is -1: it turns counter-clockwise triangles clockwise (notes 05, "Small
/// Problem").
pub fn reflection(point: Vec3, normal: Vec3) -> Option<Mat4> {
    let n = unit_normal(normal)?;
    let (t, b) = tangents(n);
    // Rows of B^T are the basis vectors: a point's coordinates in mirror space.
    let to_basis = from_rows([
        [t.x, t.y, t.z, 0.0],
        [b.x, b.y, b.z, 0.0],
        [n.x, n.y, n.z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    let to_mirror = to_basis * translate(-point.x, -point.y, -point.z);
    let negate_z = super::scale(1.0, 1.0, -1.0);
    let from_mirror = translate(point.x, point.y, point.z) * to_basis.transpose();
    Some(from_mirror * negate_z * to_mirror)
}

/// The closed form: `I - 2 n n^T` with translation `2 (p . n) n`
/// (n normalised). The tests' reference for [`reflection`].
pub fn reflection_closed_form(point: Vec3, normal: Vec3) -> Option<Mat4> {
    let n = unit_normal(normal)?;
    let d = 2.0 * point.dot(n);
    Some(from_rows([
        [
            1.0 - 2.0 * n.x * n.x,
            -2.0 * n.x * n.y,
            -2.0 * n.x * n.z,
            d * n.x,
        ],
        [
            -2.0 * n.y * n.x,
            1.0 - 2.0 * n.y * n.y,
            -2.0 * n.y * n.z,
            d * n.y,
        ],
        [
            -2.0 * n.z * n.x,
            -2.0 * n.z * n.y,
            1.0 - 2.0 * n.z * n.z,
            d * n.z,
        ],
        [0.0, 0.0, 0.0, 1.0],
    ]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Largest element-wise difference, relative to the translation's size.
    fn close(a: Mat4, b: Mat4, scale: f32) -> f32 {
        (a - b)
            .to_cols_array()
            .iter()
            .map(|x| x.abs())
            .fold(0.0, f32::max)
            / scale.max(1.0)
    }

    /// Hard cases: non-unit normals, planes far from the origin, nearly
    /// axis-aligned planes (the basis must not degenerate), axis-aligned.
    const CASES: &[([f32; 3], [f32; 3])] = &[
        ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, -3.0], [0.0, 0.0, 5.0]),
        ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]),
        ([1000.0, -2000.0, 500.0], [0.3, -0.2, 0.9]),
        ([0.0, 1.0, 0.0], [1e-4, 1.0, -1e-4]),
        ([2.0, 0.0, 0.0], [1.0, 1e-7, 0.0]),
        ([0.0, 0.0, 0.0], [-1e-3, 0.0, 2e-3]),
        ([-4.0, 0.5, 7.0], [0.0, -3.0, 0.0]),
    ];

    #[test]
    fn mirror_space_construction_equals_the_closed_form() {
        for &(p, n) in CASES {
            let (p, n) = (Vec3::from(p), Vec3::from(n));
            let a = reflection(p, n).unwrap();
            let b = reflection_closed_form(p, n).unwrap();
            let err = close(a, b, p.length());
            assert!(err < 2e-6, "p = {p}, n = {n}: differ by {err}\n{a}\n{b}");
        }
    }

    #[test]
    fn reflection_is_an_involution_with_determinant_minus_one() {
        for &(p, n) in CASES {
            let r = reflection(Vec3::from(p), Vec3::from(n)).unwrap();
            let scale = Vec3::from(p).length();
            assert!(close(r * r, Mat4::IDENTITY, scale) < 4e-6, "{p:?} {n:?}");
            let det = r.determinant();
            assert!((det + 1.0).abs() < 1e-5, "det = {det}");
        }
    }

    #[test]
    fn points_on_the_plane_stay_and_offsets_flip() {
        for &(p, n) in CASES {
            let (p, n) = (Vec3::from(p), Vec3::from(n));
            let r = reflection(p, n).unwrap();
            let u = n.normalize();
            let (t, b) = tangents(u);
            let on_plane = p + 3.0 * t - 2.0 * b;
            let tol = 1e-5 * (1.0 + p.length());
            assert!(r.transform_point3(on_plane).distance(on_plane) < tol);
            let off = on_plane + 1.5 * u;
            let image = r.transform_point3(off);
            assert!(image.distance(on_plane - 1.5 * u) < tol, "{image}");
            let pl = plane(p, n).unwrap();
            assert!((pl.dot(off.extend(1.0)) - 1.5).abs() < tol);
            assert!((pl.dot(image.extend(1.0)) + 1.5).abs() < tol);
        }
    }

    #[test]
    fn axis_aligned_mirror_through_the_origin_just_negates_a_coordinate() {
        let r = reflection(Vec3::ZERO, Vec3::X).unwrap();
        assert!(close(r, crate::math::scale(-1.0, 1.0, 1.0), 1.0) < 1e-7);
    }

    #[test]
    fn a_zero_normal_defines_no_plane() {
        assert!(reflection(Vec3::ONE, Vec3::ZERO).is_none());
        assert!(reflection_closed_form(Vec3::ONE, Vec3::ZERO).is_none());
        assert!(plane(Vec3::ONE, Vec3::splat(f32::NAN)).is_none());
    }
}
