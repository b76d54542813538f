//! The windowed falloff (`render.falloff = "windowed"`): a lighting model of
//! its own, not the notes'. Notes 04's attenuation 1 / (Kc + Kl d + Kq d^2)
//! never reaches 0, so a light volume cut at radius r (where the brightest
//! channel falls to the cutoff) drops the tail beyond it. Here the notes'
//! attenuation is multiplied by a window that is 1 at the light and falls
//! to exactly 0 at r, with a zero slope there (Karis, "Real Shading in
//! Unreal Engine 4", SIGGRAPH 2013 course notes):
//!
//! ```text
//! W(x) = clamp(1 - x^4, 0, 1)^2,   x = d / r
//! ```
//!
//! Every path then shades the same model and no cutoff drops anything. The
//! price is a different image: `model_difference` bounds how far it is from
//! the notes' model, per light.

use super::attenuation::attenuation;

/// W(d / r); a light with radius 0 (never brighter than the cutoff) gets 0.
pub fn window(d: f32, radius: f32) -> f32 {
    if radius.is_nan() || radius <= 0.0 {
        return 0.0;
    }
    let x = d / radius;
    let w = (1.0 - x * x * x * x).clamp(0.0, 1.0);
    w * w
}

/// The notes' attenuation times the window.
pub fn windowed_attenuation(kc: f32, kl: f32, kq: f32, d: f32, radius: f32) -> f32 {
    attenuation(kc, kl, kq, d) * window(d, radius)
}

/// The largest difference, over every distance, between one light's
/// attenuation in the notes' model and in the windowed one, times its
/// intensity `i_max`: `max_d i_max att(d) (1 - W(d / r))`, sampled finely
/// from 0 to r and taken at r beyond it (where att falls and 1 - W = 1).
/// Returns (the difference, the distance it is at).
pub fn model_difference(kc: f32, kl: f32, kq: f32, i_max: f32, radius: f32) -> (f32, f32) {
    let mut best = (i_max * attenuation(kc, kl, kq, radius), radius);
    for k in 0..=4096 {
        let d = radius * k as f32 / 4096.0;
        let v = i_max * attenuation(kc, kl, kq, d) * (1.0 - window(d, radius));
        if v > best.0 {
            best = (v, d);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_window_is_one_at_the_light_and_zero_from_the_radius_on() {
        for r in [0.5f32, 3.874, 100.0] {
            assert_eq!(window(0.0, r), 1.0);
            assert_eq!(window(r, r), 0.0);
            assert_eq!(window(r * 1.5, r), 0.0);
            assert_eq!(window(f32::INFINITY, r), 0.0);
            // Monotone between.
            let w: Vec<f32> = (0..=100).map(|k| window(r * k as f32 / 100.0, r)).collect();
            assert!(w.windows(2).all(|p| p[1] <= p[0]), "{w:?}");
        }
        // A light never brighter than the cutoff has radius 0: nothing.
        assert_eq!(window(0.0, 0.0), 0.0);
        assert_eq!(window(1.0, f32::NAN), 0.0);
    }

    #[test]
    fn the_window_meets_zero_with_zero_slope() {
        // W'(x) = -8 x^3 (1 - x^4): 0 at x = 1, so the light fades out with
        // no crease at its radius.
        // Near the radius W ~ 16 (1 - x)^2: the slope over the last h falls
        // with h, tenfold for h tenfold smaller.
        let r = 2.0;
        let slope = |h: f32| (window(r, r) - window(r - h, r)) / h;
        let (coarse, fine) = (slope(1e-2), slope(1e-3));
        assert!(fine.abs() < coarse.abs() / 5.0, "slopes {coarse} {fine}");
        assert!(fine.abs() < 0.01, "slope near the radius {fine}");
        let h = 1e-3;
        let mid = (window(r * 0.5 + h, r) - window(r * 0.5 - h, r)) / (2.0 * h);
        assert!(mid < -0.2, "it does fall: {mid}");
    }

    #[test]
    fn windowed_attenuation_never_exceeds_the_notes() {
        let (kc, kl, kq, r) = (1.0, 0.7, 1.8, 3.874);
        for k in 0..=200 {
            let d = r * 1.2 * k as f32 / 200.0;
            let a = attenuation(kc, kl, kq, d);
            let w = windowed_attenuation(kc, kl, kq, d, r);
            assert!(w <= a && w >= 0.0, "d {d}: {w} > {a}");
            assert!(a - w <= a * (1.0 - window(d, r)) + 1e-7);
        }
    }

    #[test]
    fn the_model_difference_of_the_many_lights_scene() {
        // scenes/many-lights.toml: Kc, Kl, Kq = 1, 0.7, 1.8, I = 0.6,
        // cutoff 5/256: radius 3.874. The window takes most from the middle
        // distances, where the notes' light is still several cutoffs strong.
        let (diff, at) = model_difference(1.0, 0.7, 1.8, 0.6, 3.874);
        assert!(diff > 5.0 / 256.0 * 0.6, "{diff} at {at}");
        assert!(diff < 0.1, "{diff} at {at}");
        assert!(at > 0.5 && at < 3.874, "{at}");
        // At the radius itself the difference is the cutoff: I att(r) = 5/256 x I_max / I_max.
        let at_r = 0.6 * attenuation(1.0, 0.7, 1.8, 3.874);
        assert!((at_r - 5.0 / 256.0).abs() < 1e-4, "{at_r}");
    }
}
