//! Where bloom's four blurs run and with which taps (notes 03, "Blur Pass
//! and Merge Pass"), decided on the CPU from the settings and the image's
//! size: the plan prints it, the passes upload it, the tests check it.
//!
//! The notes' scheme: blur k (k = 1..4) in mip level k of one texture
//! (`BLOOM_LEVELS`), 2^k full-resolution pixels a texel. Its sigma and radius are
//! in full-resolution pixels, so in level-k texels the kernel is
//! sigma_k = sqrt(sigma² - (2^(k-1))²) / 2^k, where 2^(k-1) is the blur
//! that going down to level k and back up already adds
//! (`math::gaussian::resample_sigma`), and its radius is cut at the same
//! number of sigmas as the notes' (`math::gaussian::level_kernel`).
//!
//! An image too small for a level (a 3x2 image has only level 1, a 1x1 none)
//! skips that blur, and the merge reads the last level that exists in its
//! place ("clamped", as GL clamps a texture's LOD); with none, the original.

use crate::gl::texture::{level_size, max_level};
use crate::math::gaussian::{Kernel, direct_taps, level_kernel, linear_taps};
use crate::scene::bloom::{Bloom, BloomScheme};
use crate::scene::post::Taps;

/// The notes' "tempbuffer2 (mipmaps)": blur k in level k.
pub const BLOOM_LEVELS: &str = "bloom_levels";
/// Each level's horizontal pass, before the vertical one writes `BLOOM`.
pub const BLOOM_TEMP: &str = "bloom_temp";
/// The full-resolution scheme's four blurs, each its own texture.
pub const BLOOM_FULL: [&str; 4] = ["bloom_full1", "bloom_full2", "bloom_full3", "bloom_full4"];
/// The full-resolution scheme's horizontal pass.
pub const BLOOM_FULL_TEMP: &str = "bloom_full_temp";
/// The notes' deepest level.
pub const DEEPEST: u32 = 4;

/// One blur as it runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Blur {
    /// 0..4: blur1 .. blur4.
    pub index: usize,
    /// The mip level it runs in (0: full resolution).
    pub level: u32,
    /// Its size there.
    pub size: (i32, i32),
    /// The target its result is in, and the one its horizontal pass writes.
    pub target: &'static str,
    pub temp: &'static str,
    /// Its kernel, in level texels.
    pub kernel: Kernel,
    /// One side's (offset, weight) taps, the centre first.
    pub taps: Vec<(f64, f64)>,
    /// Linear taps (bilinear fetches between texels), else direct.
    pub linear: bool,
}

impl Blur {
    /// Full-resolution pixels per texel of its level, each way.
    pub fn block(&self) -> u32 {
        1 << self.level
    }
}

/// The last mip level the notes' scheme uses at `width` x `height` (at most
/// 4; 0 when the image has no level below full size).
pub fn last_level(width: i32, height: i32) -> u32 {
    max_level(width, height).min(DEEPEST)
}

/// The blurs that run for `b` on a `width` x `height` image, in order.
pub fn blurs(b: &Bloom, width: i32, height: i32) -> Vec<Blur> {
    let last = last_level(width, height);
    (0..4)
        .filter_map(|i| {
            let l = b.levels[i];
            let (level, target, temp, kernel) = match b.scheme {
                BloomScheme::Mips => {
                    let level = i as u32 + 1;
                    if level > last {
                        return None;
                    }
                    (
                        level,
                        BLOOM_LEVELS,
                        BLOOM_TEMP,
                        level_kernel(l.sigma, l.radius, level),
                    )
                }
                BloomScheme::Full => (
                    0,
                    BLOOM_FULL[i],
                    BLOOM_FULL_TEMP,
                    Kernel::gaussian(l.sigma, l.radius),
                ),
            };
            let cut = (f64::from(kernel.radius) * b.radius_scale).ceil() as u32;
            let kernel = kernel.cut(cut.max(1));
            let taps = match b.taps {
                Taps::Direct => direct_taps(&kernel),
                Taps::Linear => linear_taps(&kernel),
            };
            Some(Blur {
                index: i,
                level,
                size: level_size(width, height, level),
                target,
                temp,
                kernel,
                taps,
                linear: b.taps == Taps::Linear,
            })
        })
        .collect()
}

/// What the merge reads for blur i: the blur itself, the last one that ran
/// in its place when its level does not exist, or None (no blur ran: the
/// original stands in).
pub fn merge_source(blurs: &[Blur], i: usize) -> Option<&Blur> {
    blurs.iter().find(|b| b.index == i).or(blurs.last())
}

/// "level 2 (320x180): sigma 6.21 texels, radius 20, 21 direct taps", for the plan.
pub fn describe(b: &Blur) -> String {
    let where_ = if b.level == 0 {
        format!("full resolution ({}x{})", b.size.0, b.size.1)
    } else {
        format!("level {} ({}x{})", b.level, b.size.0, b.size.1)
    };
    format!(
        "{where_}: sigma {:.2} texels, radius {}, {} {} taps a side",
        b.kernel.sigma,
        b.kernel.radius,
        b.taps.len(),
        if b.linear { "linear" } else { "direct" }
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::gaussian::resample_sigma;

    #[test]
    fn the_notes_scheme_puts_blur_k_in_level_k_and_keeps_sigma_in_pixels() {
        let b = Bloom::default();
        let v = blurs(&b, 1280, 720);
        assert_eq!(v.len(), 4);
        let sizes: Vec<(i32, i32)> = v.iter().map(|x| x.size).collect();
        assert_eq!(sizes, [(640, 360), (320, 180), (160, 90), (80, 45)]);
        for (x, l) in v.iter().zip(b.levels) {
            let pixels = f64::from(x.block()) * x.kernel.sigma;
            let total = (pixels * pixels + resample_sigma(x.level).powi(2)).sqrt();
            assert!((total - l.sigma).abs() < 1e-9);
        }
    }

    #[test]
    fn small_images_have_fewer_levels_and_the_merge_clamps() {
        let b = Bloom::default();
        assert_eq!(last_level(3, 2), 1);
        assert_eq!(last_level(1, 1), 0);
        assert_eq!(last_level(17, 1), 4);
        let v = blurs(&b, 3, 2);
        assert_eq!(v.len(), 1);
        assert_eq!(v[0].size, (1, 1));
        assert_eq!(merge_source(&v, 3).map(|x| x.index), Some(0));
        assert!(blurs(&b, 1, 1).is_empty());
        assert!(merge_source(&[], 0).is_none());
    }

    #[test]
    fn fewer_taps_and_linear_taps() {
        let b = Bloom {
            taps: Taps::Linear,
            radius_scale: 0.5,
            ..Bloom::default()
        };
        let full = blurs(&Bloom::default(), 1280, 720);
        let cut = blurs(&b, 1280, 720);
        for (f, c) in full.iter().zip(&cut) {
            assert_eq!(c.kernel.radius, f.kernel.radius.div_ceil(2));
            assert_eq!(c.taps.len(), 1 + (c.kernel.radius as usize).div_ceil(2));
        }
        let full_res = blurs(
            &Bloom {
                scheme: BloomScheme::Full,
                ..Bloom::default()
            },
            64,
            64,
        );
        assert_eq!(full_res[3].kernel.radius, 799);
        assert_eq!(full_res[3].size, (64, 64));
    }
}
