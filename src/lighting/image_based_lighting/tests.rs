//! The CPU twins against their references, without a GPU.

use super::*;

/// A smooth environment with a bright lobe (a sky-like gradient and a soft sun).
fn sky(d: DVec3) -> DVec3 {
    let sun = DVec3::new(0.6, 0.3, -0.7).normalize();
    let lobe = (d.dot(sun) - 1.0).exp2().powi(8) * 4.0;
    DVec3::new(0.3, 0.5, 0.9) * (0.5 + 0.5 * d.y).max(0.05) + DVec3::splat(lobe)
}

#[test]
fn ggx_half_vectors_follow_d_times_cos() {
    // The mean of n.h under D (n.h) dh, against the same integral by quadrature in theta.
    let n = DVec3::new(0.3, 0.9, 0.1).normalize();
    for alpha in [0.05, 0.3, 1.0] {
        let m = 4096;
        let got: f64 = (0..m)
            .map(|i| n.dot(importance_sample_ggx(hammersley(i, m), alpha, n)))
            .sum::<f64>()
            / f64::from(m);
        let k = 200_000;
        let mut want = 0.0;
        for j in 0..k {
            let t = (j as f64 + 0.5) / k as f64 * PI / 2.0;
            let (s, c) = t.sin_cos();
            let a2 = alpha * alpha;
            let d = a2 / (PI * (a2 * c * c + s * s).powi(2));
            want += c * d * c * 2.0 * PI * s * (PI / 2.0 / k as f64);
        }
        assert!((got - want).abs() < 2e-3, "alpha {alpha}: {got} vs {want}");
    }
}

#[test]
fn the_table_twin_matches_the_quadrature_of_gloss_brdf() {
    let mut worst: f64 = 0.0;
    for nv in [0.05, 0.2, 0.5, 0.8, 1.0] {
        for alpha in [0.01, 0.1, 0.3, 0.6, 1.0] {
            let (a, b) = integrate_brdf(nv, alpha, 4096);
            let (ra, rb) = brdf_table_reference(nv, alpha);
            worst = worst.max((a - ra).abs()).max((b - rb).abs());
        }
    }
    // Measured 0.0107, at the grazing n.v = 0.05.
    assert!(worst < 0.015, "worst |table - quadrature| {worst}");
}

#[test]
fn white_furnace_f0_one_loses_only_single_scattering_energy() {
    // F0 = 1: A + B is the microfacet BRDF's albedo with F = 1, at most 1,
    // 1 near a mirror, lower for rough surfaces (the single-scattering loss).
    let (a, b) = brdf_table_reference(1.0, 0.01);
    assert!((a + b - 1.0).abs() < 1e-3, "smooth: {}", a + b);
    let (a, b) = brdf_table_reference(0.5, 1.0);
    // Measured 0.451: GGX at alpha 1 loses over half to single scattering.
    assert!(a + b < 0.5 && a + b > 0.4, "rough: {}", a + b);
    for nv in [0.1, 0.5, 1.0] {
        for alpha in [0.1, 0.5, 1.0] {
            let (a, b) = brdf_table_reference(nv, alpha);
            assert!(a + b <= 1.0 + 1e-9, "gains energy at {nv} {alpha}");
        }
    }
}

#[test]
fn prefiltering_matches_its_monte_carlo_integral() {
    for alpha in [0.04, 0.16, 0.64] {
        for r in [
            DVec3::Y,
            DVec3::new(0.6, 0.3, -0.7).normalize(),
            DVec3::new(1.0, -0.2, 0.3).normalize(),
        ] {
            let got = prefilter_env_map(&sky, r, alpha, 4096);
            let want = prefiltered_mc(&sky, r, alpha, 200_000, 7);
            let err = (got - want).abs().max_element() / want.max_element();
            assert!(err < 0.02, "alpha {alpha}, r {r}: {got} vs {want}");
        }
    }
}

#[test]
fn a_uniform_environment_convolves_to_itself() {
    let white = CubeImage {
        size: 8,
        faces: std::array::from_fn(|_| vec![[1.0; 4]; 64]),
    };
    for n in [DVec3::X, DVec3::new(1.0, 2.0, -3.0).normalize()] {
        let e = irradiance_convolution(&white, n);
        assert!((e - DVec3::ONE).abs().max_element() < 1e-12, "{e}");
    }
    // The solid angles of a face sum to 4 pi / 6.
    let k = 16;
    let mut sum = 0.0;
    for j in 0..k {
        for i in 0..k {
            let (x, y) = (
                2.0 * i as f64 / k as f64 - 1.0,
                2.0 * j as f64 / k as f64 - 1.0,
            );
            sum += face_solid_angle(x, y, x + 2.0 / k as f64, y + 2.0 / k as f64);
        }
    }
    assert!((sum - 4.0 * PI / 6.0).abs() < 1e-12, "{sum}");
}
