//! Unit tests of the CPU bloom reference.

use super::*;

/// Small blurs that fit in a small image, for exact energy checks.
fn small() -> BloomParams {
    BloomParams {
        blurs: [(1.0, 3), (2.0, 6), (3.0, 9), (4.0, 12)],
        weights: SPENCER_WEIGHTS,
    }
}

fn point(width: usize, height: usize, x0: usize, y0: usize, v: f32) -> Vec<f32> {
    let mut img = vec![0.0; width * height * 4];
    let i = (y0 * width + x0) * 4;
    img[i..i + 3].copy_from_slice(&[v, v, v]);
    img
}

#[test]
fn the_spencer_weights_sum_to_one() {
    let sum: f64 = SPENCER_WEIGHTS.iter().sum();
    assert!((sum - 1.0).abs() < 1e-12, "{sum}");
}

#[test]
fn sanitising_zeroes_nan_and_negatives_and_caps_infinity() {
    assert_eq!(sanitise(f32::NAN), 0.0);
    assert_eq!(sanitise(-f32::NAN), 0.0);
    assert_eq!(sanitise(f32::INFINITY), HALF_MAX);
    assert_eq!(sanitise(f32::NEG_INFINITY), 0.0);
    assert_eq!(sanitise(-2.5), 0.0);
    assert_eq!(sanitise(-0.0), 0.0);
    assert_eq!(sanitise(1.5), 1.5);
    assert_eq!(sanitise(1e6), 1e6);
}

#[test]
fn black_stays_exactly_black_and_flat_stays_flat() {
    let black = vec![0.0f32; 40 * 30 * 4];
    let out = bloom(&black, 40, 30, &BloomParams::default()).unwrap();
    assert!(out.iter().all(|v| *v == 0.0));
    let flat: Vec<f32> = [0.25f32, 0.5, 2.0, 1.0].repeat(40 * 30);
    let out = bloom(&flat, 40, 30, &BloomParams::default()).unwrap();
    for p in out.chunks_exact(4) {
        for (v, e) in p.iter().zip([0.25, 0.5, 2.0, 1.0]) {
            assert!((v - e).abs() < 1e-12, "{v} against {e}");
        }
    }
}

#[test]
fn a_bright_pixel_keeps_its_energy_and_spreads_by_sigma() {
    let (w, h) = (64, 64);
    let img = point(w, h, 31, 33, 1000.0);
    let out = bloom(&img, w, h, &small()).unwrap();
    let e = energy(&out);
    for c in e {
        assert!((c - 1000.0).abs() < 1e-9, "energy {c}");
    }
    // One blur alone: the spread is the kernel's (truncated) variance.
    for (sigma, radius) in small().blurs {
        let b = gaussian_blur(&img, w, h, sigma, radius).unwrap();
        let p = psf(&b, w, h, 31, 33).unwrap();
        let wts = gaussian(sigma, radius);
        let var: f64 = 2.0
            * wts
                .iter()
                .enumerate()
                .map(|(i, v)| (i * i) as f64 * v)
                .sum::<f64>();
        assert!((p.sigma.0 - var.sqrt()).abs() < 1e-9, "{p:?}");
        assert!((p.sigma.1 - var.sqrt()).abs() < 1e-9, "{p:?}");
        assert!((p.centroid.0 - 31.0).abs() < 1e-9 && (p.centroid.1 - 33.0).abs() < 1e-9);
    }
}

#[test]
fn nan_and_infinity_do_not_spread() {
    let (w, h) = (32, 24);
    let mut img: Vec<f32> = [0.5f32, 0.5, 0.5, 1.0].repeat(w * h);
    let mut zeroed = img.clone();
    img[(5 * w + 7) * 4] = f32::NAN;
    img[(5 * w + 7) * 4 + 1] = -1.0;
    zeroed[(5 * w + 7) * 4] = 0.0;
    zeroed[(5 * w + 7) * 4 + 1] = 0.0;
    img[(20 * w + 20) * 4 + 2] = f32::INFINITY;
    zeroed[(20 * w + 20) * 4 + 2] = 65504.0;
    let a = bloom(&img, w, h, &small()).unwrap();
    let b = bloom(&zeroed, w, h, &small()).unwrap();
    assert!(a.iter().all(|v| v.is_finite()));
    assert_eq!(a, b);
}

#[test]
fn the_border_is_clamped_to_the_edge() {
    // A 3-pixel row, radius 2: offsets beyond the left end read pixel 0, so
    // pixel 0 gets w0 + w1 + w2, pixel 1 w1 + w2 (offsets -1 and -2), pixel 2 w2.
    let img: Vec<f32> = [[1.0f32, 0.0, 0.0, 1.0], [0.0; 4], [0.0; 4]].concat();
    let out = gaussian_blur(&img, 3, 1, 1.0, 2).unwrap();
    let wts = gaussian(1.0, 2);
    let left = wts[0] + wts[1] + wts[2];
    assert!((out[0] - left).abs() < 1e-15);
    assert!((out[4] - wts[1] - wts[2]).abs() < 1e-15);
    assert!((out[8] - wts[2]).abs() < 1e-15);
}

#[test]
fn a_wrong_size_is_an_error_and_degenerate_psfs_are_none() {
    assert!(bloom(&[0.0; 12], 2, 2, &BloomParams::default()).is_err());
    assert!(bloom(&[], 0, 0, &BloomParams::default()).is_err());
    assert!(psf(&[0.0f32; 16], 2, 2, 0, 0).is_none());
    assert!(psf(&[1.0f32; 15], 2, 2, 0, 0).is_none());
}
