//! The CPU twins of texture sampling (notes 01 §5): what GL does with a
//! texture coordinate outside [0, 1] (clamp, repeat, mirror), bilinear
//! filtering of neighbouring texels (§5.2), and the level of detail lambda
//! that picks a mip level (§5.3). The tests hold the GPU to these.

/// What a coordinate outside [0, 1] reads (notes 01 §5, "Clamp", "Repeat",
/// "Mirror"; GL_CLAMP_TO_EDGE, GL_REPEAT, GL_MIRRORED_REPEAT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WrapRule {
    Clamp,
    Repeat,
    Mirror,
}

/// The notes' rule on a normalised coordinate: clamp 1.1 -> 1, repeat
/// 1.1 -> 0.1 and -0.1 -> 0.9, mirror 1.1 -> 0.9 and -0.1 -> 0.1.
pub fn wrap_coordinate(u: f64, rule: WrapRule) -> f64 {
    match rule {
        WrapRule::Clamp => u.clamp(0.0, 1.0),
        WrapRule::Repeat => u - u.floor(),
        WrapRule::Mirror => {
            let m = u.rem_euclid(2.0);
            if m > 1.0 { 2.0 - m } else { m }
        }
    }
}

/// The texel a whole texel index `i` (possibly outside 0..width) reads
/// under `rule`, as GL 3.3 §3.8.10 wraps it: clamp to the edge texel,
/// repeat modulo the width, mirror every other width.
pub fn wrap_texel(i: i64, width: usize, rule: WrapRule) -> usize {
    let w = width.max(1) as i64;
    let k = match rule {
        WrapRule::Clamp => i.clamp(0, w - 1),
        WrapRule::Repeat => i.rem_euclid(w),
        WrapRule::Mirror => {
            let m = i.rem_euclid(2 * w);
            if m >= w { 2 * w - 1 - m } else { m }
        }
    };
    k as usize
}

/// Nearest filtering: the texel under normalised coordinate `u`, floor(u w) wrapped.
pub fn nearest_texel(u: f64, width: usize, rule: WrapRule) -> usize {
    wrap_texel((u * width as f64).floor() as i64, width, rule)
}

/// Bilinear filtering along one axis (notes 01 §5.2): at texel coordinate
/// x (texel i's centre is at x = i, so x = u w - 1/2), blend texels
/// floor(x) and floor(x) + 1 by the fraction of x: the notes' "7.6 blends
/// texels 7 and 8 by 0.6" is 0.4 t7 + 0.6 t8.
pub fn linear_1d(texels: &[f64], u: f64, rule: WrapRule) -> f64 {
    let x = u * texels.len() as f64 - 0.5;
    let i = x.floor();
    let a = x - i;
    let t = |k: i64| texels[wrap_texel(k, texels.len(), rule)];
    (1.0 - a) * t(i as i64) + a * t(i as i64 + 1)
}

/// The level of detail (notes 01 §5.3; GL 3.3 §3.8.11): lambda = log2 rho,
/// where rho is the longer of the two screen axes' steps in texels:
/// rho = max(|(w du/dx, h dv/dx)|, |(w du/dy, h dv/dy)|).
pub fn lod(du_dx: f64, dv_dx: f64, du_dy: f64, dv_dy: f64, width: f64, height: f64) -> f64 {
    let x = (width * du_dx).hypot(height * dv_dx);
    let y = (width * du_dy).hypot(height * dv_dy);
    x.max(y).log2()
}

/// The level GL_NEAREST_MIPMAP_NEAREST reads at `lambda` (GL 3.3
/// §3.8.11): level 0 up to lambda = 1/2, then ceil(lambda + 1/2) - 1,
/// never past the last level.
pub fn nearest_level(lambda: f64, last: u32) -> u32 {
    if lambda <= 0.5 {
        0
    } else {
        ((lambda + 0.5).ceil() - 1.0).min(last as f64) as u32
    }
}

/// The two levels GL_LINEAR_MIPMAP_LINEAR (trilinear) reads at a positive
/// `lambda` and the weight of the second (GL 3.3 §3.8.11): levels
/// floor(lambda) and the next, mixed by lambda's fraction; at or past the
/// last level, the last alone. GL_LINEAR_MIPMAP_NEAREST (bilinear_mip)
/// reads `nearest_level` alone.
pub fn linear_levels(lambda: f64, last: u32) -> (u32, u32, f64) {
    let lambda = lambda.max(0.0);
    if lambda >= last as f64 {
        return (last, last, 0.0);
    }
    let d1 = lambda.floor();
    (d1 as u32, d1 as u32 + 1, lambda - d1)
}

/// Bytes of a full mip chain of a `width` x `height` texture at
/// `bytes_per_texel`: every level down to 1 x 1 (about 4/3 of level 0).
pub fn mip_chain_bytes(width: u32, height: u32, bytes_per_texel: u32) -> u64 {
    let (mut w, mut h) = (width.max(1) as u64, height.max(1) as u64);
    let mut total = 0;
    loop {
        total += w * h * bytes_per_texel as u64;
        if w == 1 && h == 1 {
            return total;
        }
        w = (w / 2).max(1);
        h = (h / 2).max(1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_notes_wrap_examples() {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(wrap_coordinate(1.1, WrapRule::Repeat), 0.1));
        assert!(close(wrap_coordinate(-0.1, WrapRule::Repeat), 0.9));
        assert!(close(wrap_coordinate(1.1, WrapRule::Mirror), 0.9));
        assert!(close(wrap_coordinate(-0.1, WrapRule::Mirror), 0.1));
        assert_eq!(wrap_coordinate(1.1, WrapRule::Clamp), 1.0);
        assert_eq!(wrap_coordinate(-0.1, WrapRule::Clamp), 0.0);
        // On texels of a 10-wide texture: texel 11 of repeat is texel 1, of
        // mirror texel 8; texel -1 is 9 and 0.
        assert_eq!(nearest_texel(1.15, 10, WrapRule::Repeat), 1);
        assert_eq!(nearest_texel(1.15, 10, WrapRule::Mirror), 8);
        assert_eq!(nearest_texel(1.15, 10, WrapRule::Clamp), 9);
        assert_eq!(nearest_texel(-0.05, 10, WrapRule::Repeat), 9);
        assert_eq!(nearest_texel(-0.05, 10, WrapRule::Mirror), 0);
        assert_eq!(nearest_texel(-0.05, 10, WrapRule::Clamp), 0);
    }

    #[test]
    fn bilinear_blends_texels_7_and_8_by_0_6_at_7_6() {
        let texels: Vec<f64> = (0..16).map(|i| (i * i) as f64).collect();
        let u = (7.6 + 0.5) / 16.0;
        let v = linear_1d(&texels, u, WrapRule::Clamp);
        assert!((v - (0.4 * 49.0 + 0.6 * 64.0)).abs() < 1e-9, "{v}");
    }

    #[test]
    fn lod_and_the_level_it_picks() {
        // One texel a pixel is lambda 0; four texels a pixel, lambda 2.
        assert_eq!(lod(1.0 / 256.0, 0.0, 0.0, 1.0 / 256.0, 256.0, 256.0), 0.0);
        assert_eq!(lod(4.0 / 256.0, 0.0, 0.0, 1.0 / 256.0, 256.0, 256.0), 2.0);
        assert_eq!(nearest_level(0.5, 8), 0);
        assert_eq!(nearest_level(0.51, 8), 1);
        assert_eq!(nearest_level(1.5, 8), 1);
        assert_eq!(nearest_level(1.51, 8), 2);
        assert_eq!(nearest_level(40.0, 8), 8);
        assert_eq!(mip_chain_bytes(256, 256, 4), 4 * 87381);
        assert_eq!(mip_chain_bytes(1, 1, 4), 4);
        assert_eq!(mip_chain_bytes(4, 1, 1), 4 + 2 + 1);
    }

    #[test]
    fn trilinear_reads_the_two_levels_around_lambda() {
        assert_eq!(linear_levels(2.25, 8), (2, 3, 0.25));
        assert_eq!(linear_levels(0.75, 8), (0, 1, 0.75));
        assert_eq!(linear_levels(-1.0, 8), (0, 1, 0.0));
        assert_eq!(linear_levels(7.5, 8), (7, 8, 0.5));
        assert_eq!(linear_levels(8.0, 8), (8, 8, 0.0));
        assert_eq!(linear_levels(30.0, 8), (8, 8, 0.0));
    }
}
