//! The geometry of cascaded shadow maps (Engel 2006, "Cascaded Shadow
//! Maps", ShaderX5; Zhang et al. 2006, "Parallel-Split Shadow Maps";
//! Valient 2008, "Stable Rendering of Cascaded Shadow Maps", ShaderX6):
//!
//! 1. split the camera's depth range [n, f] into m slices (`splits`);
//! 2. fit an orthographic box, looking along the light, around each slice
//!    (`fit`): tightly (the slice's corners, the most texels on the slice),
//!    or stably (a square about the slice's bounding sphere, moved in
//!    whole texels, so that a texel of the map stays on the same world
//!    points as the camera moves and the shadow's edge does not shimmer).
//!
//! In depth every box holds every caster: what lies between the light and
//! the slice still casts onto it.

use super::shadow::bounds;
use super::{look_at, orthographic};
use glam::{Mat4, Vec3};

/// The m + 1 split distances (view depth) of [near, far] into `m` slices,
/// Zhang et al.'s practical scheme: C_i = lambda C_log + (1 - lambda) C_uni
/// with C_uni = n + (f - n) i / m and C_log = n (f / n)^(i / m); lambda 0
/// is the uniform scheme, 1 the logarithmic (`Shadow::split_lambda`).
pub fn splits(near: f32, far: f32, m: u32, lambda: f32) -> Vec<f32> {
    let m = m.max(1);
    let (n, f) = (near.max(1e-6), far.max(near * 1.0001));
    (0..=m)
        .map(|i| {
            let t = i as f32 / m as f32;
            let uniform = n + (f - n) * t;
            let log = n * (f / n).powf(t);
            lambda * log + (1.0 - lambda) * uniform
        })
        .collect()
}

/// One cascade's box this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cascade {
    /// bias-free light projection x light view.
    pub view_projection: Mat4,
    /// The slice's view-depth range [near, far].
    pub near: f32,
    pub far: f32,
    /// A texel's width in world units.
    pub texel: f32,
}

/// The light's view: a rotation only (the eye at the origin), so that the
/// texel grid of a stable cascade is fixed in the world.
pub fn light_rotation(direction: Vec3) -> Option<Mat4> {
    let d = direction.try_normalize()?;
    let up = if d.y.abs() > 0.999 { Vec3::Z } else { Vec3::Y };
    Some(look_at(Vec3::ZERO, d, up))
}

/// The corners of the slice [a, b] of a view frustum given by its eight
/// corners (`frustum`: index bit 2 clear on the near plane, set on the far
/// plane, as `shadow::corners` orders them) whose planes lie at view depths
/// `near` and `far`: each edge from near to far is cut where the depth is a
/// and b (depth grows linearly along an edge).
pub fn slice(frustum: &[Vec3], near: f32, far: f32, a: f32, b: f32) -> [Vec3; 8] {
    let at = |i: usize, z: f32| {
        let t = ((z - near) / (far - near).max(1e-9)).clamp(0.0, 1.0);
        frustum[i & 3].lerp(frustum[(i & 3) | 4], t)
    };
    std::array::from_fn(|i| if i & 4 == 0 { at(i, a) } else { at(i, b) })
}

/// Fit cascade `[a, b]` (its corners `slice`) for a light along
/// `direction` with `resolution` texels a side. `casters` are the corners of
/// every caster's box (world). None for a zero direction or no points.
pub fn fit(
    direction: Vec3,
    slice: &[Vec3; 8],
    casters: &[Vec3],
    (a, b): (f32, f32),
    resolution: u32,
    stable: bool,
) -> Option<Cascade> {
    let view = light_rotation(direction)?;
    let res = resolution.max(2) as f32;
    let to_light =
        |p: &[Vec3]| -> Vec<Vec3> { p.iter().map(|&p| view.transform_point3(p)).collect() };
    let slice_l = to_light(slice);
    let (slo, shi) = bounds(&slice_l)?;
    let (clo, chi) = bounds(&to_light(casters)).unwrap_or((slo, shi));
    let (lo, hi, texel) = if stable {
        // The slice's bounding sphere: its size depends only on the camera's
        // projection and the split distances, not on where the camera looks.
        let centre = slice.iter().copied().sum::<Vec3>() / 8.0;
        let r = slice
            .iter()
            .map(|p| p.distance(centre))
            .fold(0.0f32, f32::max);
        // Rounded up (to 1/64 of the next power of two) so that a split
        // that moves a little keeps the same box size, and widened by a
        // texel on each side for the snapping below.
        let step = 2f32.powf(r.max(1e-6).log2().ceil()) / 64.0;
        let r = (r / step).ceil() * step * res / (res - 2.0);
        let texel = 2.0 * r / res;
        // Move the centre in whole texels of the light's fixed grid.
        let c = view.transform_point3(centre);
        let snapped = Vec3::new(
            (c.x / texel).round() * texel,
            (c.y / texel).round() * texel,
            c.z,
        );
        (snapped - Vec3::splat(r), snapped + Vec3::splat(r), texel)
    } else {
        // Tight: the slice's box, cut to the casters' where they overlap.
        let (mut lo, mut hi) = (slo, shi);
        let (nlo, nhi) = (lo.max(clo), hi.min(chi));
        if nlo.x < nhi.x && nlo.y < nhi.y {
            (lo.x, lo.y, hi.x, hi.y) = (nlo.x, nlo.y, nhi.x, nhi.y);
        }
        let m = (hi - lo).max(Vec3::splat(1e-3)) * 0.01;
        let (lo, hi) = (lo - m, hi + m);
        (lo, hi, (hi.x - lo.x).max(hi.y - lo.y) / res)
    };
    // In depth: every caster and the slice itself, with a margin.
    let zlo = clo.z.min(slo.z);
    let zhi = chi.z.max(shi.z);
    let dz = (zhi - zlo).max(1e-3) * 0.01;
    let projection = orthographic(lo.x, hi.x, lo.y, hi.y, -(zhi + dz), -(zlo - dz));
    Some(Cascade {
        view_projection: projection * view,
        near: a,
        far: b,
        texel,
    })
}

/// Every cascade of a light along `direction`: the camera's `frustum`
/// corners (near plane at view depth `near`, far plane at `far`) split
/// into `m` slices with weight `lambda` (`splits`). Cascade i + 1 is also
/// fitted around the last `blend` of cascade i's range, where the lookup
/// blends the two: without it a point in that band may lie outside the
/// next cascade's box, and read as lit there (a gap in the shadow).
#[allow(clippy::too_many_arguments)]
pub fn cascades(
    direction: Vec3,
    frustum: &[Vec3],
    (near, far): (f32, f32),
    casters: &[Vec3],
    (m, lambda, blend): (u32, f32, f32),
    resolution: u32,
    stable: bool,
) -> Option<Vec<Cascade>> {
    let z = splits(near, far, m, lambda);
    (0..m as usize)
        .map(|i| {
            let (a, b) = (z[i], z[i + 1]);
            let from = if i > 0 { a - blend * (a - z[i - 1]) } else { a };
            let s = slice(frustum, near, far, from, b);
            fit(direction, &s, casters, (a, b), resolution, stable)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::shadow::corners;

    #[test]
    fn the_three_schemes_match_zhangs_formulas() {
        let (n, f) = (1.0, 100.0);
        let u = splits(n, f, 4, 0.0);
        let l = splits(n, f, 4, 1.0);
        let p = splits(n, f, 4, 0.5);
        for i in 0..=4 {
            let t = i as f32 / 4.0;
            assert!((u[i] - (1.0 + 99.0 * t)).abs() < 1e-4);
            assert!((l[i] - 100f32.powf(t)).abs() < 1e-3);
            assert!((p[i] - 0.5 * (u[i] + l[i])).abs() < 1e-3);
        }
        // The ends are the camera's near and far, and the splits increase.
        for z in [&u, &l, &p] {
            assert!((z[0] - n).abs() < 1e-5 && (z[4] - f).abs() < 1e-3);
            assert!(z.windows(2).all(|w| w[0] < w[1]));
        }
    }

    fn frustum() -> Vec<Vec3> {
        // A camera at the origin looking down -z, 90 degrees, near 1, far 9.
        let n = [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)];
        let mut c: Vec<Vec3> = n.iter().map(|&(x, y)| Vec3::new(x, y, -1.0)).collect();
        c.extend(n.iter().map(|&(x, y)| Vec3::new(9.0 * x, 9.0 * y, -9.0)));
        c
    }

    #[test]
    fn every_slice_corner_lies_inside_its_cascade() {
        let f = frustum();
        let casters = corners(Vec3::splat(-40.0), Vec3::splat(40.0));
        for stable in [false, true] {
            let d = Vec3::new(0.3, -1.0, 0.2);
            let cs = cascades(d, &f, (1.0, 9.0), &casters, (4, 0.5, 0.0), 512, stable).unwrap();
            for c in &cs {
                let s = slice(&f, 1.0, 9.0, c.near, c.far);
                for p in s {
                    let q = c.view_projection.project_point3(p);
                    assert!(
                        q.abs().max_element() <= 1.0 + 1e-4,
                        "stable {stable}: {p} -> {q}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_stable_cascade_moves_in_whole_texels_and_keeps_its_size() {
        let f = frustum();
        let casters = corners(Vec3::splat(-30.0), Vec3::splat(30.0));
        let d = Vec3::new(0.4, -1.0, 0.1);
        let at = |shift: Vec3, stable: bool| {
            let moved: Vec<Vec3> = f.iter().map(|&p| p + shift).collect();
            cascades(d, &moved, (1.0, 9.0), &casters, (3, 0.0, 0.0), 1024, stable).unwrap()
        };
        let a = at(Vec3::ZERO, true);
        let b = at(Vec3::new(0.0123, 0.0, 0.0371), true);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(x.texel, y.texel);
            // The world origin lands on the same place within a texel in both maps:
            // the offset between the two is a whole number of texels.
            let o = |c: &Cascade| c.view_projection.project_point3(Vec3::ZERO);
            let texels = (o(x) - o(y)) * 0.5 * 1024.0;
            for v in [texels.x, texels.y] {
                assert!((v - v.round()).abs() < 2e-2, "{texels}");
            }
        }
        // A tight cascade follows the slice to a fraction of a texel.
        let a = at(Vec3::ZERO, false);
        let b = at(Vec3::new(0.0123, 0.0, 0.0371), false);
        let o = |c: &Cascade| c.view_projection.project_point3(Vec3::ZERO);
        let t = (o(&a[0]) - o(&b[0])) * 0.5 * 1024.0;
        assert!(
            (t.x - t.x.round()).abs() > 0.05 || (t.y - t.y.round()).abs() > 0.05,
            "{t}"
        );
    }
}
