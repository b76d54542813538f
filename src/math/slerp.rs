//! Spherical linear interpolation of rotations (notes 01 §7, "Animation":
//! keyframes of rotation interpolated between). Shoemake, "Animating
//! Rotation with Quaternion Curves" (SIGGRAPH 1985):
//!
//! ```text
//! slerp(a, b, t) = sin((1 - t) φ) / sin φ  a  +  sin(t φ) / sin φ  b
//! ```
//!
//! with φ the angle between a and b as unit 4-vectors. Written naively it
//! fails in three places, and each is handled here:
//!
//! - **The long way round.** q and -q are the same rotation. When a · b < 0
//!   the formula turns through more than 180° of rotation; negating b first
//!   takes the shortest arc. After that, φ is at most 90°.
//! - **Nearly equal keys.** φ from acos(a · b) loses every digit when a · b
//!   is near 1 (acos is flat there), and sin φ divides by almost 0. Here
//!   φ = 2 atan2(|a - b|, |a + b|), which keeps its digits at every angle.
//!   Both weights are written with sinc(x) = sin(x) / x, which needs no
//!   division near 0 (a Taylor series there):
//!   `sin(s φ) / sin φ = s sinc(s φ) / sinc(φ)`, and sinc(φ) >= 2/π for φ up
//!   to 90°.
//! - **Drift.** The sum is normalised, and the arithmetic is in f64, so a
//!   long chain of interpolations stays a rotation.

use glam::{DQuat, Quat};

/// sin(x) / x, 1 at 0.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// The angle between two unit 4-vectors, accurate at every angle.
fn angle(a: DQuat, b: DQuat) -> f64 {
    2.0 * (a - b).length().atan2((a + b).length())
}

/// The rotation `t` of the way from `a` to `b` along the shortest arc,
/// normalised. `t` = 0 gives `a`; `t` = 1 gives `b` or `-b` (the same
/// rotation). `a` and `b` are normalised first; `t` outside 0..=1
/// extrapolates along the same great circle.
pub fn slerp(a: Quat, b: Quat, t: f32) -> Quat {
    let a = DQuat::from_xyzw(a.x.into(), a.y.into(), a.z.into(), a.w.into()).normalize();
    let mut b = DQuat::from_xyzw(b.x.into(), b.y.into(), b.z.into(), b.w.into()).normalize();
    if a.dot(b) < 0.0 {
        b = -b;
    }
    let t = f64::from(t);
    let phi = angle(a, b);
    let s = sinc(phi);
    let wa = (1.0 - t) * sinc((1.0 - t) * phi) / s;
    let wb = t * sinc(t * phi) / s;
    let q = (a * wa + b * wb).normalize();
    Quat::from_xyzw(q.x as f32, q.y as f32, q.z as f32, q.w as f32)
}

/// The angle of the rotation that takes `a` to `b` (radians, 0..=π): how far
/// apart two orientations are, whichever sign each quaternion has.
pub fn rotation_between(a: Quat, b: Quat) -> f32 {
    let a = DQuat::from_xyzw(a.x.into(), a.y.into(), a.z.into(), a.w.into()).normalize();
    let mut b = DQuat::from_xyzw(b.x.into(), b.y.into(), b.z.into(), b.w.into()).normalize();
    if a.dot(b) < 0.0 {
        b = -b;
    }
    (2.0 * angle(a, b)) as f32
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn q(axis: Vec3, degrees: f32) -> Quat {
        Quat::from_axis_angle(axis.normalize(), degrees.to_radians())
    }

    fn unit(q: Quat) -> bool {
        (q.length() - 1.0).abs() < 1e-6 && q.is_finite()
    }

    #[test]
    fn the_ends_are_the_keys() {
        let (a, b) = (q(Vec3::Y, 10.0), q(Vec3::new(1.0, 1.0, 0.0), 130.0));
        assert!(rotation_between(slerp(a, b, 0.0), a) < 1e-6);
        assert!(rotation_between(slerp(a, b, 1.0), b) < 1e-6);
        // Exactly, not merely the same rotation, at t = 0.
        assert!((slerp(a, b, 0.0) - a).length() < 2e-7);
    }

    #[test]
    fn it_turns_at_a_constant_rate_about_one_axis() {
        // 0° to 120° about z: t of the way is 120 t degrees.
        let (a, b) = (Quat::IDENTITY, q(Vec3::Z, 120.0));
        for k in 0..=10 {
            let t = k as f32 / 10.0;
            let s = slerp(a, b, t);
            assert!(unit(s));
            let want = q(Vec3::Z, 120.0 * t);
            assert!(rotation_between(s, want) < 1e-5, "t {t}: {s} vs {want}");
        }
    }

    #[test]
    fn it_takes_the_shortest_arc() {
        // 170° about y then -170° about y (190°): the short way is 20°
        // through 180°, not 340° back through 0°.
        let (a, b) = (q(Vec3::Y, 170.0), q(Vec3::Y, -170.0));
        let mid = slerp(a, b, 0.5);
        assert!(rotation_between(mid, q(Vec3::Y, 180.0)) < 1e-5, "{mid}");
        // A key and its negation are the same rotation: nothing moves.
        let c = q(Vec3::new(0.3, -1.0, 0.2), 75.0);
        for t in [0.0, 0.3, 0.5, 1.0] {
            assert!(rotation_between(slerp(c, -c, t), c) < 1e-6, "t {t}");
        }
    }

    #[test]
    fn identical_and_nearly_identical_keys_give_finite_unit_rotations() {
        let a = q(Vec3::new(1.0, 2.0, 3.0), 40.0);
        for t in [0.0, 0.25, 0.5, 1.0] {
            let s = slerp(a, a, t);
            assert!(
                unit(s) && rotation_between(s, a) < 1e-6,
                "identical, t {t}: {s}"
            );
        }
        // 1e-7 apart: acos would be all rounding; here the result lies
        // between the keys.
        let b = Quat::from_xyzw(a.x + 1e-7, a.y, a.z, a.w).normalize();
        for t in [0.0, 0.5, 1.0] {
            let s = slerp(a, b, t);
            assert!(unit(s), "nearly identical, t {t}: {s}");
            assert!(rotation_between(s, a) <= rotation_between(a, b) + 1e-6);
        }
    }

    #[test]
    fn nearly_antipodal_keys_are_nearly_the_same_rotation() {
        let a = q(Vec3::X, 33.0);
        let b = -Quat::from_xyzw(a.x, a.y + 1e-6, a.z, a.w).normalize();
        for t in [0.0, 0.5, 1.0] {
            let s = slerp(a, b, t);
            assert!(unit(s), "t {t}: {s}");
            assert!(rotation_between(s, a) < 1e-5, "t {t}: {s}");
        }
        // A 180° turn between the keys (a · b = 0 as 4-vectors) has two
        // shortest arcs, +90° and -90° about the axis at halfway; the
        // rounding of the keys picks one. Either is 90° from both keys.
        let (c, d) = (Quat::IDENTITY, q(Vec3::Z, 180.0));
        let mid = slerp(c, d, 0.5);
        assert!(unit(mid));
        let about_z =
            rotation_between(mid, q(Vec3::Z, 90.0)).min(rotation_between(mid, q(Vec3::Z, -90.0)));
        assert!(about_z < 1e-5, "{mid}");
    }

    #[test]
    fn unnormalised_keys_are_normalised_first() {
        let (a, b) = (q(Vec3::Y, 0.0) * 3.0, q(Vec3::Y, 90.0) * 0.5);
        let s = slerp(a, b, 0.5);
        assert!(unit(s));
        assert!(rotation_between(s, q(Vec3::Y, 45.0)) < 1e-5);
    }
}
