//! Each post pass against its CPU twin. An image of known values is
//! uploaded into the `hdr` target just before the chain runs (after the
//! world's last pass), so each test checks the chain alone.

use crate::common;
use gloss::frame::Runs;
use gloss::gl::Headless;
use gloss::gl::program::Sources;
use gloss::lighting::srgb_encode;
use gloss::lighting::tonemap::{gamma_encode, luminance, tonemap};
use gloss::math::gaussian::Kernel;
use gloss::renderer::{Output, Renderer};
use gloss::scene::Scene;
use gloss::scene::post::ToneOperator;
use gloss::techniques::ALL;
use glow::HasContext;

pub const W: usize = 48;
pub const H: usize = 24;

/// A scene of `W` x `H` with nothing in it but the chain `post` (TOML).
pub fn chain_scene(post: &str) -> Scene {
    let text = format!(
        "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[render]\nsize = [{W}, {H}]\n{post}"
    );
    Scene::parse(&text, std::path::Path::new("chain.toml"))
        .unwrap_or_else(|e| panic!("{e:#}\n{post}"))
}

/// Run `scene`'s chain on `input` (RGBA, bottom row first, `W` x `H`): the
/// world is drawn, then `input` replaces the `hdr` target's colour, then the
/// chain runs. Returns the renderer (its output holds the result).
pub fn run_chain(ctx: &Headless, scene: &Scene, input: &[f32], output: Output) -> Renderer {
    let gl = &ctx.gl;
    let mut r = Renderer::with_output(
        gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        W as i32,
        H as i32,
        output,
    )
    .unwrap_or_else(|e| panic!("{e:#}"));
    let hdr = r.targets().get("hdr").colors[0].id;
    let world = (r.plan.passes.iter())
        .take_while(|p| ALL[p.technique].runs != Runs::AfterViews)
        .count();
    assert!(world > 0, "a frame draws the world before its chain");
    let mut n = 0;
    let camera = scene.camera.clone();
    r.render_inspected(&camera, &mut |_| {
        n += 1;
        if n == world {
            unsafe {
                gl.bind_texture(glow::TEXTURE_2D, Some(hdr));
                gl.tex_sub_image_2d(
                    glow::TEXTURE_2D,
                    0,
                    0,
                    0,
                    W as i32,
                    H as i32,
                    glow::RGBA,
                    glow::FLOAT,
                    glow::PixelUnpackData::Slice(Some(bytes(input))),
                );
                gl.bind_texture(glow::TEXTURE_2D, None);
            }
        }
    })
    .unwrap_or_else(|e| panic!("{e:#}"));
    ctx.debug.check(gl, "the chain").unwrap();
    r
}

fn bytes(v: &[f32]) -> &[u8] {
    // SAFETY: f32 has no padding and any byte pattern is a valid u8.
    unsafe { std::slice::from_raw_parts(v.as_ptr().cast::<u8>(), std::mem::size_of_val(v)) }
}

/// A reproducible image of values k / 256 (exact in half floats) in 0..`max`.
pub fn random_image(seed: u64, max: f32) -> Vec<f32> {
    let mut s = seed;
    let mut next = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 33) % (max * 256.0) as u64) as f32 / 256.0
    };
    (0..W * H)
        .flat_map(|_| [next(), next(), next(), 1.0])
        .collect()
}

/// Compare `actual` and `expected` (RGBA, RGB checked) within `tol`; on
/// failure write both as images and name them.
pub fn assert_within(name: &str, actual: &[f32], expected: &[f32], tol: f32) {
    let mut worst = (0.0f32, 0);
    for i in (0..W * H * 4).filter(|i| i % 4 != 3) {
        // A NaN is the worst error of all.
        let d = (actual[i] - expected[i]).abs();
        let d = if d.is_nan() { f32::INFINITY } else { d };
        if d > worst.0 {
            worst = (d, i);
        }
    }
    if worst.0 > tol {
        let dir = common::out_dir();
        let save = |what: &str, v: &[f32]| {
            let img = image::RgbaImage::from_fn(W as u32, H as u32, |x, y| {
                let i = (((H as u32 - 1 - y) * W as u32 + x) * 4) as usize;
                let c = |c: f32| (srgb_encode(c) * 255.0).round() as u8;
                image::Rgba([c(v[i]), c(v[i + 1]), c(v[i + 2]), 255])
            });
            let path = dir.join(format!("post-{name}.{what}.png"));
            img.save(&path).unwrap();
            path
        };
        let (a, e) = (save("actual", actual), save("expected", expected));
        let (p, c) = (worst.1 / 4, worst.1 % 4);
        panic!(
            "{name}: pixel ({}, {}) channel {c}: {} against {} (error {} > {tol}); wrote {} and {}",
            p % W,
            p / W,
            actual[worst.1],
            expected[worst.1],
            worst.0,
            a.display(),
            e.display()
        );
    }
}

/// `f` applied to each RGB channel of `input`, alpha 1.
fn per_channel(input: &[f32], f: impl Fn(f32) -> f32) -> Vec<f32> {
    (input.chunks(4))
        .flat_map(|p| [f(p[0]), f(p[1]), f(p[2]), 1.0])
        .collect()
}

#[test]
fn tone_mapping_operators_match_their_cpu_twins() {
    let ctx = common::context(common::backend());
    // Light from 0 to 64: far past the 1.0 an 8-bit target would clip.
    let input = random_image(1, 64.0);
    for op in ToneOperator::ALL {
        for exposure in [1.0f32, 0.25] {
            let post = format!(
                "[[post]]\npass = \"tonemap\"\noperator = \"{}\"\nexposure = {exposure}\n[[post]]\npass = \"gamma\"\n",
                op.name()
            );
            let r = run_chain(&ctx, &chain_scene(&post), &input, Output::Linear32F);
            let expected = per_channel(&input, |c| tonemap(op, exposure, c));
            // The tone-mapped image passes through a half-float texture:
            // 0..1 rounds to 2^-11 (5e-4); the GPU's exp and division add little.
            assert_within(
                &format!("tonemap-{}", op.name()),
                &r.read_linear(),
                &expected,
                1e-3,
            );
        }
    }
}

#[test]
fn gamma_and_srgb_encode_as_their_formulas() {
    let ctx = common::context(common::backend());
    let input = random_image(2, 1.0);
    for (post, curve) in [
        ("gamma = 2.2", (|c| gamma_encode(2.2, c)) as fn(f32) -> f32),
        ("gamma = 1.8", |c| gamma_encode(1.8, c)),
        ("srgb = true", srgb_encode),
    ] {
        let scene = chain_scene(&format!("[[post]]\npass = \"gamma\"\n{post}\n"));
        let r = run_chain(&ctx, &scene, &input, Output::Srgb8);
        let image = r.read_image();
        let mut worst = 0i32;
        for y in 0..H {
            for x in 0..W {
                let i = ((H - 1 - y) * W + x) * 4;
                let px = image.get_pixel(x as u32, y as u32);
                for c in 0..3 {
                    let want = (curve(input[i + c]) * 255.0).round() as i32;
                    worst = worst.max((i32::from(px[c]) - want).abs());
                }
            }
        }
        // One 8-bit step: the GPU's pow and the hardware's sRGB table may
        // round the other way at a step's edge.
        assert!(worst <= 1, "{post}: off by {worst} steps of 255");
    }
    // sRGB needs the sRGB output format, and says so in the plan.
    let plan = gloss::techniques::plan(&chain_scene("[[post]]\npass = \"gamma\"\nsrgb = true\n"));
    let output = plan.target("output").unwrap();
    assert_eq!(output.colors[0].1, glow::SRGB8_ALPHA8);
}

#[test]
fn a_3x3_kernel_matches_the_cpu_convolution() {
    let ctx = common::context(common::backend());
    let input = random_image(3, 1.0);
    // Asymmetric: a flipped row or column cannot pass.
    let k = [0.5f32, 0.25, 0.0, 0.0, 0.125, 0.0, -0.125, 0.0, 0.25];
    let post = format!("[[post]]\npass = \"kernel\"\nkernel = {k:?}\n[[post]]\npass = \"gamma\"\n");
    let r = run_chain(&ctx, &chain_scene(&post), &input, Output::Linear32F);
    let mut expected = vec![1.0f32; W * H * 4];
    for y in 0..H as i64 {
        for x in 0..W as i64 {
            for c in 0..3 {
                let mut sum = 0.0f64;
                for row in 0..3i64 {
                    for col in 0..3i64 {
                        // Row 0 is the top: y + 1 in GL's bottom-up rows.
                        let qx = (x + col - 1).clamp(0, W as i64 - 1);
                        let qy = (y + 1 - row).clamp(0, H as i64 - 1);
                        let v = input[((qy * W as i64 + qx) * 4 + c) as usize];
                        sum += f64::from(k[(row * 3 + col) as usize]) * f64::from(v);
                    }
                }
                // The gamma pass clamps to 0..1 (linear output: no encoding).
                expected[((y * W as i64 + x) * 4 + c) as usize] = (sum as f32).clamp(0.0, 1.0);
            }
        }
    }
    assert_within("kernel", &r.read_linear(), &expected, 1e-3);
}

/// The separable convolution of `input` by `k` on the CPU in f64, rows
/// first, clamped at the edges, the intermediate rounded as the GPU's
/// half-float texture rounds it (to 2^-11 relative).
fn cpu_blur(input: &[f32], k: &Kernel) -> Vec<f32> {
    let r = k.radius as i64;
    let at = |v: &[f64], x: i64, y: i64, c: usize| {
        v[((y.clamp(0, H as i64 - 1) * W as i64 + x.clamp(0, W as i64 - 1)) * 4) as usize + c]
    };
    let src: Vec<f64> = input.iter().map(|&v| f64::from(v)).collect();
    let mut rows = src.clone();
    let mut out = vec![1.0f32; W * H * 4];
    for pass in 0..2 {
        let from = if pass == 0 { src.clone() } else { rows.clone() };
        for y in 0..H as i64 {
            for x in 0..W as i64 {
                for c in 0..3 {
                    let mut sum = 0.0;
                    for i in -r..=r {
                        let v = if pass == 0 {
                            at(&from, x + i, y, c)
                        } else {
                            at(&from, x, y + i, c)
                        };
                        sum += k.weight(i) * v;
                    }
                    let i = ((y * W as i64 + x) * 4) as usize + c;
                    if pass == 0 {
                        rows[i] = f64::from(half_round(sum as f32));
                    } else {
                        out[i] = sum as f32;
                    }
                }
            }
        }
    }
    out
}

/// `v` rounded to the nearest half float (11 significant bits).
fn half_round(v: f32) -> f32 {
    if v == 0.0 {
        return 0.0;
    }
    let e = v.abs().log2().floor();
    let step = 2f32.powf(e - 10.0);
    (v / step).round() * step
}

#[test]
fn separable_blur_matches_the_cpu_convolution() {
    let ctx = common::context(common::backend());
    let input = random_image(4, 1.0);
    for (entry, kernel, tol) in [
        // Direct taps fetch whole texels: only half-float rounding (5e-4).
        (
            "pass = \"blur\"\nsigma = 2.0\nradius = 6\ntaps = \"direct\"",
            Kernel::gaussian(2.0, 6),
            1e-3,
        ),
        // Linear taps: the bilinear weights have 8 bits of sub-texel
        // precision on llvmpipe, an error of up to 1/512 of a neighbour
        // difference per tap pair.
        (
            "pass = \"blur\"\nsigma = 2.0\nradius = 6\ntaps = \"linear\"",
            Kernel::gaussian(2.0, 6),
            4e-3,
        ),
        ("pass = \"box\"\nradius = 3", Kernel::box_(3), 1e-3),
    ] {
        let post = format!("[[post]]\n{entry}\n[[post]]\npass = \"gamma\"\n");
        let r = run_chain(&ctx, &chain_scene(&post), &input, Output::Linear32F);
        let name = entry
            .lines()
            .map(|l| l.split('=').nth(1).unwrap_or("").trim())
            .collect::<Vec<_>>()
            .join("-");
        assert_within(
            &format!("blur{name}"),
            &r.read_linear(),
            &cpu_blur(&input, &kernel),
            tol,
        );
    }
}

#[test]
fn grayscale_and_invert_match_their_formulas() {
    let ctx = common::context(common::backend());
    let input = random_image(5, 2.0);
    let grey: Vec<f32> = (input.chunks(4))
        .flat_map(|p| {
            let l = luminance([p[0], p[1], p[2]]).min(1.0);
            [l, l, l, 1.0]
        })
        .collect();
    let r = run_chain(
        &ctx,
        &chain_scene("[[post]]\npass = \"grayscale\"\n[[post]]\npass = \"gamma\"\n"),
        &input,
        Output::Linear32F,
    );
    assert_within("grayscale", &r.read_linear(), &grey, 1e-3);
    let r = run_chain(
        &ctx,
        &chain_scene("[[post]]\npass = \"invert\"\n[[post]]\npass = \"gamma\"\n"),
        &input,
        Output::Linear32F,
    );
    let inverted = per_channel(&input, |c| 1.0 - c.clamp(0.0, 1.0));
    assert_within("invert", &r.read_linear(), &inverted, 1e-3);
}

/// One NaN and one infinite pixel (a division by zero upstream) must not
/// spread through a neighbourhood pass: both passes read through
/// glsl/post/finite.glsl (NaN as 0, +inf as 65504), and give what the CPU
/// gives on the image sanitised alike.
#[test]
fn a_nan_or_inf_pixel_does_not_spread_through_a_blur_or_a_kernel() {
    let ctx = common::context(common::backend());
    let mut input = random_image(6, 1.0);
    let (nan, inf) = ((H / 2 * W + 10) * 4, (H / 3 * W + 30) * 4);
    input[nan..nan + 3].copy_from_slice(&[f32::NAN; 3]);
    input[inf] = f32::INFINITY;
    let mut clean = input.clone();
    clean[nan..nan + 3].copy_from_slice(&[0.0; 3]);
    clean[inf] = 65504.0;
    let post = "[[post]]\npass = \"blur\"\nsigma = 2.0\nradius = 6\ntaps = \"direct\"\n[[post]]\npass = \"gamma\"\n";
    let r = run_chain(&ctx, &chain_scene(post), &input, Output::Linear32F);
    let out = r.read_linear();
    assert!(
        out.iter().all(|v| v.is_finite()),
        "a NaN or inf came through the blur"
    );
    let expected = per_channel(&cpu_blur(&clean, &Kernel::gaussian(2.0, 6)), |c| {
        c.clamp(0.0, 1.0)
    });
    assert_within("blur-nan-inf", &out, &expected, 1e-3);
    let post = "[[post]]\npass = \"sharpen\"\n[[post]]\npass = \"gamma\"\n";
    let r = run_chain(&ctx, &chain_scene(post), &input, Output::Linear32F);
    assert!(
        r.read_linear().iter().all(|v| v.is_finite()),
        "a NaN or inf came through the kernel"
    );
}
