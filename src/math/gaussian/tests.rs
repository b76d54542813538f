//! Unit tests for the blur kernels of notes 03, "Blur Pass and Merge Pass".

use super::*;

/// The notes' four blurs: (sigma, radius) in full-resolution pixels.
const NOTES: [(f64, u32); 4] = [(6.2, 24), (24.9, 80), (81.0, 243), (263.0, 799)];

/// A seeded signal in 0..1 (a linear congruential generator).
fn signal(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// The signal at real position x, linearly interpolated (what a GPU's
/// bilinear filter does along one axis, with exact weights).
fn lerp_at(s: &[f64], x: f64) -> f64 {
    let i = x.floor();
    let f = x - i;
    let i = i as usize;
    (1.0 - f) * s[i] + f * s[i + 1]
}

#[test]
fn gaussian_weights_sum_to_one_for_the_notes_and_for_small_sigmas() {
    let small = [
        (0.3, 1),
        (0.5, 2),
        (1.0, 3),
        (0.1, 799),
        (2.0, 0),
        (1e-3, 5),
    ];
    for (sigma, radius) in NOTES.into_iter().chain(small) {
        let k = Kernel::gaussian(sigma, radius);
        assert_eq!(k.weights.len(), k.radius as usize + 1);
        assert!(
            (k.sum() - 1.0).abs() < 1e-12,
            "sigma {sigma} radius {radius}: sum {}",
            k.sum()
        );
        assert!(k.weights.iter().all(|w| w.is_finite() && *w >= 0.0));
        // Decreasing away from the centre.
        assert!(k.weights.windows(2).all(|p| p[1] <= p[0]));
    }
}

#[test]
fn degenerate_kernels_are_the_identity_without_nan() {
    for k in [
        Kernel::gaussian(0.0, 24),
        Kernel::gaussian(-3.0, 24),
        Kernel::gaussian(f64::NAN, 24),
        Kernel::gaussian(6.2, 0),
        Kernel::box_(0),
    ] {
        assert_eq!(k.weights, vec![1.0], "{k:?}");
        assert_eq!(linear_taps(&k), vec![(0.0, 1.0)]);
    }
    // An infinite sigma is the box.
    assert_eq!(
        Kernel::gaussian(f64::INFINITY, 3).weights,
        Kernel::box_(3).weights
    );
}

#[test]
fn box_weights_are_equal_and_sum_to_one() {
    for r in [1, 2, 7, 100] {
        let k = Kernel::box_(r);
        let expect = 1.0 / f64::from(2 * r + 1);
        assert!(k.weights.iter().all(|w| (w - expect).abs() < 1e-15));
        assert!((k.sum() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn linear_taps_pair_the_texels_and_keep_the_weight() {
    for (sigma, radius) in NOTES.into_iter().chain([(1.5, 4), (1.5, 5), (3.0, 1)]) {
        let k = Kernel::gaussian(sigma, radius);
        let taps = linear_taps(&k);
        assert_eq!(taps.len(), 1 + (radius as usize).div_ceil(2));
        assert_eq!(taps[0], (0.0, k.weights[0]));
        // Tap j reads texels 2j - 1 and 2j: its offset lies between them.
        for (j, &(off, _)) in taps.iter().enumerate().skip(1) {
            let lo = (2 * j - 1) as f64;
            assert!(off >= lo && off <= lo + 1.0, "tap {j} at {off}");
        }
        // The taps are mirrored: the centre once, every other tap twice.
        let total = taps[0].1 + 2.0 * taps[1..].iter().map(|t| t.1).sum::<f64>();
        assert!((total - 1.0).abs() < 1e-12);
    }
    // An odd texel at the end keeps its own tap at its own offset.
    let k = Kernel::gaussian(1.5, 5);
    assert_eq!(*linear_taps(&k).last().unwrap(), (5.0, k.weights[5]));
}

#[test]
fn linear_taps_on_a_linearly_interpolated_signal_equal_the_direct_kernel() {
    for (sigma, radius) in [(6.2, 24), (24.9, 80), (2.0, 7), (0.8, 3), (0.2, 9)] {
        let k = Kernel::gaussian(sigma, radius);
        let taps = linear_taps(&k);
        let r = radius as usize;
        let s = signal(4 * r + 64, 7);
        for c in (r + 1..s.len() - r - 1).step_by(5) {
            let direct: f64 = (-(r as i64)..=r as i64)
                .map(|i| k.weight(i) * s[(c as i64 + i) as usize])
                .sum();
            let fetched: f64 = taps[0].1 * s[c]
                + taps[1..]
                    .iter()
                    .map(|&(off, w)| {
                        w * (lerp_at(&s, c as f64 + off) + lerp_at(&s, c as f64 - off))
                    })
                    .sum::<f64>();
            assert!(
                (direct - fetched).abs() < 1e-12,
                "sigma {sigma} at {c}: direct {direct} taps {fetched}"
            );
        }
    }
}

#[test]
fn the_variance_of_a_wide_kernel_is_sigma_squared() {
    for sigma in [2.0, 6.2, 24.9, 81.0] {
        let k = Kernel::gaussian(sigma, (10.0 * sigma) as u32);
        let rel = k.variance() / (sigma * sigma) - 1.0;
        assert!(rel.abs() < 1e-9, "sigma {sigma}: variance off by {rel:e}");
    }
    // The notes cut at 3 to 3.9 sigma: the truncated variance is a little lower.
    for (sigma, radius) in NOTES {
        let ratio = Kernel::gaussian(sigma, radius).variance().sqrt() / sigma;
        assert!((0.985..1.0).contains(&ratio), "sigma {sigma}: {ratio}");
    }
}

#[test]
fn cutting_a_kernel_keeps_it_normalised() {
    let k = Kernel::gaussian(24.9, 80);
    let c = k.cut(40);
    assert_eq!(c.radius, 40);
    assert!((c.sum() - 1.0).abs() < 1e-12);
    assert_eq!(k.cut(80), k);
    assert_eq!(k.cut(500), k);
}

/// Down to level k (the mean of each block of h = 2^k pixels) and back up
/// (linear interpolation between the texel centres, clamped at the ends),
/// in 1D: the response to a unit impulse at `x0`.
fn down_up(n: usize, level: u32, x0: usize) -> Vec<f64> {
    let h = 1usize << level;
    let m = n / h;
    let mut low = vec![0.0; m];
    if x0 / h < m {
        low[x0 / h] = 1.0 / h as f64;
    }
    (0..n)
        .map(|x| {
            // Pixel x's centre in level-k texels, less the half texel.
            let u = ((x as f64 + 0.5) / h as f64 - 0.5).clamp(0.0, (m - 1) as f64);
            let i = (u.floor() as usize).min(m - 2);
            let f = u - i as f64;
            (1.0 - f) * low[i] + f * low[i + 1]
        })
        .collect()
}

#[test]
fn going_down_and_up_blurs_by_the_resample_sigma_on_average() {
    for level in 1..=4 {
        let h = 1usize << level;
        let n = 64 * h;
        let mut second = 0.0;
        // Every phase of the impulse within its texel, away from the ends.
        for x0 in 32 * h..33 * h {
            let out = down_up(n, level, x0);
            let mass: f64 = out.iter().sum();
            assert!((mass - 1.0).abs() < 1e-12, "level {level}: mass {mass}");
            second += out
                .iter()
                .enumerate()
                .map(|(x, v)| (x as f64 - x0 as f64).powi(2) * v)
                .sum::<f64>();
        }
        let sigma = (second / h as f64).sqrt();
        assert!(
            (sigma - resample_sigma(level)).abs() < 1e-9,
            "level {level}: {sigma} against {}",
            resample_sigma(level)
        );
    }
    assert_eq!(resample_sigma(0), 0.0);
}

#[test]
fn level_kernels_add_up_to_the_notes_sigma() {
    for (k, (sigma, radius)) in NOTES.into_iter().enumerate() {
        let level = k as u32 + 1;
        let kern = level_kernel(sigma, radius, level);
        let texel = f64::from(1u32 << level);
        // The kernel's sigma in full-resolution pixels, with the resampling's.
        let total = ((kern.sigma * texel).powi(2) + resample_sigma(level).powi(2)).sqrt();
        assert!((total - sigma).abs() < 1e-9, "level {level}: {total}");
        // Cut at the notes' number of sigmas, to the texel above.
        let cut = f64::from(kern.radius) / kern.sigma;
        let notes_cut = f64::from(radius) / sigma;
        assert!(cut >= notes_cut - 1e-9 && cut < notes_cut + 1.0 / kern.sigma);
        assert!((kern.sum() - 1.0).abs() < 1e-12);
    }
    // Level 0 is the notes' kernel itself.
    assert_eq!(level_kernel(6.2, 24, 0), Kernel::gaussian(6.2, 24));
    // A sigma the resampling already reaches is the identity.
    assert_eq!(level_kernel(1.0, 3, 2), Kernel::identity());
    assert_eq!(level_kernel(-1.0, 3, 2), Kernel::identity());
}
