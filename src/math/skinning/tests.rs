//! Skinning's formula, its weights' hard cases, and the candy wrapper.

use super::*;

#[test]
fn one_joint_is_that_joints_transform() {
    let t = Mat4::from_rotation_translation(Quat::from_rotation_z(0.7), Vec3::new(1.0, 2.0, 3.0));
    let v = Vec3::new(0.3, -0.2, 0.5);
    let (p, n) = linear_blend(&[t], [0, 0, 0, 0], [1.0, 0.0, 0.0, 0.0], v, Vec3::Y);
    assert!((p - t.transform_point3(v)).length() < 1e-6);
    assert!((n - t.transform_vector3(Vec3::Y)).length() < 1e-6);
    let d = [DualQuat::from_mat4(&t)];
    let (q, m) = dual_quaternion_blend(&d, [0; 4], [1.0, 0.0, 0.0, 0.0], v, Vec3::Y);
    assert!((q - p).length() < 1e-5, "{q} vs {p}");
    assert!((m - n).length() < 1e-5);
}

#[test]
fn the_blend_is_the_notes_weighted_sum() {
    let a = Mat4::from_translation(Vec3::X);
    let b = Mat4::from_translation(Vec3::Y * 2.0);
    let (p, _) = linear_blend(
        &[a, b],
        [0, 1, 0, 0],
        [0.25, 0.75, 0.0, 0.0],
        Vec3::ZERO,
        Vec3::Z,
    );
    assert!((p - Vec3::new(0.25, 1.5, 0.0)).length() < 1e-6);
}

#[test]
fn weights_are_checked_and_renormalised() {
    assert_eq!(
        normalised_weights("v", [0.5, 0.5, 0.0, 0.0]).unwrap(),
        ([0.5, 0.5, 0.0, 0.0], false)
    );
    let (w, fixed) = normalised_weights("v", [1.0, 1.0, 2.0, 0.0]).unwrap();
    assert!(fixed);
    assert_eq!(w, [0.25, 0.25, 0.5, 0.0]);
    let zero = normalised_weights("mesh \"arm\" vertex 17", [0.0; 4]).unwrap_err();
    assert!(format!("{zero}").contains("mesh \"arm\" vertex 17: every weight is 0"));
    assert!(normalised_weights("v", [f32::NAN, 1.0, 0.0, 0.0]).is_err());
    assert!(normalised_weights("v", [-0.5, 1.5, 0.0, 0.0]).is_err());
}

/// Two joints along x: the second twists 180° about x. A vertex on the
/// limb's surface (1 from the axis), weighted half and half.
fn twisted() -> ([Mat4; 2], Vec3) {
    let twist = Mat4::from_rotation_x(std::f32::consts::PI);
    ([Mat4::IDENTITY, twist], Vec3::new(0.5, 1.0, 0.0))
}

#[test]
fn linear_blending_collapses_a_twisted_joint_and_dual_quaternions_do_not() {
    let (joints, v) = twisted();
    let w = [0.5, 0.5, 0.0, 0.0];
    let (lbs, _) = linear_blend(&joints, [0, 1, 0, 0], w, v, Vec3::Y);
    // Halfway between (0.5, 1, 0) and (0.5, -1, 0): on the axis.
    assert!(lbs.y.hypot(lbs.z) < 1e-6, "linear blending keeps {lbs}");
    let dq = joints.map(|m| DualQuat::from_mat4(&m));
    let (dqs, n) = dual_quaternion_blend(&dq, [0, 1, 0, 0], w, v, Vec3::Y);
    // A quarter twist: still 1 from the axis, and the normal turned with it.
    assert!(
        (dqs.y.hypot(dqs.z) - 1.0).abs() < 1e-5,
        "dual quaternions give {dqs}"
    );
    assert!((dqs.x - 0.5).abs() < 1e-5);
    assert!(
        (n.length() - 1.0).abs() < 1e-5 && n.dot(Vec3::Y).abs() < 1e-5,
        "{n}"
    );
}

#[test]
fn dual_quaternions_carry_rotation_and_translation() {
    let r = Quat::from_rotation_y(1.1);
    let t = Vec3::new(-2.0, 0.5, 4.0);
    let d = DualQuat::from_rotation_translation(r, t);
    let p = Vec3::new(0.2, 0.3, -0.4);
    assert!((d.transform_point(p) - (r * p + t)).length() < 1e-5);
}
