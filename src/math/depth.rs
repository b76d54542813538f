//! Depth precision (notes 01 §4.4 "Depth Buffer / Depth Test": "Can have z
//! fighting when two objects with close z coordinates are rasterised inside
//! each other. A higher precision depth buffer avoids this.").
//!
//! A perspective projection with near n and far f (§2.5.2, glDepthRange(0, 1))
//! stores, for a point at eye-space distance z in front of the eye, the
//! window-space depth
//!
//! ```text
//! d(z) = f (z - n) / (z (f - n))          d(n) = 0, d(f) = 1
//! ```
//!
//! which a B-bit fixed-point depth buffer rounds to one of 2^B - 1 steps.
//! Its slope is d'(z) = f n / (z^2 (f - n)): steep near the eye, flat far
//! away. One step of the buffer, 1 / (2^B - 1) ≈ 2^-B, is then, to first
//! order, an eye-space distance of
//!
//! ```text
//! dz ≈ 2^-B / d'(z) = z^2 (f - n) / (f n 2^B)
//! ```
//!
//! Two surfaces closer than dz at distance z may round to the same stored
//! depth, and which one shows depends on draw order and rounding: z-fighting.
//! dz grows with z^2 and with 1/n: moving the near plane out helps far more
//! than moving the far plane in. The first-order form holds while dz is
//! small against z; `resolvable_step` finds the exact step by walking the
//! quantised values, and the tests compare the two.

/// The window-space depth of eye distance `z` (perspective, near `n`, far `f`).
pub fn window_depth(z: f64, n: f64, f: f64) -> f64 {
    f * (z - n) / (z * (f - n))
}

/// The eye distance whose window-space depth is `d` (the inverse of `window_depth`).
pub fn eye_distance(d: f64, n: f64, f: f64) -> f64 {
    f * n / (f - d * (f - n))
}

/// The smallest resolvable eye-space depth difference at distance `z` for a
/// `bits`-bit depth buffer, to first order: z^2 (f - n) / (f n 2^bits).
pub fn resolvable_difference(z: f64, n: f64, f: f64, bits: u32) -> f64 {
    z * z * (f - n) / (f * n * 2f64.powi(bits as i32))
}

/// The exact size, in eye space, of the depth-buffer step that holds
/// distance `z`: quantise d(z) to the nearest of the 2^bits - 1 steps, map
/// the step's two ends (half a step either side) back to eye space. None
/// when the step reaches past the far plane (the last step).
pub fn resolvable_step(z: f64, n: f64, f: f64, bits: u32) -> Option<f64> {
    let max = 2f64.powi(bits as i32) - 1.0;
    let code = (window_depth(z, n, f) * max).round();
    let (lo, hi) = ((code - 0.5) / max, (code + 0.5) / max);
    if lo < 0.0 || hi > 1.0 {
        return None;
    }
    Some(eye_distance(hi, n, f) - eye_distance(lo, n, f))
}

/// Whether two surfaces at eye distances `z1` and `z2` get different stored
/// depths in a `bits`-bit buffer (no z-fighting between them).
pub fn distinct_in_buffer(z1: f64, z2: f64, n: f64, f: f64, bits: u32) -> bool {
    let max = 2f64.powi(bits as i32) - 1.0;
    let code = |z: f64| (window_depth(z, n, f).clamp(0.0, 1.0) * max).round();
    code(z1) != code(z2)
}

/// The depth buffer gloss allocates: DEPTH24_STENCIL8.
pub const DEPTH_BITS: u32 = 24;

/// (z, dz) at a few eye distances between `n` and `f` (10 n, 1, 10, 100,
/// f / 2 and f, those inside the range), for `gloss plan`. An orthographic
/// projection stores depth linearly: dz = (f - n) / 2^bits at every z.
pub fn precision_table(n: f64, f: f64, perspective: bool, bits: u32) -> Vec<(f64, f64)> {
    let mut zs: Vec<f64> = [10.0 * n, 1.0, 10.0, 100.0, f / 2.0, f]
        .into_iter()
        .filter(|&z| z > n && z <= f)
        .collect();
    zs.sort_by(f64::total_cmp);
    zs.dedup_by(|a, b| (*a - *b).abs() <= 1e-6 * b.abs());
    zs.into_iter()
        .map(|z| {
            let dz = if perspective {
                resolvable_difference(z, n, f, bits)
            } else {
                (f - n) / 2f64.powi(bits as i32)
            };
            (z, dz)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_lists_distances_inside_the_range_growing_with_z_squared() {
        let t = precision_table(0.01, 100.0, true, 24);
        let zs: Vec<f64> = t.iter().map(|r| r.0).collect();
        assert_eq!(zs, [0.1, 1.0, 10.0, 50.0, 100.0]);
        // dz(10 z) = 100 dz(z).
        assert!((t[2].1 / t[1].1 - 100.0).abs() < 1e-9);
        let ortho = precision_table(1.0, 20.0, false, 24);
        assert!(ortho.iter().all(|r| r.1 == 19.0 / 16777216.0));
    }

    #[test]
    fn window_depth_maps_near_to_0_and_far_to_1_and_inverts() {
        for (n, f) in [(0.1, 100.0), (0.01, 100.0), (1.0, 60.0), (1e-4, 1e4)] {
            assert!(window_depth(n, n, f).abs() < 1e-12);
            assert!((window_depth(f, n, f) - 1.0).abs() < 1e-12);
            for z in [n * 1.5, (n + f) / 2.0, f * 0.9] {
                let back = eye_distance(window_depth(z, n, f), n, f);
                // Near the far plane d is close to 1 and 1 - d cancels: even in
                // f64 the round trip keeps only about 8 digits for n = 1e-4.
                assert!((back - z).abs() <= 1e-6 * z, "{z} -> {back}");
            }
        }
    }

    #[test]
    fn the_formula_matches_the_quantised_buffer_where_dz_is_small() {
        // (near, far, z): z near n, mid-range, z near f, and a tiny near plane.
        for (n, f, z) in [
            (0.1, 100.0, 0.1001),
            (0.1, 100.0, 50.0),
            (0.1, 100.0, 99.0),
            (0.01, 100.0, 50.0),
            (0.01, 100.0, 99.9),
            (1.0, 100.0, 50.0),
            (1e-4, 1000.0, 5.0),
            (1e-4, 1000.0, 1e-4 * 1.001),
        ] {
            let exact = resolvable_step(z, n, f, 24).unwrap();
            let approx = resolvable_difference(z, n, f, 24);
            assert!(exact / z < 0.01, "the first-order regime: {exact} at {z}");
            let rel = (approx - exact).abs() / exact;
            assert!(
                rel < 0.01,
                "n {n} f {f} z {z}: formula {approx:e}, quantised buffer {exact:e}"
            );
        }
    }

    #[test]
    fn with_a_tiny_near_plane_the_far_steps_span_whole_distances() {
        // n = 1e-4, f = 1e4: at z = 1000 one step spans over a tenth of the
        // distance, the first-order form is no longer accurate (it
        // overestimates), and the last step (which reaches f) has no end.
        let (n, f) = (1e-4, 1e4);
        let exact = resolvable_step(1000.0, n, f, 24).unwrap();
        assert!(exact > 100.0, "{exact}");
        assert!(resolvable_difference(1000.0, n, f, 24) > 1.2 * exact);
        assert!(resolvable_step(f, n, f, 24).is_none());
    }

    #[test]
    fn surfaces_closer_than_dz_share_a_depth_and_farther_ones_do_not() {
        let (n, f, z) = (0.01, 100.0, 50.0);
        let dz = resolvable_difference(z, n, f, 24);
        // Far apart (ten steps): always distinct; a tenth of a step: mostly not.
        let mut same = 0;
        for k in 0..1000 {
            let z1 = z + k as f64 * dz * 0.0137;
            assert!(distinct_in_buffer(z1, z1 + 10.0 * dz, n, f, 24));
            if !distinct_in_buffer(z1, z1 + 0.1 * dz, n, f, 24) {
                same += 1;
            }
        }
        assert!((850..=950).contains(&same), "{same} of 1000");
    }
}
