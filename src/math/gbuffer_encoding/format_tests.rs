//! The formats' quantisation against IEEE half floats and 8-bit UNORM.

use super::*;

#[test]
fn half_float_rounding_matches_ieee() {
    assert_eq!(quantise_f16(1.0), 1.0);
    // Ties go to the even significand: 1 + 2^-11 to 1, 1 + 3 2^-11 to 1 + 2^-9.
    assert_eq!(quantise_f16(1.0 + 1.0 / 2048.0), 1.0);
    assert_eq!(quantise_f16(1.0 + 3.0 / 2048.0), 1.0 + 1.0 / 512.0);
    assert_eq!(quantise_f16(1.0 + 1.1 / 2048.0), 1.0 + 1.0 / 1024.0);
    assert_eq!(quantise_f16(0.1), 0.0999755859375);
    assert_eq!(quantise_f16(-0.1), -0.0999755859375);
    assert_eq!(quantise_f16(1e-3), 0.0010004043579101562);
    assert_eq!(quantise_f16(1.0 / 3.0), 0.333251953125);
    // The top: 65504 is the largest; from 65520 (the tie) up, infinity.
    assert_eq!(quantise_f16(F16_MAX), F16_MAX);
    assert_eq!(quantise_f16(65519.99), F16_MAX);
    assert_eq!(quantise_f16(65520.0), f64::INFINITY);
    assert_eq!(quantise_f16(-1e6), f64::NEG_INFINITY);
    // The subnormals, 2^-24 apart.
    let tiny = 2f64.powi(-24);
    assert_eq!(quantise_f16(tiny), tiny);
    assert_eq!(quantise_f16(tiny / 2.0), 0.0);
    assert_eq!(quantise_f16(1.5 * tiny), 2.0 * tiny);
    assert_eq!(quantise_f16(F16_MIN_NORMAL - tiny / 4.0), F16_MIN_NORMAL);
    assert!(quantise_f16(f64::NAN).is_nan());
    assert_eq!(quantise_f16(f64::INFINITY), f64::INFINITY);
    // Anywhere in the normal range: 11 significant bits, at most half a step off.
    for i in 0..=20_000 {
        let x = 2f64.powf(-14.0 + 29.9 * i as f64 / 20_000.0);
        let q = quantise_f16(x);
        let ulp = 2f64.powi(x.log2().floor() as i32 - 10);
        assert!((q - x).abs() <= ulp / 2.0, "{x}: {q}");
        assert_eq!((q / ulp).fract(), 0.0, "{x}: {q}");
    }
}

#[test]
fn unorm8_rounds_to_the_nearest_step_and_clamps() {
    assert_eq!(quantise_unorm8(0.5), 128.0 / 255.0);
    assert_eq!(quantise_unorm8(1.0), 1.0);
    assert_eq!(quantise_unorm8(1.2), 1.0);
    assert_eq!(quantise_unorm8(-0.3), 0.0);
    assert_eq!(quantise_unorm8(f64::NAN), 0.0);
    assert_eq!(quantise_unorm8(0.99 / 510.0), 0.0);
    assert_eq!(quantise_unorm8(1.01 / 510.0), 1.0 / 255.0);
}
