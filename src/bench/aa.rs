//! `gloss bench SCENE --aa`: anti-aliasing measured (notes 01 §8.6, "may
//! need to perform anti-aliasing on final scene to remove jaggedness from
//! edges"; docs/post/fxaa.md, docs/fragment_tests/msaa.md).
//!
//! The reference is the scene with no anti-aliasing rendered at 4x the
//! width and the height, 16 samples per pixel on a regular grid, and
//! box-filtered down in linear light (the mean of each 4x4 block of linear
//! RGB). Each setting (none, FXAA, MSAA 2/4/8, MSAA 4 + FXAA) is rendered at
//! the scene's size, and compared with it:
//!
//! - RMSE x 255 over every pixel and channel, on display values (both
//!   images sRGB-encoded, 0..255), as a screen shows the difference;
//! - the same over the *edge pixels* only: where the reference's display
//!   luma differs from a 4-neighbour's by more than `EDGE_STEP` (most pixels
//!   are flat, and anti-aliasing changes nothing there).
//!
//! Times: the median and the 10th-90th percentiles of the frame, of the
//! forward pass (which pays for MSAA's samples) and of the AA passes (the
//! MSAA resolve plus FXAA), on the CPU clock around glFinish
//! (src/frame/timing.rs).

use super::headless;
use super::{BenchArgs, Stats};
use crate::gl::Headless;
use crate::gl::program::Sources;
use crate::lighting::srgb_encode;
use crate::renderer::{Output, Renderer};
use crate::scene::Scene;
use crate::scene::fxaa::Fxaa;
use crate::scene::post::PostPass;
use anyhow::{Context as _, Result, bail};
use std::fmt::Write as _;
use std::path::Path;

/// Supersampling factor of the reference along each axis (16 samples a pixel).
pub const FACTOR: u32 = 4;

/// A pixel is on an edge where the reference's display luma (0..1) steps
/// by more than this to one of its four neighbours.
pub const EDGE_STEP: f32 = 1.0 / 16.0;

/// One setting: a label, MSAA samples, FXAA on or off.
pub const SETTINGS: [(&str, u32, bool); 6] = [
    ("none", 1, false),
    ("FXAA", 1, true),
    ("MSAA 2", 2, false),
    ("MSAA 4", 4, false),
    ("MSAA 8", 8, false),
    ("MSAA 4 + FXAA", 4, true),
];

/// Linear RGB, top row first.
#[derive(Clone, Debug)]
pub struct LinearImage {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<f32>,
}

impl LinearImage {
    /// From a renderer's RGBA32F output (bottom row first).
    pub fn read(r: &Renderer) -> LinearImage {
        let (w, h) = (r.width as usize, r.height as usize);
        let rgba = r.read_linear();
        let mut rgb = Vec::with_capacity(w * h * 3);
        for y in (0..h).rev() {
            for x in 0..w {
                rgb.extend_from_slice(&rgba[(y * w + x) * 4..][..3]);
            }
        }
        LinearImage {
            width: w as u32,
            height: h as u32,
            rgb,
        }
    }

    /// The mean of each `k` x `k` block: a box filter in linear light.
    pub fn box_down(&self, k: u32) -> LinearImage {
        let (w, h) = (self.width / k, self.height / k);
        let mut rgb = vec![0.0f32; (w * h * 3) as usize];
        for y in 0..h {
            for x in 0..w {
                for c in 0..3 {
                    let mut sum = 0.0f64;
                    for j in 0..k {
                        for i in 0..k {
                            let (sx, sy) = (x * k + i, y * k + j);
                            sum += f64::from(self.rgb[((sy * self.width + sx) * 3 + c) as usize]);
                        }
                    }
                    rgb[((y * w + x) * 3 + c) as usize] = (sum / f64::from(k * k)) as f32;
                }
            }
        }
        LinearImage {
            width: w,
            height: h,
            rgb,
        }
    }

    /// The display luma of pixel `i` (Rec. 709 weights of the sRGB-encoded channels).
    fn display_luma(&self, i: usize) -> f32 {
        let c = |k: usize| srgb_encode(self.rgb[i * 3 + k]);
        0.2126 * c(0) + 0.7152 * c(1) + 0.0722 * c(2)
    }
}

/// `base` with `msaa` samples and with or without FXAA: FXAA is the
/// scene's own entry, or a default one right before the chain's last pass
/// (gamma). FXAA needs a chain with a tonemap.
pub fn variant(base: &Scene, msaa: u32, fxaa: bool) -> Result<Scene> {
    let mut s = base.clone();
    s.render.msaa = msaa;
    let own = (s.post.iter())
        .find(|p| matches!(p, PostPass::Fxaa(_)))
        .cloned();
    s.post.retain(|p| !matches!(p, PostPass::Fxaa(_)));
    if fxaa {
        let tonemap = s
            .post
            .iter()
            .position(|p| matches!(p, PostPass::Tonemap { .. }));
        let Some(t) = tonemap else {
            bail!(
                "{}: FXAA needs a [[post]] chain with a tonemap pass (it sits after tonemap, before gamma)",
                base.name
            );
        };
        s.post
            .insert(t + 1, own.unwrap_or(PostPass::Fxaa(Fxaa::default())));
    }
    Ok(s)
}

/// Render `scene` at `w` x `h` into the RGBA32F output.
pub fn render_linear(ctx: &Headless, scene: &Scene, w: u32, h: u32) -> Result<LinearImage> {
    let mut s = scene.clone();
    s.render.size = (w, h);
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &s,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Linear32F,
    )?;
    r.render(&s.camera)?;
    Ok(LinearImage::read(&r))
}

/// The reference: `scene` with no MSAA and no FXAA at `FACTOR` x its size,
/// box-filtered down in linear light.
pub fn reference(ctx: &Headless, scene: &Scene) -> Result<LinearImage> {
    let (w, h) = scene.render.size;
    if w * FACTOR > 8192 || h * FACTOR > 8192 {
        bail!("{w}x{h}: the {FACTOR}x reference would pass 8192 pixels a side; use --size");
    }
    let plain = variant(scene, 1, false)?;
    Ok(render_linear(ctx, &plain, w * FACTOR, h * FACTOR)?.box_down(FACTOR))
}

/// The edge pixels of `reference` (see `EDGE_STEP`), top row first.
pub fn edge_mask(reference: &LinearImage) -> Vec<bool> {
    let (w, h) = (reference.width as i64, reference.height as i64);
    let luma: Vec<f32> = (0..(w * h) as usize)
        .map(|i| reference.display_luma(i))
        .collect();
    let at = |x: i64, y: i64| luma[(y.clamp(0, h - 1) * w + x.clamp(0, w - 1)) as usize];
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let m = at(x, y);
            [(1, 0), (-1, 0), (0, 1), (0, -1)]
                .iter()
                .any(|(dx, dy)| (at(x + dx, y + dy) - m).abs() > EDGE_STEP)
        })
        .collect()
}

/// An image's error against the reference, in 0..1 display units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AaError {
    pub rmse: f64,
    pub edge_rmse: f64,
    pub edge_pixels: usize,
}

/// RMSE of the sRGB-encoded RGB of `image` against `reference`, over every
/// pixel and over the pixels `edges` marks.
pub fn error(image: &LinearImage, reference: &LinearImage, edges: &[bool]) -> Result<AaError> {
    if (image.width, image.height) != (reference.width, reference.height) {
        bail!(
            "{}x{} image against a {}x{} reference",
            image.width,
            image.height,
            reference.width,
            reference.height
        );
    }
    let (mut all, mut edge, mut n_edge) = (0.0f64, 0.0f64, 0usize);
    for (i, &is_edge) in edges.iter().enumerate() {
        let mut sq = 0.0f64;
        for c in 0..3 {
            let d = srgb_encode(image.rgb[i * 3 + c]) - srgb_encode(reference.rgb[i * 3 + c]);
            sq += f64::from(d) * f64::from(d);
        }
        all += sq;
        if is_edge {
            edge += sq;
            n_edge += 1;
        }
    }
    Ok(AaError {
        rmse: (all / (3 * edges.len()).max(1) as f64).sqrt(),
        edge_rmse: (edge / (3 * n_edge).max(1) as f64).sqrt(),
        edge_pixels: n_edge,
    })
}

/// One row of the table.
struct Row {
    label: &'static str,
    samples: i32,
    frame: Stats,
    forward: Stats,
    aa: Stats,
    error: AaError,
}

pub(super) fn run(args: &BenchArgs, scene_path: &Path, ctx: &Headless) -> Result<()> {
    let mut base = Scene::load_with(scene_path, &args.set)?;
    if let Some(size) = args.size {
        base.render.size = size;
    }
    let (w, h) = base.render.size;
    eprintln!(
        "gloss bench --aa: {} at {w}x{h} on {}, against {FACTOR}x{FACTOR} supersampling; {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        args.warmup,
        args.frames
    );
    let reference = reference(ctx, &base)?;
    let edges = edge_mask(&reference);
    let mut rows = Vec::new();
    for (label, msaa, fxaa) in SETTINGS {
        let scene = variant(&base, msaa, fxaa)?;
        let image = render_linear(ctx, &scene, w, h)?;
        let error = error(&image, &reference, &edges)?;
        let mut r =
            headless::renderer(ctx, &scene, (w, h)).with_context(|| format!("setting {label}"))?;
        r.timing = true;
        let samples = r
            .targets()
            .find(crate::frame::multisample::MSAA)
            .map_or(1, |t| t.colors[0].samples);
        let (mut frame, mut forward, mut aa) = (Vec::new(), Vec::new(), Vec::new());
        for f in 0..args.warmup + args.frames {
            eprint!(
                "\r{label:<14} frame {}/{}   ",
                f + 1,
                args.warmup + args.frames
            );
            r.render(&scene.camera)?;
            if f < args.warmup {
                continue;
            }
            let t = &r.last_times;
            let sum = |names: &[&str]| -> f64 {
                (t.passes.iter())
                    .filter(|(n, _)| names.contains(n))
                    .map(|(_, ms)| ms)
                    .sum()
            };
            frame.push(t.frame_ms);
            forward.push(sum(&["forward"]));
            aa.push(sum(&["msaa resolve", "fxaa"]));
        }
        rows.push(Row {
            label,
            samples,
            frame: Stats::from_samples(&mut frame),
            forward: Stats::from_samples(&mut forward),
            aa: Stats::from_samples(&mut aa),
            error,
        });
    }
    eprintln!();
    let text = table(&rows, edges.iter().filter(|&&e| e).count(), edges.len());
    println!("{text}");
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let csv = args.out.join("aa.csv");
    std::fs::write(&csv, csv_text(&rows)).with_context(|| format!("writing {}", csv.display()))?;
    println!("wrote {}", csv.display());
    Ok(())
}

fn table(rows: &[Row], edge: usize, all: usize) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "edge pixels: {edge} of {all} ({:.1}%); times: median (p10-p90) ms, cpu+glFinish",
        100.0 * edge as f64 / all.max(1) as f64
    );
    let _ = writeln!(
        s,
        "{:<14} {:>7} {:>20} {:>20} {:>20} {:>10} {:>15}",
        "setting", "samples", "frame", "forward pass", "AA passes", "RMSE x255", "edge RMSE x255"
    );
    let t = |x: &Stats| format!("{:.2} ({:.2}-{:.2})", x.median, x.p10, x.p90);
    for r in rows {
        let _ = writeln!(
            s,
            "{:<14} {:>7} {:>20} {:>20} {:>20} {:>10.2} {:>15.2}",
            r.label,
            r.samples,
            t(&r.frame),
            t(&r.forward),
            t(&r.aa),
            r.error.rmse * 255.0,
            r.error.edge_rmse * 255.0
        );
    }
    s
}

fn csv_text(rows: &[Row]) -> String {
    let mut s = String::from(
        "setting,samples,frame_ms,frame_p10,frame_p90,forward_ms,aa_ms,rmse_x255,edge_rmse_x255,edge_pixels\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{}",
            r.label,
            r.samples,
            r.frame.median,
            r.frame.p10,
            r.frame.p90,
            r.forward.median,
            r.aa.median,
            r.error.rmse * 255.0,
            r.error.edge_rmse * 255.0,
            r.error.edge_pixels
        );
    }
    s
}
