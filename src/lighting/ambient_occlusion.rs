//! Ambient occlusion on the CPU: what the SSAO pass (notes 03, "Ambient
//! Light"; src/techniques/deferred/ambient_light.rs) estimates, ray traced
//! against the scene's triangles, and the pieces the pass shares with it.
//!
//! The definition both use: the ambient occlusion of a surface point P with
//! normal N, for a radius r, is the cosine-weighted fraction of the
//! hemisphere around N along which no geometry lies within r,
//! ```text
//! AO(P) = 1/pi  ∫_hemisphere V_r(P, w) (N . w) dw,
//! V_r(P, w) = 1 if the ray P + t w meets nothing for 0 < t < r, else 0.
//! ```
//! 1 on an open plane, 0 at the bottom of a narrow pit. Cosine-weighted
//! directions, because that is how ambient light arriving from a direction
//! lights a diffuse surface: AO x ambient x albedo is then the diffuse
//! reflection of a uniform sky that stops at distance r.
//!
//! Directions: `kernel(n)` gives n cosine-weighted unit vectors in the
//! tangent frame (z along N): Malley's method, points spread evenly over the
//! unit disk (radius sqrt((i + 0.5) / n), angle i x the golden angle) lifted
//! onto the hemisphere. The GPU pass uses `kernel(samples)` rotated about N
//! by one of 16 angles that a 4x4 tile (`TILE`) repeats over the screen;
//! the reference here traces `kernel(rays)`, rotated per pixel, with many
//! more rays.
//!
//! Self-occlusion: the point P comes from the depth buffer, a little off
//! its surface. As in the shadow reference (`shadow_reference`), a ray
//! starts `epsilon` along and a triangle within `epsilon` of P never counts.
//!
//! The analytic case of the tests, a 90-degree corner (`corner`): a floor
//! point at distance d from an infinite wall. A direction w hits the wall
//! within r when its component towards the wall exceeds d / r; cosine-
//! weighted directions project uniformly onto the unit disk of the tangent
//! plane (Malley), and that component is the disk point's coordinate along
//! the wall's normal, so the occluded fraction is the disk's segment beyond
//! the chord at a = d / r, over the disk's area pi:
//! ```text
//! AO(d) = 1 - (acos(a) - a sqrt(1 - a^2)) / pi,   a = min(d / r, 1)
//! ```
//! 1/2 in the corner itself, 1 from d = r on.

use super::shadow_reference::{SceneTriangles, pixel_world_point};
use glam::{Mat4, Vec3};
use std::f32::consts::PI;

/// The golden angle, pi (3 - sqrt 5): consecutive kernel directions turn
/// by it, so that any first few of them are spread around the normal.
pub const GOLDEN_ANGLE: f32 = 2.399_963_1;

/// The 4x4 rotation tile: texel (x, y) of the tile turns the kernel by
/// `TILE[4 y + x]` sixteenths of a turn. A Bayer order: each rotation once,
/// neighbours far apart, so that the 4x4 blur averages all sixteen.
pub const TILE: [u8; 16] = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];

/// The rotation of pixel (x, y) in the tile, radians.
pub fn tile_angle(x: usize, y: usize) -> f32 {
    2.0 * PI * f32::from(TILE[4 * (y % 4) + x % 4]) / 16.0
}

/// `n` cosine-weighted unit directions, z along the normal (module header).
pub fn kernel(n: usize) -> Vec<Vec3> {
    (0..n)
        .map(|i| {
            let u = (i as f32 + 0.5) / n as f32;
            let (s, c) = (i as f32 * GOLDEN_ANGLE).sin_cos();
            let rho = u.sqrt();
            Vec3::new(rho * c, rho * s, (1.0 - u).sqrt())
        })
        .collect()
}

/// Two unit vectors that make an orthonormal frame with the unit normal
/// `n` (Duff et al. 2017, "Building an Orthonormal Basis, Revisited": no
/// branch but the sign, no division by a small number). The GLSL twin is
/// `tangent_frame` in glsl/deferred/ambient_light.frag.
pub fn tangent_frame(n: Vec3) -> (Vec3, Vec3) {
    let sign = if n.z >= 0.0 { 1.0 } else { -1.0 };
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// Kernel direction `k` in the frame of `n`, turned by `angle` about it.
pub fn to_world(k: Vec3, n: Vec3, angle: f32) -> Vec3 {
    let (t, b) = tangent_frame(n);
    let (s, c) = angle.sin_cos();
    let (t, b) = (c * t + s * b, -s * t + c * b);
    t * k.x + b * k.y + n * k.z
}

/// AO(P) of the module header, ray traced: the fraction of the directions
/// `kernel` (turned by `angle` about `n`) along which no triangle of `tris`
/// lies at epsilon < t < radius.
pub fn ray_traced(
    tris: &SceneTriangles,
    p: Vec3,
    n: Vec3,
    radius: f32,
    kernel: &[Vec3],
    angle: f32,
) -> f32 {
    let Some(n) = n.try_normalize() else {
        return 1.0;
    };
    let eps = tris.epsilon;
    let open = kernel
        .iter()
        .filter(|&&k| {
            let w = to_world(k, n, angle);
            !(tris.bvh()).any_hit(p, w, eps, radius, |t| t.distance(p) > eps)
        })
        .count();
    open as f32 / kernel.len().max(1) as f32
}

/// The reference AO image: for every pixel of `depth` (window depth 0..1,
/// rows bottom-up, as glReadPixels gives them) with a surface (depth < 1),
/// AO(P) ray traced with `rays` directions about the G-buffer's normal at
/// that pixel (`normals`, same layout), P rebuilt from the depth with
/// `inverse_view_projection`; None for the background. The kernel is turned
/// by a different angle at every pixel, so that its finite set of
/// directions leaves noise, not a pattern.
#[allow(clippy::too_many_arguments)]
pub fn reference(
    tris: &SceneTriangles,
    depth: &[f32],
    normals: &[Vec3],
    inverse_view_projection: Mat4,
    width: usize,
    height: usize,
    radius: f32,
    rays: usize,
) -> Vec<Option<f32>> {
    assert_eq!(depth.len(), width * height, "depth is not width x height");
    assert_eq!(normals.len(), depth.len(), "one normal per pixel");
    let kernel = kernel(rays);
    let mut out = vec![None; depth.len()];
    if width == 0 {
        return out;
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let rows_per = height.div_ceil(threads).max(1);
    std::thread::scope(|s| {
        for (chunk, rows) in out.chunks_mut(rows_per * width).enumerate() {
            let kernel = &kernel;
            s.spawn(move || {
                for (i, v) in rows.iter_mut().enumerate() {
                    let (x, y) = (i % width, chunk * rows_per + i / width);
                    let at = y * width + x;
                    let d = depth[at];
                    if d >= 1.0 || d.is_nan() {
                        continue;
                    }
                    let p = pixel_world_point(x, y, d, inverse_view_projection, width, height);
                    // A turn per pixel along a golden-ratio sequence.
                    let angle = 2.0 * PI * ((at as f32 * 0.618_034) % 1.0);
                    *v = Some(ray_traced(tris, p, normals[at], radius, kernel, angle));
                }
            });
        }
    });
    out
}

/// AO of a floor point at distance `d` from a wall that meets the floor at
/// 90 degrees, for radius `radius` (module header): 1/2 at d = 0, 1 from
/// d = r on.
pub fn corner(d: f32, radius: f32) -> f32 {
    let a = (d / radius).clamp(0.0, 1.0);
    1.0 - (a.acos() - a * (1.0 - a * a).sqrt()) / PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_kernel_is_cosine_weighted_and_the_frame_orthonormal() {
        // E[cos] over cosine-weighted directions is 2/3; E[cos^2] is 1/2.
        let k = kernel(4096);
        let m1: f32 = k.iter().map(|w| w.z).sum::<f32>() / k.len() as f32;
        let m2: f32 = k.iter().map(|w| w.z * w.z).sum::<f32>() / k.len() as f32;
        assert!((m1 - 2.0 / 3.0).abs() < 1e-3, "{m1}");
        assert!((m2 - 0.5).abs() < 1e-3, "{m2}");
        for n in [
            Vec3::X,
            Vec3::Y,
            -Vec3::Z,
            Vec3::new(0.3, -0.5, 0.8).normalize(),
        ] {
            let (t, b) = tangent_frame(n);
            for (u, v) in [(t, b), (t, n), (b, n)] {
                assert!(u.dot(v).abs() < 1e-6);
            }
            assert!((t.length() - 1.0).abs() < 1e-6 && (b.length() - 1.0).abs() < 1e-6);
            assert!((to_world(Vec3::Z, n, 1.0) - n).length() < 1e-6);
        }
    }

    #[test]
    fn the_corner_formula_matches_its_disk_segment_integral() {
        assert!((corner(0.0, 1.0) - 0.5).abs() < 1e-6);
        assert_eq!(corner(1.0, 1.0), 1.0);
        assert_eq!(corner(2.0, 1.0), 1.0);
        // The fraction of cosine-weighted directions whose component along
        // -x exceeds a = d / r, counted over a dense kernel.
        let k = kernel(1 << 16);
        for d in [0.1f32, 0.3, 0.5, 0.8] {
            let hit = k.iter().filter(|w| -w.x > d).count() as f32 / k.len() as f32;
            assert!((corner(d, 1.0) - (1.0 - hit)).abs() < 2e-3, "d {d}");
        }
    }
}
