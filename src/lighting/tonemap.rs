//! The post chain's per-pixel curves on the CPU: the tone-mapping operators
//! of glsl/post/tone_mapping.frag and the gamma curve of
//! glsl/post/gamma_correction.frag, written once more so that tests can
//! compare the rendered pixels with them (sRGB is `super::srgb_encode`).

use crate::scene::post::ToneOperator;

/// `operator` applied to `exposure * c` (one channel of linear light).
pub fn tonemap(operator: ToneOperator, exposure: f32, c: f32) -> f32 {
    let x = exposure * c.max(0.0);
    match operator {
        ToneOperator::Clamp => x.min(1.0),
        ToneOperator::Reinhard => x / (1.0 + x),
        ToneOperator::Exposure => 1.0 - (-x).exp(),
        ToneOperator::Aces => {
            ((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)).clamp(0.0, 1.0)
        }
    }
}

/// The gamma pass's curve: `pow(c, 1 / gamma)` of `c` clamped to 0..1.
pub fn gamma_encode(gamma: f32, c: f32) -> f32 {
    c.clamp(0.0, 1.0).powf(1.0 / gamma)
}

/// Rec. 709 luminance of linear light (the grayscale filter).
pub fn luminance(rgb: [f32; 3]) -> f32 {
    0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_operator_maps_zero_to_zero_and_rises() {
        for op in ToneOperator::ALL {
            assert!(tonemap(op, 1.0, 0.0).abs() < 1e-6, "{op:?}");
            let mut last = 0.0;
            for i in 1..200 {
                let y = tonemap(op, 1.0, i as f32 * 0.1);
                assert!(y >= last && y <= 1.0, "{op:?} at {}", i as f32 * 0.1);
                last = y;
            }
        }
        // Reinhard of 1 is one half; the exposure curve of ln 2 is one half.
        assert!((tonemap(ToneOperator::Reinhard, 1.0, 1.0) - 0.5).abs() < 1e-7);
        assert!((tonemap(ToneOperator::Exposure, 1.0, 2f32.ln()) - 0.5).abs() < 1e-7);
        // The ACES fit's shoulder saturates below x = 20; at x = 1 it is
        // (2.51 + 0.03) / (2.43 + 0.59 + 0.14), worked by hand.
        assert_eq!(tonemap(ToneOperator::Aces, 1.0, 20.0), 1.0);
        assert!((tonemap(ToneOperator::Aces, 1.0, 1.0) - 2.54 / 3.16).abs() < 1e-6);
    }

    #[test]
    fn gamma_one_is_the_identity_and_2_2_brightens_the_mid_tones() {
        assert!((gamma_encode(1.0, 0.37) - 0.37).abs() < 1e-7);
        assert!((gamma_encode(2.2, 0.5) - 0.72974).abs() < 1e-4);
        assert_eq!(gamma_encode(2.2, 7.0), 1.0);
        assert_eq!(gamma_encode(2.2, -1.0), 0.0);
    }
}
