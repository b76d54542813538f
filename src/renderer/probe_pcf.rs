//! The pixel probe's percentage-closer filter (notes 01 §8.5.1): the
//! kernel glsl/common/shadow.glsl's `pcf_2d` and `pcf_cube` run, redone on
//! the CPU with the same taps and weights, on depths read back from the
//! map, so that the probe says how much of the light the shader let through
//! (0 in shadow, 1 lit, between in a penumbra), not only the centre texel's
//! verdict.
//!
//! Each tap is the comparison the sampler makes (GL_LEQUAL: lit when the
//! point's depth <= the stored one): GL_NEAREST for `none`, the boxes and
//! the Poisson disc; GL_LINEAR for `hardware`, the four nearest texels'
//! comparisons blended bilinearly (GL 3.3 §3.8.16). Outside a 2D map the
//! border depth 1.0 (GL_CLAMP_TO_BORDER); a cube's tap picks its face as
//! GL does (`cube_face`) and clamps to the face's edge
//! (GL_CLAMP_TO_EDGE). A bilinear lookup within half a texel of a cube
//! face's edge is where this differs from a GPU that filters across faces
//! (GL_TEXTURE_CUBE_MAP_SEAMLESS): said in the read-out.

use crate::scene::Pcf;
use glam::{Vec2, Vec3};

/// glsl/common/shadow.glsl's `POISSON`: sixteen points of a Poisson disc
/// in the unit circle, scaled there by 2.5 texels (its digits as written).
#[allow(clippy::excessive_precision)]
const POISSON: [[f32; 2]; 16] = [
    [-0.942_016_24, -0.399_062_16],
    [0.945_586_09, -0.768_907_25],
    [-0.094_184_1, -0.929_388_7],
    [0.344_959_38, 0.293_877_6],
    [-0.915_885_81, 0.457_714_32],
    [-0.815_442_32, -0.879_124_64],
    [-0.382_775_43, 0.276_768_45],
    [0.974_843_98, 0.756_483_79],
    [0.443_233_25, -0.975_115_54],
    [0.537_429_81, -0.473_734_2],
    [-0.264_969_11, -0.418_930_23],
    [0.791_975_14, 0.190_901_88],
    [-0.241_888_4, 0.997_065_07],
    [-0.814_099_55, 0.914_375_9],
    [0.199_841_26, 0.786_413_67],
    [0.143_831_61, -0.141_007_9],
];

/// The filtered visibility and how it was found.
#[derive(Clone, Debug, PartialEq)]
pub struct Filtered {
    /// The kernel's average of its taps' comparisons, 0..1.
    pub visibility: f32,
    /// How many comparisons it averaged (a bilinear tap counts its four).
    pub taps: usize,
    /// A bilinear cube lookup near a face's edge: the GPU may blend texels
    /// of the next face there, this filter clamps to the face.
    pub near_face_edge: bool,
}

/// The offsets of `pcf`'s taps in texels, each with its weight, and whether
/// each tap is bilinear (GL_LINEAR) rather than one texel (GL_NEAREST).
pub fn taps(pcf: Pcf) -> (Vec<(Vec2, f32)>, bool) {
    let boxed = |r: i32| {
        let n = ((2 * r + 1) * (2 * r + 1)) as f32;
        let mut v = Vec::new();
        for y in -r..=r {
            for x in -r..=r {
                v.push((Vec2::new(x as f32, y as f32), 1.0 / n));
            }
        }
        v
    };
    match pcf {
        Pcf::None => (vec![(Vec2::ZERO, 1.0)], false),
        Pcf::Hardware => (vec![(Vec2::ZERO, 1.0)], true),
        Pcf::Box3 => (boxed(1), false),
        Pcf::Box5 => (boxed(2), false),
        Pcf::Poisson => (
            POISSON
                .iter()
                .map(|p| (Vec2::from(*p) * 2.5, 1.0 / 16.0))
                .collect(),
            false,
        ),
    }
}

/// The filter on a 2D map of `res` texels a side at texture coordinate
/// `c` (uv, and the depth compared), reading texels with `stored(x, y)`.
pub fn filter_2d(pcf: Pcf, c: Vec3, res: u32, stored: &mut dyn FnMut(i64, i64) -> f32) -> Filtered {
    let (kernel, linear) = taps(pcf);
    let texel = 1.0 / res as f32;
    let n = res as i64;
    // Outside the map: the border's 1.0.
    let mut at = |x: i64, y: i64| {
        if x < 0 || y < 0 || x >= n || y >= n {
            1.0
        } else {
            stored(x, y)
        }
    };
    let mut visibility = 0.0;
    let mut taps = 0;
    for (offset, weight) in kernel {
        let uv = Vec2::new(c.x, c.y) + offset * texel;
        let (v, t) = lookup(uv, c.z, res, linear, &mut at);
        visibility += weight * v;
        taps += t;
    }
    Filtered {
        visibility,
        taps,
        near_face_edge: false,
    }
}

/// The filter on a cube map of `res` texels a side, looking along `d` (from
/// the light) with compared distance `reference`; `texel` is one texel at
/// unit distance along a face's axis (2 / res). `stored(face, x, y)`.
pub fn filter_cube(
    pcf: Pcf,
    d: Vec3,
    reference: f32,
    res: u32,
    texel: f32,
    stored: &mut dyn FnMut(usize, i64, i64) -> f32,
) -> Filtered {
    let (kernel, linear) = taps(pcf);
    // The shader's tangents: across the face that d points into.
    let a = d.abs();
    let major = a.max_element();
    let u = if a.x == major { Vec3::Y } else { Vec3::X };
    let v = if a.z == major { Vec3::Y } else { Vec3::Z };
    let step = texel * major;
    let n = res as i64;
    let mut visibility = 0.0;
    let mut taps = 0;
    let mut near_face_edge = false;
    for (offset, weight) in kernel {
        // A box or disc tap: d moved across the face (the none and
        // hardware kernels have the one tap at d).
        let dir = if offset == Vec2::ZERO {
            d
        } else {
            d + (offset.x * u + offset.y * v) * step
        };
        let (face, uv) = cube_face(dir);
        if linear {
            let half = 0.5 / res as f32;
            near_face_edge |= uv.min_element() < half || uv.max_element() > 1.0 - half;
        }
        let mut at = |x: i64, y: i64| stored(face, x.clamp(0, n - 1), y.clamp(0, n - 1));
        let (s, t) = lookup(uv, reference, res, linear, &mut at);
        visibility += weight * s;
        taps += t;
    }
    Filtered {
        visibility,
        taps,
        near_face_edge,
    }
}

/// The cube face direction `d` points into and where on it (s, t in
/// 0..1), as GL picks them (GL 3.3 §3.8.10, table 3.21).
pub fn cube_face(d: Vec3) -> (usize, Vec2) {
    let a = d.abs();
    let (face, sc, tc, ma) = if a.x >= a.y && a.x >= a.z {
        if d.x >= 0.0 {
            (0, -d.z, -d.y, a.x)
        } else {
            (1, d.z, -d.y, a.x)
        }
    } else if a.y >= a.z {
        if d.y >= 0.0 {
            (2, d.x, d.z, a.y)
        } else {
            (3, d.x, -d.z, a.y)
        }
    } else if d.z >= 0.0 {
        (4, d.x, -d.y, a.z)
    } else {
        (5, -d.x, -d.y, a.z)
    };
    let ma = ma.max(1e-20);
    (
        face,
        Vec2::new(0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)),
    )
}

/// One sampler lookup with comparison at `uv`: the texel it falls in
/// (GL_NEAREST), or the bilinear blend of the four around it (GL_LINEAR).
/// Returns the result and the comparisons made.
fn lookup(
    uv: Vec2,
    reference: f32,
    res: u32,
    linear: bool,
    at: &mut dyn FnMut(i64, i64) -> f32,
) -> (f32, usize) {
    let lit = |stored: f32| if reference <= stored { 1.0 } else { 0.0 };
    let p = uv * res as f32;
    if !linear {
        return (lit(at(p.x.floor() as i64, p.y.floor() as i64)), 1);
    }
    let p = p - Vec2::splat(0.5);
    let (i, j) = (p.x.floor() as i64, p.y.floor() as i64);
    let (a, b) = (p.x - p.x.floor(), p.y - p.y.floor());
    let v = (1.0 - a) * (1.0 - b) * lit(at(i, j))
        + a * (1.0 - b) * lit(at(i + 1, j))
        + (1.0 - a) * b * lit(at(i, j + 1))
        + a * b * lit(at(i + 1, j + 1));
    (v, 4)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kernels_weights_add_up_to_one() {
        for pcf in Pcf::ALL {
            let (k, _) = taps(pcf);
            let sum: f32 = k.iter().map(|(_, w)| w).sum();
            assert!((sum - 1.0).abs() < 1e-6, "{pcf:?}: {sum}");
        }
        assert_eq!(taps(Pcf::Box5).0.len(), 25);
    }

    #[test]
    fn an_edge_half_across_a_texel_is_half_lit_bilinearly() {
        // Texels x < 4 hold 0.2 (a caster), the rest 1.0; the point at
        // depth 0.5 sits on the boundary between texel 3 and 4's centres.
        let mut stored = |x: i64, _: i64| if x < 4 { 0.2 } else { 1.0 };
        let res = 8;
        let c = Vec3::new(4.0 / 8.0, 0.5, 0.5);
        let f = filter_2d(Pcf::Hardware, c, res, &mut stored);
        assert!((f.visibility - 0.5).abs() < 1e-6, "{f:?}");
        // Nearest: texel 4, lit. A 3x3 box: two of three columns lit.
        assert_eq!(filter_2d(Pcf::None, c, res, &mut stored).visibility, 1.0);
        let b = filter_2d(Pcf::Box3, c, res, &mut stored).visibility;
        assert!((b - 2.0 / 3.0).abs() < 1e-6, "{b}");
        // Past the map's edge: the border's 1.0, lit.
        let out = Vec3::new(-0.5, 0.5, 0.9);
        let v = filter_2d(Pcf::Box5, out, res, &mut stored).visibility;
        assert!((v - 1.0).abs() < 1e-6, "{v}");
    }
}
