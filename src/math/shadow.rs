//! The matrices of shadow mapping (notes 01 §8.5; notes 02, "Rendering Cast
//! Shadows"): the light's view-projection, orthographic for a directional
//! light and perspective for a spot light; the six cube-face views of a point
//! light; and the bias matrix that takes the light's clip space to the shadow
//! map's texture space.
//!
//! "A bias matrix (uniform scale by 0.5, uniform translation by 0.5) is used
//! to convert from clip space coordinates (-1 to 1) to texture coordinates
//! (0 to 1)." The shadow matrix of a world point is then
//! `bias * light_projection * light_view`; its z, after the perspective
//! divide, is the depth the shadow map stores for that point.

use super::{from_rows, look_at, orthographic, perspective};
use glam::{Mat4, Vec3};

/// Notes 01 §8.5: scale by 0.5, then translate by 0.5, on x, y and z.
/// ```text
/// | 0.5  0    0    0.5 |
/// | 0    0.5  0    0.5 |
/// | 0    0    0.5  0.5 |
/// | 0    0    0    1   |
/// ```
pub fn bias() -> Mat4 {
    from_rows([
        [0.5, 0.0, 0.0, 0.5],
        [0.0, 0.5, 0.0, 0.5],
        [0.0, 0.0, 0.5, 0.5],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// An up vector for looking along `direction`: world y, unless the light
/// looks (nearly) straight up or down, then world z.
fn up_for(direction: Vec3) -> Vec3 {
    if direction.normalize().y.abs() > 0.999 {
        Vec3::Z
    } else {
        Vec3::Y
    }
}

/// A directional light's view-projection (notes 02: "orthographic
/// projection" for a light at infinity): looking along `direction` at a
/// sphere of radius `radius` about `centre` (the scene's bounds), the box
/// fitted tightly around that sphere. None for a zero direction.
pub fn directional(direction: Vec3, centre: Vec3, radius: f32) -> Option<Mat4> {
    let d = direction.try_normalize()?;
    let r = radius.max(1e-3);
    // The eye outside the sphere, looking at its centre along the light.
    let eye = centre - d * 2.0 * r;
    let view = look_at(eye, centre, up_for(d));
    Some(orthographic(-r, r, -r, r, r, 3.0 * r) * view)
}

/// A directional light's view-projection fitted to points (notes 01
/// §8.5.1, aliasing: the fewer world units a texel covers, the sharper the
/// shadow). The light looks along `direction`; in its view space the box
/// holds every point of `scene` (every caster, so nothing between the light
/// and what is seen is lost); with `visible`, x and y shrink to the part of
/// the scene those points span (the camera's frustum), when they overlap.
/// Returns the matrix and the box's width and height in world units.
pub fn directional_fitted(
    direction: Vec3,
    scene: &[Vec3],
    visible: Option<&[Vec3]>,
) -> Option<(Mat4, f32, f32)> {
    let d = direction.try_normalize()?;
    let (lo, hi) = bounds(scene)?;
    let centre = (lo + hi) * 0.5;
    let r = ((hi - lo).length() * 0.5).max(1e-3);
    let view = look_at(centre - d * 2.0 * r, centre, up_for(d));
    let to_light = |p: &[Vec3]| {
        let q: Vec<Vec3> = p.iter().map(|&p| view.transform_point3(p)).collect();
        bounds(&q)
    };
    let (mut lo, mut hi) = to_light(scene)?;
    if let Some((vlo, vhi)) = visible.and_then(to_light) {
        let (nlo, nhi) = (lo.max(vlo), hi.min(vhi));
        if nlo.x < nhi.x && nlo.y < nhi.y {
            (lo.x, lo.y, hi.x, hi.y) = (nlo.x, nlo.y, nhi.x, nhi.y);
        }
    }
    // A margin of 1% keeps points on the box's faces inside it.
    let m = (hi - lo).max(Vec3::splat(1e-3)) * 0.01;
    let (lo, hi) = (lo - m, hi + m);
    // View space looks down -z: the near plane is at -hi.z, the far at -lo.z.
    let projection = orthographic(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);
    Some((projection * view, hi.x - lo.x, hi.y - lo.y))
}

/// The axis-aligned box around `points` (None for none, or a non-finite one).
pub fn bounds(points: &[Vec3]) -> Option<(Vec3, Vec3)> {
    let lo = points.iter().fold(Vec3::INFINITY, |a, &p| a.min(p));
    let hi = points.iter().fold(Vec3::NEG_INFINITY, |a, &p| a.max(p));
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// The eight corners of the box `lo`..`hi`.
pub fn corners(lo: Vec3, hi: Vec3) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    })
}

/// A spot light's view-projection (notes 02: "perspective projection" for a
/// light at a point): from `position` along `direction`, a square frustum
/// whose half-angle is the cone's outer angle, from `near` to `far`. None
/// for a zero direction or a cone of 90 degrees or more.
pub fn spot(
    position: Vec3,
    direction: Vec3,
    outer_degrees: f32,
    near: f32,
    far: f32,
) -> Option<Mat4> {
    let d = direction.try_normalize()?;
    if !(outer_degrees > 0.0 && outer_degrees < 89.0) {
        return None;
    }
    let view = look_at(position, position + d, up_for(d));
    Some(perspective(2.0 * outer_degrees.to_radians(), 1.0, near, far) * view)
}

/// The six faces of a cube map, in GL's order (+x, -x, +y, -y, +z, -z):
/// each face's view direction and up vector as GL's cube-map convention
/// fixes them (the up vectors point to -y, except on the y faces).
pub const CUBE_FACES: [(Vec3, Vec3); 6] = [
    (Vec3::X, Vec3::NEG_Y),
    (Vec3::NEG_X, Vec3::NEG_Y),
    (Vec3::Y, Vec3::Z),
    (Vec3::NEG_Y, Vec3::NEG_Z),
    (Vec3::Z, Vec3::NEG_Y),
    (Vec3::NEG_Z, Vec3::NEG_Y),
];

/// A point light's six view-projections ("6 maps for omnidirectional
/// lights"): 90 degree square frusta from `position` through each face.
pub fn point(position: Vec3, near: f32, far: f32) -> [Mat4; 6] {
    let projection = perspective(std::f32::consts::FRAC_PI_2, 1.0, near, far);
    CUBE_FACES.map(|(dir, up)| projection * look_at(position, position + dir, up))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Vec4, Vec4Swizzles};

    fn project(m: Mat4, p: Vec3) -> Vec3 {
        let c = m * p.extend(1.0);
        c.xyz() / c.w
    }

    #[test]
    fn the_bias_matrix_takes_clip_space_to_texture_space() {
        let b = bias();
        for (clip, tex) in [
            (Vec3::splat(-1.0), Vec3::ZERO),
            (Vec3::splat(1.0), Vec3::ONE),
            (Vec3::ZERO, Vec3::splat(0.5)),
            (Vec3::new(-1.0, 1.0, 0.0), Vec3::new(0.0, 1.0, 0.5)),
        ] {
            assert!(b.transform_point3(clip).distance(tex) < 1e-6);
        }
        // The notes' form: scale by 0.5, then translate by 0.5.
        let composed =
            Mat4::from_translation(Vec3::splat(0.5)) * Mat4::from_scale(Vec3::splat(0.5));
        assert!((b - composed).abs_diff_eq(Mat4::ZERO, 1e-7));
        // The w of a clip-space point passes through: the divide comes after.
        assert_eq!(
            b * Vec4::new(0.0, 0.0, 0.0, 2.0),
            Vec4::new(1.0, 1.0, 1.0, 2.0)
        );
    }

    #[test]
    fn a_directional_light_sees_its_whole_bounding_sphere() {
        // A sun at the horizon (direction nearly horizontal) and one straight down.
        for dir in [
            Vec3::new(-0.3, -1.0, -0.4),
            Vec3::new(1.0, -1e-3, 0.0),
            Vec3::NEG_Y,
        ] {
            let (c, r) = (Vec3::new(1.0, 0.5, -2.0), 4.0);
            let m = directional(dir, c, r).unwrap();
            // The sphere's extreme points land inside the map, [-1, 1]^3.
            for p in [
                Vec3::X,
                Vec3::NEG_X,
                Vec3::Y,
                Vec3::NEG_Y,
                Vec3::Z,
                Vec3::NEG_Z,
            ] {
                let q = project(m, c + p * r * 0.999);
                assert!(q.abs().max_element() <= 1.0, "{dir} {p}: {q}");
            }
            // Nearer the light is smaller depth.
            let near = project(m, c - dir.normalize() * r * 0.5).z;
            let far = project(m, c + dir.normalize() * r * 0.5).z;
            assert!(near < far, "{dir}");
        }
        assert!(directional(Vec3::ZERO, Vec3::ZERO, 1.0).is_none());
    }

    #[test]
    fn a_fitted_box_holds_the_scene_and_narrows_to_the_visible_part() {
        let scene = corners(Vec3::new(-10.0, 0.0, -10.0), Vec3::new(10.0, 2.0, 10.0));
        for dir in [Vec3::new(-0.3, -1.0, -0.4), Vec3::new(1.0, -0.02, 0.0)] {
            let (m, w, h) = directional_fitted(dir, &scene, None).unwrap();
            for p in scene {
                let q = project(m, p);
                assert!(q.abs().max_element() <= 1.0, "{dir} {p}: {q}");
            }
            // A small visible part: a narrower box, every scene point still
            // inside in depth.
            let seen = corners(Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 1.0, 1.0));
            let (mv, wv, hv) = directional_fitted(dir, &scene, Some(&seen)).unwrap();
            assert!(wv * hv < 0.25 * w * h, "{dir}: {wv}x{hv} vs {w}x{h}");
            for p in seen {
                assert!(project(mv, p).abs().max_element() <= 1.0);
            }
            for p in scene {
                assert!(project(mv, p).z.abs() <= 1.0);
            }
        }
        assert!(directional_fitted(Vec3::NEG_Y, &[], None).is_none());
    }

    #[test]
    fn a_spot_light_frustum_is_its_outer_cone() {
        let (pos, dir) = (Vec3::new(0.0, 5.0, 0.0), Vec3::new(0.0, -1.0, 0.2));
        let m = spot(pos, dir, 30.0, 0.1, 50.0).unwrap();
        let d = dir.normalize();
        // A point on the cone's axis projects to the map's centre; one on
        // the cone's edge (in the map's plane) to its edge.
        let on_axis = project(m, pos + d * 10.0);
        assert!(on_axis.truncate().length() < 1e-5, "{on_axis}");
        let side = d.cross(Vec3::Y).normalize();
        let edge = pos + (d * 30f32.to_radians().cos() + side * 30f32.to_radians().sin()) * 10.0;
        let e = project(m, edge);
        assert!((e.x.abs().max(e.y.abs()) - 1.0).abs() < 1e-4, "{e}");
        assert!(spot(pos, dir, 90.0, 0.1, 50.0).is_none());
        assert!(spot(pos, Vec3::ZERO, 30.0, 0.1, 50.0).is_none());
    }

    #[test]
    fn each_cube_face_looks_along_its_axis() {
        let pos = Vec3::new(1.0, 2.0, 3.0);
        let faces = point(pos, 0.05, 20.0);
        for (k, (m, (dir, _))) in faces.iter().zip(CUBE_FACES).enumerate() {
            // A point along the face's axis is at the face's centre, in front.
            let q = project(*m, pos + dir * 5.0);
            assert!(
                q.truncate().length() < 1e-5 && q.z.abs() < 1.0,
                "face {k}: {q}"
            );
            // And every direction is seen by exactly the faces whose frustum holds it.
            let p = pos + dir * 5.0 + CUBE_FACES[(k + 2) % 6].0 * 4.9;
            let q = project(*m, p);
            assert!(q.x.abs() <= 1.0 && q.y.abs() <= 1.0, "face {k}: {q}");
        }
    }
}
