//! FLIP against values computed here from the paper's colour pipeline
//! (sRGB to CIELAB with D65 white, Hunt-adjusted, HyAB distance, the
//! 0.7 power and the (0.4, 0.95) remap): on two flat images the spatial
//! filters change nothing and the feature term is 0, so FLIP is the
//! colour error alone.

use super::flip;
use image::{Rgba, RgbaImage};

fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Linear RGB to Hunt-adjusted CIELAB (D65).
fn lab_hunt(rgb: [f64; 3]) -> [f64; 3] {
    let [r, g, b] = rgb;
    let x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
    let f = |t: f64| {
        let d: f64 = 6.0 / 29.0;
        if t > d * d * d {
            t.cbrt()
        } else {
            t / (3.0 * d * d) + 4.0 / 29.0
        }
    };
    let (fx, fy, fz) = (f(x / 0.95047), f(y), f(z / 1.08883));
    let l = 116.0 * fy - 16.0;
    let (a, bb) = (500.0 * (fx - fy), 200.0 * (fy - fz));
    [l, 0.01 * l * a, 0.01 * l * bb]
}

fn hyab(p: [f64; 3], q: [f64; 3]) -> f64 {
    (p[0] - q[0]).abs() + ((p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// FLIP of two flat 8-bit sRGB colours, by the paper's colour pipeline.
fn flat_flip(c0: [u8; 3], c1: [u8; 3]) -> f64 {
    let lin = |c: [u8; 3]| c.map(|v| srgb_to_linear(f64::from(v) / 255.0));
    let cmax = hyab(lab_hunt([0.0, 1.0, 0.0]), lab_hunt([0.0, 0.0, 1.0])).powf(0.7);
    let e = hyab(lab_hunt(lin(c0)), lab_hunt(lin(c1))).powf(0.7);
    let (pc, pt) = (0.4, 0.95);
    if e < pc * cmax {
        e * pt / (pc * cmax)
    } else {
        pt + (e - pc * cmax) / (cmax - pc * cmax) * (1.0 - pt)
    }
}

fn flat(c: [u8; 3]) -> RgbaImage {
    RgbaImage::from_pixel(32, 24, Rgba([c[0], c[1], c[2], 255]))
}

#[test]
fn identical_images_have_no_error() {
    let img = RgbaImage::from_fn(40, 30, |x, y| {
        Rgba([(x * 6) as u8, (y * 8) as u8, ((x * y) % 251) as u8, 255])
    });
    let f = flip(&img, &img).unwrap();
    // The pool starts from f32::MIN_POSITIVE, not 0.
    assert!(f.mean < 1e-30 && f.max < 1e-30, "{} {}", f.mean, f.max);
    // The magma map of 0 is its darkest entry, (0, 0, 4).
    assert!(f.map.pixels().all(|p| p.0 == [0, 0, 4]));
}

#[test]
fn flat_pairs_match_the_papers_colour_pipeline() {
    for (a, b) in [
        ([0, 0, 0], [255, 255, 255]),
        ([128, 128, 128], [138, 138, 138]),
        ([200, 40, 40], [40, 200, 40]),
        ([10, 20, 30], [12, 20, 30]),
    ] {
        let expect = flat_flip(a, b);
        let f = flip(&flat(a), &flat(b)).unwrap();
        assert!(
            (f.mean - expect).abs() < 2e-3 && (f.max - expect).abs() < 2e-3,
            "{a:?} against {b:?}: FLIP mean {} max {}, the pipeline gives {expect}",
            f.mean,
            f.max
        );
    }
    // Black against white lands in the top band of the remap.
    assert!((flat_flip([0; 3], [255; 3]) - 0.967).abs() < 1e-3);
}

#[test]
fn an_edge_that_appears_costs_more_than_its_colour() {
    // A one-pixel line the reference lacks: the feature term raises FLIP
    // on it above the flat colour error of the same two colours.
    let reference = flat([100, 100, 100]);
    let mut test = reference.clone();
    for y in 0..24 {
        test.put_pixel(16, y, Rgba([160, 160, 160, 255]));
    }
    let f = flip(&test, &reference).unwrap();
    assert!(f.max > flat_flip([100; 3], [160; 3]) * 0.5, "max {}", f.max);
    assert!(f.mean > 0.0 && f.mean < f.max);
}

#[test]
fn sizes_that_differ_are_an_error() {
    let e = flip(&flat([0; 3]), &RgbaImage::new(3, 3)).err().unwrap();
    assert!(e.to_string().contains("32x24 vs 3x3"), "{e}");
    let e = flip(&RgbaImage::new(0, 0), &RgbaImage::new(0, 0))
        .err()
        .unwrap();
    assert!(e.to_string().contains("empty"), "{e}");
}
