//! Normal maps baked on the CPU from a height field (notes 01 §8.4: "surface
//! texture stored in bump map (texture) in tangent space"). The asset
//! generator bakes scenes/assets/bricks-normal.png with it, and the tests
//! bake a known height field to hold the GPU's TBN lighting to the analytic
//! normal.

use glam::DVec3;

/// The tangent-space normal of a height field with slopes dh/du and dh/dv
/// (heights in the same units as u and v): normalize(-dh/du, -dh/dv, 1). T
/// is +u, B is +v, N is out of the surface.
pub fn tangent_normal(dh_du: f64, dh_dv: f64) -> DVec3 {
    DVec3::new(-dh_du, -dh_dv, 1.0).normalize()
}

/// A unit normal stored as 8-bit RGB: (n + 1) / 2, rounded.
pub fn encode(n: DVec3) -> [u8; 3] {
    [n.x, n.y, n.z].map(|c| ((c + 1.0) * 0.5 * 255.0).round().clamp(0.0, 255.0) as u8)
}

/// A `width` x `height` tangent-space normal map of the height field `h(u,
/// v)` (u, v in [0, 1], heights in uv units), the slopes taken by central
/// differences one texel apart at each texel's centre. Rows run as an image
/// file stores them: the first row is the top, v = 1 (the loader flips it
/// for GL).
pub fn bake_normal_map(width: u32, height: u32, h: impl Fn(f64, f64) -> f64) -> Vec<[u8; 3]> {
    let (du, dv) = (1.0 / f64::from(width), 1.0 / f64::from(height));
    let mut out = Vec::with_capacity((width * height) as usize);
    for row in 0..height {
        let v = 1.0 - (f64::from(row) + 0.5) * dv;
        for x in 0..width {
            let u = (f64::from(x) + 0.5) * du;
            let dh_du = (h(u + du, v) - h(u - du, v)) / (2.0 * du);
            let dh_dv = (h(u, v + dv) - h(u, v - dv)) / (2.0 * dv);
            out.push(encode(tangent_normal(dh_du, dh_dv)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_field_is_the_flat_normal_and_slopes_tilt_it() {
        let flat = bake_normal_map(4, 4, |_, _| 0.25);
        assert!(flat.iter().all(|&t| t == [128, 128, 255]));
        // h = 0.5 u: the surface rises along +u, its normal leans to -u.
        let ramp = bake_normal_map(4, 4, |u, _| 0.5 * u);
        let n = tangent_normal(0.5, 0.0);
        assert!(ramp.iter().all(|&t| t == encode(n)));
        assert!(n.x < 0.0 && n.y == 0.0);
        // The first row is the top (v near 1): h = v rises upwards, so the
        // normal leans to -v on every row.
        let up = bake_normal_map(2, 3, |_, v| v);
        assert!(up.iter().all(|t| t[1] < 128));
    }
}
