//! Bloom (notes 03, "Blur Pass and Merge Pass"; src/techniques/post/bloom.rs,
//! glsl/post/bloom_*.frag) against its CPU reference
//! (src/image_compare/bloom_reference.rs) and the figures of the notes.
//!
//! * each level's point-spread function, one bright pixel through one blur
//!   alone, has the notes' sigma in full-resolution pixels (within 1% of the
//!   CPU reference's, the notes' kernel cut at its radius);
//! * the whole bloom of a test image is within the stated RMSE and maximum
//!   of the reference, direct and linear taps;
//! * 1x1, 3x2 and sizes that are not powers of two: every mip level has
//!   GL's size, missing levels are clamped, and no GL error;
//! * all black in is exactly black out; a NaN or inf pixel does not spread;
//!   a very bright pixel keeps its energy through the merge.
//!
//! Every frame runs with GL debug output on and fails on any GL error.

use crate::common;
use gloss::bench::bloom::{BloomError, bloom_image, error, evaluate};
use gloss::gl::texture::level_size;
use gloss::image_compare::bloom_reference::{energy, gaussian_blur, psf};
use gloss::math::gaussian::{Kernel, level_kernel};
use gloss::scene::Scene;
use gloss::scene::bloom::NOTES_LEVELS;
use gloss::techniques::post::bloom_levels::{self, BLOOM_LEVELS};
use glow::HasContext;
use image::{Rgba, RgbaImage};

/// A scene that draws nothing, at `w` x `h`: the chain is a bloom with
/// `keys`, then gamma. The tests put their own image where the world would be.
fn scene(w: u32, h: u32, keys: &str) -> Scene {
    let text = format!(
        "name = \"bloom-test\"\n[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\nsize = [{w}, {h}]\n[[post]]\npass = \"bloom\"\n{keys}\n[[post]]\npass = \"gamma\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/bloom-test.toml")).expect("test scene")
}

/// One bright pixel of `v` at (x0, y0) on black.
fn point(w: usize, h: usize, x0: usize, y0: usize, v: f32) -> Vec<f32> {
    let mut img = vec![0.0; w * h * 4];
    let i = (y0 * w + x0) * 4;
    img[i..i + 4].copy_from_slice(&[v, v, v, 1.0]);
    img
}

/// Linear light as 8 bits (Reinhard, then a 1/2.2 gamma), top row first.
fn picture(data: &[f32], w: usize, h: usize) -> RgbaImage {
    RgbaImage::from_fn(w as u32, h as u32, |x, y| {
        let p = &data[((h - 1 - y as usize) * w + x as usize) * 4..][..3];
        let c = |v: f32| (255.0 * (v.max(0.0) / (1.0 + v.max(0.0))).powf(1.0 / 2.2)) as u8;
        Rgba([c(p[0]), c(p[1]), c(p[2]), 255])
    })
}

/// Write the actual, expected and diff pictures; return their paths.
fn write_pictures(name: &str, actual: &[f32], expected: &[f64], w: usize, h: usize) -> String {
    let dir = common::out_dir();
    let expected: Vec<f32> = expected.iter().map(|&v| v as f32).collect();
    let diff: Vec<f32> = (actual.iter().zip(&expected))
        .map(|(a, e)| 16.0 * (a - e).abs())
        .collect();
    let mut paths = Vec::new();
    for (kind, data) in [
        ("actual", actual),
        ("expected", &expected[..]),
        ("diff", &diff[..]),
    ] {
        let p = dir.join(format!("{name}.{kind}.png"));
        picture(data, w, h).save(&p).expect("write picture");
        paths.push(p.display().to_string());
    }
    paths.join(", ")
}

/// A seeded test image: a dim gradient, a few hot pixels, a bright disc and
/// a bright line, as a lit scene's highlights would be.
fn test_image(w: usize, h: usize) -> Vec<f32> {
    let mut img = vec![0.0f32; w * h * 4];
    let mut seed = 12345u64;
    let mut rand = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 40) as f32 / (1u64 << 24) as f32
    };
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) * 4;
            let (fx, fy) = (x as f32 / w as f32, y as f32 / h as f32);
            let disc =
                ((x as f32 - 0.3 * w as f32).powi(2) + (y as f32 - 0.6 * h as f32).powi(2)) < 64.0;
            let line = y == h / 4 && x > w / 2;
            let hot = if disc {
                40.0
            } else if line {
                8.0
            } else {
                0.0
            };
            img[i..i + 4].copy_from_slice(&[
                0.4 * fx + hot + 0.05 * rand(),
                0.3 * fy + hot * 0.7,
                0.2 + hot * 0.4,
                1.0,
            ]);
        }
    }
    for (x, y, v) in [
        (20, 20, 500.0),
        (w.saturating_sub(30), h.saturating_sub(40), 2000.0),
        (w / 2, h / 2, 100.0),
    ] {
        if x >= w || y >= h {
            continue;
        }
        let i = (y * w + x) * 4;
        img[i..i + 3].copy_from_slice(&[v, v * 0.8, v * 0.5]);
    }
    img
}

#[test]
fn the_uploaded_kernels_sum_to_one() {
    for taps in ["direct", "linear"] {
        let s = scene(1280, 720, &format!("taps = \"{taps}\""));
        let gloss::scene::post::PostPass::Bloom(b) = &s.post[0] else {
            unreachable!()
        };
        for blur in bloom_levels::blurs(b, 1280, 720) {
            let one_side: f64 = blur.taps[1..].iter().map(|t| t.1).sum();
            let sum = blur.taps[0].1 + 2.0 * one_side;
            let sum32 = blur.taps[0].1 as f32
                + 2.0 * blur.taps[1..].iter().map(|t| t.1 as f32).sum::<f32>();
            assert!(
                (sum - 1.0).abs() < 1e-12,
                "{taps} blur{}: {sum}",
                blur.index + 1
            );
            assert!(
                (sum32 - 1.0).abs() < 1e-6,
                "{taps} blur{} in f32: {sum32}",
                blur.index + 1
            );
        }
    }
}

#[test]
fn each_level_spreads_a_pixel_by_the_notes_sigma_in_full_resolution_pixels() {
    let ctx = common::context(common::backend());
    // The blur is separable, so the spread along x needs only a wide image:
    // 2 x 799 + 1 pixels for blur4. Then the same along y.
    let (long, short) = (1800usize, 48usize);
    let mut report = Vec::new();
    for axis in 0..2 {
        let (w, h) = if axis == 0 {
            (long, short)
        } else {
            (short, long)
        };
        let (x0, y0) = (w / 2 + 3, h / 2 + 1);
        let img = point(w, h, x0, y0, 1000.0);
        for k in 0..4 {
            let mut weights = [0.0; 5];
            weights[k + 1] = 1.0;
            let s = scene(w as u32, h as u32, &format!("weights = {weights:?}"));
            let b = bloom_image(&ctx, &s, Some(&img)).unwrap_or_else(|e| panic!("{e:#}"));
            let p = psf(&b.output, w, h, x0, y0).expect("some light");
            let measured = [p.sigma.0, p.sigma.1][axis];
            let notes = NOTES_LEVELS[k];
            // The CPU reference's spread: the notes' kernel, cut at its radius.
            let reference = Kernel::gaussian(notes.sigma, notes.radius)
                .variance()
                .sqrt();
            // What the mip scheme gives exactly for this pixel: the level's
            // kernel, the upsampling tent, and where the pixel sits in its texel.
            let level = k as u32 + 1;
            let t = f64::from(1u32 << level);
            let at = [x0, y0][axis] as f64;
            let centre = t * (at / t).floor() + (t - 1.0) / 2.0;
            let kernel = level_kernel(notes.sigma, notes.radius, level);
            let exact =
                (t * t * kernel.variance() + t * t / 6.0 + 1.0 / 12.0 + (centre - at).powi(2))
                    .sqrt();
            report.push(format!(
                "blur{} along {}: measured {measured:.3} px, exact for the scheme {exact:.3}, reference {reference:.3}, notes {}",
                k + 1,
                ["x", "y"][axis],
                notes.sigma
            ));
            if (measured / exact - 1.0).abs() >= 0.002 || (measured / reference - 1.0).abs() >= 0.01
            {
                // The CPU reference's blur of the same pixel, to look at.
                let expected = gaussian_blur(&b.input, w, h, notes.sigma, notes.radius).unwrap();
                let name = format!("bloom-psf-blur{}-{}", k + 1, ["x", "y"][axis]);
                let files = write_pictures(&name, &b.output, &expected, w, h);
                panic!("{}; pictures: {files}", report.last().unwrap());
            }
        }
    }
    println!("{}", report.join("\n"));
}

/// Bloom `img` with `keys` and compare with the CPU reference; on failure
/// the pictures are written and named.
fn against_reference(
    name: &str,
    w: usize,
    h: usize,
    img: &[f32],
    keys: &str,
    rmse: f64,
    max: f64,
) -> BloomError {
    let ctx = common::context(common::backend());
    let s = scene(w as u32, h as u32, keys);
    let e = evaluate(&ctx, &s, Some(img)).unwrap_or_else(|e| panic!("{e:#}"));
    if !(e.error.rms_rel <= rmse && e.error.max_rel <= max) {
        let files = write_pictures(name, &e.bloomed.output, &e.reference, w, h);
        panic!(
            "{name}: {} (bounds: {rmse:e} root mean square, {max:e} at most); pictures: {files}",
            e.error
        );
    }
    println!("{name}: {}", e.error);
    e.error
}

/// Each blur alone (its merge weight 1, the others 0), then the whole
/// bloom, against the reference, with the bounds each must keep:
/// (name, keys, root-mean-square bound, largest bound). The full-resolution
/// scheme is off only by the half floats it stores (2^-10 of a value at
/// most, rounded toward 0); the notes' mip scheme moves a sharp feature by
/// up to 2^(k-1) - 1/2 pixels at level k (a pixel falls anywhere in its
/// texel), which changes the halo of a hot pixel by up to 15% in blur1.
const CASES: [(&str, &str, f64, f64); 9] = [
    ("blur1", "weights = [0, 1, 0, 0, 0]", 1.5e-2, 0.2),
    ("blur2", "weights = [0, 0, 1, 0, 0]", 6e-3, 5e-2),
    ("blur3", "weights = [0, 0, 0, 1, 0]", 4e-3, 5e-2),
    ("blur4", "weights = [0, 0, 0, 0, 1]", 1.2e-2, 6e-2),
    ("bloom", "", 4e-3, 8e-2),
    ("bloom-linear", "taps = \"linear\"", 4e-3, 8e-2),
    ("bloom-fewer-taps", "radius_scale = 0.5", 1e-2, 0.1),
    (
        "blur1-full",
        "weights = [0, 1, 0, 0, 0]\nscheme = \"full\"",
        6e-4,
        3e-3,
    ),
    ("bloom-full", "scheme = \"full\"", 6e-4, 3e-3),
];

#[test]
fn the_bloom_matches_the_cpu_reference() {
    let (w, h) = (384, 256);
    let img = test_image(w, h);
    for (name, keys, rms, max) in CASES {
        against_reference(name, w, h, &img, keys, rms, max);
    }
}

#[test]
fn linear_taps_differ_from_direct_taps_by_the_filter_precision() {
    // Bilinear filtering weighs a pair of texels with 8 bits of sub-texel
    // position on llvmpipe: a tap lands up to 1/512 texel off, and the
    // weights move by as much. Exact arithmetic would give the same image.
    let ctx = common::context(common::backend());
    let (w, h) = (384, 256);
    let img = test_image(w, h);
    let direct = bloom_image(&ctx, &scene(w as u32, h as u32, ""), Some(&img)).unwrap();
    let linear = bloom_image(
        &ctx,
        &scene(w as u32, h as u32, "taps = \"linear\""),
        Some(&img),
    )
    .unwrap();
    let as_f64: Vec<f64> = direct.output.iter().map(|&v| f64::from(v)).collect();
    let e = error(&linear.output, &as_f64);
    println!("linear against direct taps: {e}");
    assert!(
        e.rms_rel < 5e-4 && e.max_rel < 5e-3,
        "linear against direct taps: {e}; pictures: {}",
        write_pictures("bloom-linear-vs-direct", &linear.output, &as_f64, w, h)
    );
    assert!(e.max_rel > 0.0, "the linear taps were not used");
}

#[test]
fn every_mip_level_has_its_size_and_missing_levels_are_clamped() {
    let ctx = common::context(common::backend());
    for (w, h, sizes) in [
        (1usize, 1usize, vec![]),
        (3, 2, vec![(1, 1)]),
        (5, 3, vec![(2, 1), (1, 1)]),
        (37, 23, vec![(18, 11), (9, 5), (4, 2), (2, 1)]),
        (1280, 720, vec![(640, 360), (320, 180), (160, 90), (80, 45)]),
        (1, 17, vec![(1, 8), (1, 4), (1, 2), (1, 1)]),
    ] {
        let s = scene(w as u32, h as u32, "");
        let plan = gloss::techniques::plan(&s);
        let blurs = plan
            .passes
            .iter()
            .filter(|p| p.name == "bloom blur v")
            .count();
        assert_eq!(blurs, sizes.len(), "{w}x{h}: {plan}");
        let merge = plan
            .passes
            .iter()
            .find(|p| p.name == "bloom merge")
            .expect("a merge");
        if sizes.len() < 4 {
            assert!(
                merge.draws.contains("stands in"),
                "{w}x{h}: {}",
                merge.draws
            );
        }
        let img = test_image(w, h);
        let b = bloom_image(&ctx, &s, Some(&img)).unwrap_or_else(|e| panic!("{w}x{h}: {e:#}"));
        assert!(b.output.iter().all(|v| v.is_finite()), "{w}x{h}");
        let levels = b.renderer.targets().mip(BLOOM_LEVELS);
        assert_eq!(levels.is_some(), !sizes.is_empty(), "{w}x{h}");
        if let Some(t) = levels {
            let gl = &ctx.gl;
            for (k, &size) in sizes.iter().enumerate() {
                let level = k as u32 + 1;
                let gl_size = unsafe {
                    gl.bind_texture(glow::TEXTURE_2D, Some(t.texture.id));
                    let q = |p| gl.get_tex_level_parameter_i32(glow::TEXTURE_2D, level as i32, p);
                    let s = (q(glow::TEXTURE_WIDTH), q(glow::TEXTURE_HEIGHT));
                    gl.bind_texture(glow::TEXTURE_2D, None);
                    s
                };
                assert_eq!(gl_size, size, "{w}x{h} level {level} in GL");
                assert_eq!(level_size(w as i32, h as i32, level), size);
                let l = t.level(level).expect("the level's framebuffer");
                assert_eq!((l.width, l.height), size, "{w}x{h} level {level}");
            }
            assert_eq!(t.last() as usize, sizes.len());
        }
        // A 1x1 image has no level: every blur is the pixel itself.
        if sizes.is_empty() {
            for (o, i) in b.output.iter().zip(&b.input).take(3) {
                // Half floats round the weighted sum (1 up to f32) toward 0: one step.
                assert!((o - i).abs() <= 1e-3 * i.abs(), "1x1: {o} against {i}");
            }
        }
        ctx.debug.check(&ctx.gl, "bloom sizes").unwrap();
    }
}

#[test]
fn black_stays_exactly_black() {
    let ctx = common::context(common::backend());
    let (w, h) = (200, 120);
    for keys in ["", "taps = \"linear\"", "scheme = \"full\""] {
        let b = bloom_image(
            &ctx,
            &scene(w, h, keys),
            Some(&vec![0.0; (w * h * 4) as usize]),
        )
        .unwrap();
        let lit = b
            .output
            .chunks(4)
            .filter(|p| p[..3].iter().any(|v| *v != 0.0))
            .count();
        if lit > 0 {
            let black = vec![0.0f64; b.output.len()];
            let files = write_pictures("bloom-black", &b.output, &black, w as usize, h as usize);
            panic!("{keys}: {lit} pixels are not black; pictures: {files}");
        }
    }
}

#[test]
fn nan_and_infinity_do_not_spread() {
    let ctx = common::context(common::backend());
    let (w, h) = (160usize, 96usize);
    let mut bad: Vec<f32> = [0.5f32, 0.25, 1.0, 1.0].repeat(w * h);
    let mut clean = bad.clone();
    for (x, y, c, v, sane) in [
        (20, 30, 0, f32::NAN, 0.0),
        (80, 50, 1, f32::INFINITY, 65504.0),
        (81, 50, 2, f32::NEG_INFINITY, 0.0),
        (120, 10, 0, -3.0, 0.0),
        (121, 10, 1, 1e9, 65504.0),
    ] {
        bad[(y * w + x) * 4 + c] = v;
        clean[(y * w + x) * 4 + c] = sane;
    }
    for keys in ["", "taps = \"linear\""] {
        let s = scene(w as u32, h as u32, keys);
        let a = bloom_image(&ctx, &s, Some(&bad)).unwrap();
        let b = bloom_image(&ctx, &s, Some(&clean)).unwrap();
        let nonfinite = a.output.iter().filter(|v| !v.is_finite()).count();
        if nonfinite > 0 || a.output != b.output {
            let expected: Vec<f64> = b.output.iter().map(|&v| f64::from(v)).collect();
            let files = write_pictures("bloom-nan", &a.output, &expected, w, h);
            panic!(
                "{keys}: {nonfinite} values are NaN or inf, or sanitising on the GPU differs \
                 from blooming the image sanitised by hand; pictures: {files}"
            );
        }
    }
}

#[test]
fn a_bright_pixel_keeps_its_energy() {
    let ctx = common::context(common::backend());
    // Wide enough for blur4 (radius 799) every way, so no light reaches an edge.
    let (w, h) = (1800usize, 1800usize);
    let img = point(w, h, 900, 901, 60000.0);
    for keys in ["", "taps = \"linear\""] {
        let b = bloom_image(&ctx, &scene(w as u32, h as u32, keys), Some(&img)).unwrap();
        let (before, after) = (energy(&b.input), energy(&b.output));
        for c in 0..3 {
            let rel = after[c] / before[c] - 1.0;
            println!(
                "energy {keys}: {:.3} -> {:.3} ({rel:+.2e})",
                before[c], after[c]
            );
            assert!(
                rel.abs() < 1e-3,
                "{keys}: channel {c}: {} -> {} ({rel:+e})",
                before[c],
                after[c]
            );
        }
    }
}

#[test]
fn the_passes_restore_the_gl_state() {
    let ctx = common::context(common::backend());
    for keys in ["", "taps = \"linear\"", "scheme = \"full\""] {
        let changed = common::state_left_changed(&ctx, &scene(96, 64, keys), 96, 64);
        assert!(changed.is_empty(), "{keys}: {changed:#?}");
    }
}
