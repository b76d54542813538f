//! Point-light attenuation and the light-volume radius (notes 04, "Calculate
//! volume radius of point light" and "Calculating radius").
//!
//! The notes attenuate a light of intensity `I` at distance `d` as
//!
//! ```text
//! F = I / (Kc + Kl d + Kq d^2)
//! ```
//!
//! and bound each point light by a sphere whose radius is the distance where
//! the attenuated brightest channel falls to a cutoff (5/256 in the notes):
//!
//! ```text
//! Kq d^2 + Kl d + (Kc - Imax / cutoff) = 0
//! ```
//!
//! The notes solve this with the textbook root
//! `(-Kl + sqrt(Kl^2 - 4 Kq c)) / (2 Kq)`, which subtracts two nearly equal
//! numbers when `Kq` is small (and divides by zero when `Kq = 0`). Here the
//! same root is computed as `2|c| / (Kl + sqrt(Kl^2 + 4 Kq |c|))`, which only
//! adds positive numbers; [`notes_radius`] keeps the notes' version for the
//! comparison table in docs.

use crate::scene::validate_attenuation;

/// The notes' default light-volume cutoff: 5/256 of the light's brightest
/// channel.
pub const NOTES_CUTOFF: f32 = 5.0 / 256.0;
/// The notes' default constant attenuation (the `1` in `calculateRadius`).
pub const NOTES_KC: f32 = 1.0;
/// The notes' default linear attenuation (`linear_att = 0.09f`).
pub const NOTES_KL: f32 = 0.09;
/// The notes' default quadratic attenuation (`quadratic_att = 0.032f`).
pub const NOTES_KQ: f32 = 0.032;

/// The attenuation factor `1 / (Kc + Kl d + Kq d^2)` at distance `d`.
///
/// Multiply by the light's intensity to get the notes' `F_light`. Inputs are
/// not checked (the scene loader checks them with [`validate_attenuation`]); a zero denominator gives
/// `+inf`, as IEEE division does.
pub fn attenuation(kc: f32, kl: f32, kq: f32, d: f32) -> f32 {
    1.0 / (kc + kl * d + kq * d * d)
}

/// Radius of a point light's volume: the distance `d >= 0` at which
/// `i_max * attenuation(kc, kl, kq, d) == cutoff`.
///
/// - `Some(r)`, `r > 0`: draw a sphere of radius `r`.
/// - `Some(0.0)`: the light is never brighter than the cutoff (`Kc >= i_max /
///   cutoff`, including `i_max == 0`); it contributes nothing anywhere. This is
///   checked first, so it also holds when `Kl = Kq = 0`.
/// - `None`: no finite volume, because `Kl = Kq = 0` (constant attenuation
///   never falls to the cutoff) or the radius overflows `f32`; the caller
///   lights it with a full-screen quad like a directional light. `None` is
///   also returned for invalid input (negative, NaN or infinite coefficients,
///   `i_max` negative or not finite, `cutoff` not a finite positive number):
///   reject those earlier with [`validate_attenuation`].
///
/// Computed in `f64` with the cancellation-free root
/// `2|c| / (Kl + sqrt(Kl^2 + 4 Kq |c|))`, `c = Kc - i_max / cutoff`, which is
/// `|c| / Kl` when `Kq = 0`.
pub fn light_volume_radius(kc: f32, kl: f32, kq: f32, i_max: f32, cutoff: f32) -> Option<f32> {
    if validate_attenuation(kc, kl, kq).is_err()
        || !i_max.is_finite()
        || i_max < 0.0
        || !cutoff.is_finite()
        || cutoff <= 0.0
    {
        return None;
    }
    let (kc, kl, kq) = (f64::from(kc), f64::from(kl), f64::from(kq));
    let c = kc - f64::from(i_max) / f64::from(cutoff);
    if c >= 0.0 {
        return Some(0.0);
    }
    let a = -c;
    let denom = kl + (kl * kl + 4.0 * kq * a).sqrt();
    if denom <= 0.0 {
        // Kl = Kq = 0: the attenuation is the constant 1/Kc.
        return None;
    }
    let d = (2.0 * a / denom) as f32;
    d.is_finite().then_some(d)
}

/// The notes' `calculateRadius`, verbatim in `f32` (generalised from the
/// hard-coded `Kc = 1` and `256/5` to `kc` and `1/cutoff`):
/// `(-Kl + sqrt(Kl^2 - 4 Kq (Kc - i_max / cutoff))) / (2 Kq)`.
///
/// Kept only to document its failure: it cancels catastrophically for small
/// `Kq` and is NaN or infinite for `Kq = 0`. Use [`light_volume_radius`].
pub fn notes_radius(kc: f32, kl: f32, kq: f32, i_max: f32, cutoff: f32) -> f32 {
    (-kl + (kl * kl - 4.0 * kq * (kc - i_max / cutoff)).sqrt()) / (2.0 * kq)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    /// Independent reference: bisection in f64 on the attenuation equation
    /// `Kc + Kl d + Kq d^2 = i_max / cutoff` (monotonic for d >= 0), using the
    /// same f32 inputs widened to f64.
    fn bisect_radius(kc: f32, kl: f32, kq: f32, i_max: f32, cutoff: f32) -> f64 {
        let (kc, kl, kq) = (f64::from(kc), f64::from(kl), f64::from(kq));
        let target = f64::from(i_max) / f64::from(cutoff);
        let g = |d: f64| kc + kl * d + kq * d * d - target;
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        while g(hi) < 0.0 {
            hi *= 2.0;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if g(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    #[test]
    fn notes_defaults_match_hand_value() {
        // (-0.09 + sqrt(0.09^2 + 4 * 0.032 * 50.2)) / (2 * 0.032)
        let hand = 38.226_155_163_735_65_f64;
        let r = light_volume_radius(NOTES_KC, NOTES_KL, NOTES_KQ, 1.0, NOTES_CUTOFF).unwrap();
        assert!(rel(f64::from(r), hand) < 1e-5, "r = {r}");
        // The notes' formula is fine here (Kq is not small).
        let n = notes_radius(NOTES_KC, NOTES_KL, NOTES_KQ, 1.0, NOTES_CUTOFF);
        assert!(rel(f64::from(n), hand) < 1e-5, "notes = {n}");
    }

    #[test]
    fn linear_only_is_linear_root() {
        let r = light_volume_radius(1.0, 0.09, 0.0, 1.0, NOTES_CUTOFF).unwrap();
        let expect = (256.0 / 5.0 - 1.0) / 0.09f64;
        assert!(rel(f64::from(r), expect) < 1e-6, "r = {r}");
        // The notes' formula divides by zero here.
        assert!(!notes_radius(1.0, 0.09, 0.0, 1.0, NOTES_CUTOFF).is_finite());
    }

    #[test]
    fn constant_only_has_no_finite_volume() {
        assert_eq!(light_volume_radius(1.0, 0.0, 0.0, 1.0, NOTES_CUTOFF), None);
        // ...unless the light never reaches the cutoff at all.
        assert_eq!(
            light_volume_radius(100.0, 0.0, 0.0, 1.0, NOTES_CUTOFF),
            Some(0.0)
        );
    }

    #[test]
    fn dim_light_contributes_nothing() {
        assert_eq!(
            light_volume_radius(1.0, 0.09, 0.032, 0.0, NOTES_CUTOFF),
            Some(0.0)
        );
        // Kc = i_max / cutoff exactly: brightness equals the cutoff only at d = 0.
        assert_eq!(
            light_volume_radius(64.0, 0.09, 0.032, 1.0, 1.0 / 64.0),
            Some(0.0)
        );
    }

    #[test]
    fn tiny_kq_is_accurate_and_notes_formula_is_not() {
        // (Kq, how far off the notes' f32 formula is at least). Measured: at
        // Kq = 1e-9 it returns 558.79 for 557.77 (0.18 % off, 180x the f32
        // rounding of the stable form); at 1e-11 it is 33 % off; at 1e-12
        // `sqrt(Kl^2 + 4 Kq |c|)` rounds to Kl and it returns 0.
        for (kq, notes_at_least) in [(1e-9f32, 1e-3), (1e-11, 0.3), (1e-12, 0.99)] {
            let reference = bisect_radius(1.0, 0.09, kq, 1.0, NOTES_CUTOFF);
            let r = light_volume_radius(1.0, 0.09, kq, 1.0, NOTES_CUTOFF).unwrap();
            assert!(
                rel(f64::from(r), reference) < 1e-5,
                "kq {kq}: r = {r}, reference = {reference}"
            );
            let n = notes_radius(1.0, 0.09, kq, 1.0, NOTES_CUTOFF);
            let notes_err = rel(f64::from(n), reference);
            assert!(
                notes_err > notes_at_least,
                "kq {kq}: notes formula {n} closer to {reference} than expected (rel err {notes_err})"
            );
        }
    }

    #[test]
    fn intensity_at_radius_equals_cutoff() {
        let cases = [
            (1.0, 0.09, 0.032, 1.0),
            (1.0, 0.09, 0.032, 0.3),
            (1.0, 0.7, 1.8, 2.5),
            (1.0, 0.0014, 0.000007, 1.0),
            (0.5, 0.09, 1e-9, 1.0),
            (1.0, 0.0, 0.5, 1.0),
            (1.0, 0.09, 0.0, 4.0),
        ];
        for (kc, kl, kq, i_max) in cases {
            let r = light_volume_radius(kc, kl, kq, i_max, NOTES_CUTOFF).unwrap();
            assert!(r > 0.0);
            // Evaluate in f64 so the check itself does not add f32 error.
            let (kc64, kl64, kq64, r64) =
                (f64::from(kc), f64::from(kl), f64::from(kq), f64::from(r));
            let at_r = f64::from(i_max) / (kc64 + kl64 * r64 + kq64 * r64 * r64);
            assert!(
                rel(at_r, f64::from(NOTES_CUTOFF)) < 1e-5,
                "({kc}, {kl}, {kq}, {i_max}): r = {r}, intensity {at_r}"
            );
            // And the f32 attenuation() agrees to f32 precision.
            let f = i_max * attenuation(kc, kl, kq, r);
            assert!(rel(f64::from(f), f64::from(NOTES_CUTOFF)) < 1e-5, "{f}");
        }
    }

    #[test]
    fn radius_is_monotonic_in_intensity() {
        for (kc, kl, kq) in [
            (1.0, 0.09, 0.032),
            (1.0, 0.09, 0.0),
            (1.0, 0.0, 0.032),
            (1.0, 0.09, 1e-9),
        ] {
            let mut prev = 0.0f32;
            for step in 0..=200 {
                let i_max = step as f32 * 0.05;
                let r = light_volume_radius(kc, kl, kq, i_max, NOTES_CUTOFF).unwrap();
                assert!(r >= prev, "({kc}, {kl}, {kq}) i_max {i_max}: {r} < {prev}");
                prev = r;
            }
            assert!(prev > 0.0);
        }
    }

    #[test]
    fn attenuation_is_the_notes_formula() {
        assert_eq!(attenuation(1.0, 0.0, 0.0, 10.0), 1.0);
        let a = attenuation(1.0, 0.09, 0.032, 2.0);
        assert!((a - 1.0 / (1.0 + 0.18 + 0.128)).abs() < 1e-7);
        assert_eq!(attenuation(0.0, 0.0, 0.0, 1.0), f32::INFINITY);
    }

    #[test]
    fn validate_rejects_bad_coefficients() {
        assert!(validate_attenuation(1.0, 0.09, 0.032).is_ok());
        assert!(validate_attenuation(0.0, 0.0, 1.0).is_ok());
        assert!(validate_attenuation(-1.0, 0.09, 0.032).is_err());
        assert!(validate_attenuation(1.0, -0.09, 0.032).is_err());
        assert!(validate_attenuation(1.0, 0.09, -0.032).is_err());
        assert!(validate_attenuation(f32::NAN, 0.09, 0.032).is_err());
        assert!(validate_attenuation(1.0, f32::INFINITY, 0.032).is_err());
        let e = validate_attenuation(0.0, 0.0, 0.0).unwrap_err();
        assert!(e.contains("all 0"), "{e}");
    }

    #[test]
    fn invalid_radius_input_is_none() {
        assert_eq!(
            light_volume_radius(-1.0, 0.09, 0.032, 1.0, NOTES_CUTOFF),
            None
        );
        assert_eq!(
            light_volume_radius(1.0, f32::NAN, 0.032, 1.0, NOTES_CUTOFF),
            None
        );
        assert_eq!(
            light_volume_radius(1.0, 0.09, 0.032, f32::NAN, NOTES_CUTOFF),
            None
        );
        assert_eq!(
            light_volume_radius(1.0, 0.09, 0.032, -1.0, NOTES_CUTOFF),
            None
        );
        assert_eq!(light_volume_radius(1.0, 0.09, 0.032, 1.0, 0.0), None);
        assert_eq!(light_volume_radius(1.0, 0.09, 0.032, 1.0, f32::NAN), None);
        // Overflowing f32 is "no finite volume", not infinity.
        assert_eq!(light_volume_radius(1.0, 1e-44, 0.0, 1e30, 1e-30), None);
    }
}
