use super::*;
use crate::math::{look_at, orthographic, perspective};

/// Points on each of the six planes and the plane's inward unit normal, in
/// the camera's space (looking down -z), for the frustum of `projection`.
fn perspective_planes() -> (Mat4, Vec<(Vec3, Vec3)>) {
    // 90° vertical field, square: the side planes are x = ±z and y = ±z.
    let p = perspective(std::f32::consts::FRAC_PI_2, 1.0, 1.0, 10.0);
    let s = std::f32::consts::FRAC_1_SQRT_2;
    let planes = vec![
        (Vec3::new(-5.0, 0.0, -5.0), Vec3::new(s, 0.0, -s)),
        (Vec3::new(5.0, 0.0, -5.0), Vec3::new(-s, 0.0, -s)),
        (Vec3::new(0.0, -5.0, -5.0), Vec3::new(0.0, s, -s)),
        (Vec3::new(0.0, 5.0, -5.0), Vec3::new(0.0, -s, -s)),
        (Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, 0.0, -1.0)),
        (Vec3::new(0.0, 0.0, -10.0), Vec3::new(0.0, 0.0, 1.0)),
    ];
    (p, planes)
}

fn orthographic_planes() -> (Mat4, Vec<(Vec3, Vec3)>) {
    let p = orthographic(-2.0, 2.0, -1.0, 1.0, 0.5, 20.0);
    let planes = vec![
        (Vec3::new(-2.0, 0.0, -5.0), Vec3::X),
        (Vec3::new(2.0, 0.0, -5.0), -Vec3::X),
        (Vec3::new(0.0, -1.0, -5.0), Vec3::Y),
        (Vec3::new(0.0, 1.0, -5.0), -Vec3::Y),
        (Vec3::new(0.0, 0.0, -0.5), -Vec3::Z),
        (Vec3::new(0.0, 0.0, -20.0), Vec3::Z),
    ];
    (p, planes)
}

#[test]
fn just_inside_just_outside_and_straddling_each_plane() {
    // A camera away from the origin: the planes are checked in world space.
    let eye = Vec3::new(3.0, 2.0, 5.0);
    let view = look_at(eye, Vec3::new(-1.0, 0.5, -2.0), Vec3::Y);
    let to_world = view.inverse();
    for (name, (projection, planes), r) in [
        ("perspective", perspective_planes(), 0.5),
        ("orthographic", orthographic_planes(), 0.2),
    ] {
        let f = Frustum::from_view_projection(&(projection * view));
        let eps = 1e-3;
        for (i, &(p, n)) in planes.iter().enumerate() {
            let world = |q: Vec3| to_world.transform_point3(q);
            // The plane's own distance, as the notes' plane equation gives it.
            let at = |q: Vec3| f.distance(i, world(q));
            assert!(at(p).abs() < 1e-4, "{name} plane {i}: {}", at(p));
            assert!(
                (at(p + n) - 1.0).abs() < 1e-4,
                "{name} plane {i} is normalised"
            );
            // Spheres of radius r.
            let sphere = |q: Vec3| f.sphere(world(q), r);
            assert_eq!(sphere(p + n * (r + eps)), Containment::Inside, "{name} {i}");
            assert_eq!(
                sphere(p - n * (r + eps)),
                Containment::Outside,
                "{name} {i}"
            );
            assert_eq!(sphere(p), Containment::Straddles, "{name} {i}");
            assert_eq!(
                sphere(p + n * (r - eps)),
                Containment::Straddles,
                "{name} {i}"
            );
            // Boxes of half-size h in the camera's axes: their corner
            // furthest along n lies h (|nx| + |ny| + |nz|) from the centre.
            // In world space the camera's axes are turned, so test boxes in
            // the camera's own space (view = identity).
            let local = Frustum::from_view_projection(&projection);
            let h = r * 0.5;
            let reach = h * (n.x.abs() + n.y.abs() + n.z.abs());
            let cube = |c: Vec3| local.aabb(c - Vec3::splat(h), c + Vec3::splat(h));
            assert_eq!(
                cube(p + n * (reach + eps)),
                Containment::Inside,
                "{name} box {i}"
            );
            assert_eq!(
                cube(p - n * (reach + eps)),
                Containment::Outside,
                "{name} box {i}"
            );
            assert_eq!(cube(p), Containment::Straddles, "{name} box {i}");
        }
    }
}

#[test]
fn a_box_moved_by_a_matrix_holds_every_moved_corner_tightly() {
    let m = Mat4::from_scale_rotation_translation(
        Vec3::new(2.0, 0.5, 1.0),
        glam::Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 0.7),
        Vec3::new(4.0, -1.0, 2.0),
    );
    let (lo, hi) = (Vec3::new(-1.0, 0.0, -2.0), Vec3::new(1.0, 3.0, 0.5));
    let (wlo, whi) = transform_aabb(&m, lo, hi);
    let corners = crate::math::shadow::corners(lo, hi).map(|c| m.transform_point3(c));
    let (mut blo, mut bhi) = (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN));
    for c in corners {
        blo = blo.min(c);
        bhi = bhi.max(c);
    }
    assert!(wlo.abs_diff_eq(blo, 1e-5) && whi.abs_diff_eq(bhi, 1e-5));
}

#[test]
fn a_singular_matrix_culls_nothing_and_never_nan() {
    let f = Frustum::from_view_projection(&Mat4::ZERO);
    assert_eq!(f.sphere(Vec3::splat(1e6), 1.0), Containment::Inside);
    assert_eq!(f.aabb(Vec3::ZERO, Vec3::ONE), Containment::Inside);
}
