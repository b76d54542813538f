//! `gloss bench --filtering`: texture filtering measured (notes 01
//! §5.2-5.3.1; docs/texture_mapping/texture_mapping.md).
//!
//! The reference is the scene (default scenes/texture-filtering.toml: a
//! checkerboard floor to the horizon) point-sampled from the full-size
//! texture (`render.texture_filter = "nearest"`) at 8x the width and the
//! height, 64 samples a pixel, box-filtered down in linear light: what an
//! ideal filter would show. Each filter is rendered at the scene's size and
//! compared with it, as RMSE x 255 of the display values (src/bench/aa.rs
//! `error`). Times: the median and the 10th-90th percentiles of the frame
//! and of the forward pass, on the CPU clock around glFinish.

use super::aa::{LinearImage, error, render_linear};
use super::headless;
use super::{BenchArgs, Stats};
use crate::gl::Headless;
use crate::scene::Scene;
use crate::scene::texturing::FilterOverride;
use anyhow::{Context as _, Result, bail};
use std::fmt::Write as _;
use std::path::Path;

/// Supersampling factor of the reference along each axis (64 samples a pixel).
pub const FACTOR: u32 = 8;

/// The filters measured, in the notes' order.
pub const FILTERS: [FilterOverride; 6] = [
    FilterOverride::Nearest,
    FilterOverride::Bilinear,
    FilterOverride::NearestMip,
    FilterOverride::BilinearMip,
    FilterOverride::Trilinear,
    FilterOverride::Anisotropic,
];

/// One filter's figures.
pub struct FilterRow {
    pub filter: FilterOverride,
    pub frame: Stats,
    pub forward: Stats,
    /// RMSE of the display values against the reference, 0..1.
    pub rmse: f64,
}

/// The reference: `scene` point-sampled at `FACTOR` x its size, box-filtered down.
pub fn reference(ctx: &Headless, scene: &Scene) -> Result<LinearImage> {
    let (w, h) = scene.render.size;
    if w * FACTOR > 8192 || h * FACTOR > 8192 {
        bail!("{w}x{h}: the {FACTOR}x reference would pass 8192 pixels a side; use --size");
    }
    let mut s = scene.clone();
    s.render.texture_filter = FilterOverride::Nearest;
    Ok(render_linear(ctx, &s, w * FACTOR, h * FACTOR)?.box_down(FACTOR))
}

/// Every filter of `FILTERS` on `base`: error against `reference`, and times
/// over `warmup` + `frames` frames.
pub fn measure(
    ctx: &Headless,
    base: &Scene,
    reference: &LinearImage,
    warmup: usize,
    frames: usize,
) -> Result<Vec<FilterRow>> {
    let (w, h) = base.render.size;
    let none = vec![false; (w * h) as usize];
    let mut rows = Vec::new();
    for filter in FILTERS {
        let mut scene = base.clone();
        scene.render.texture_filter = filter;
        let image = render_linear(ctx, &scene, w, h)?;
        let rmse = error(&image, reference, &none)?.rmse;
        let mut r =
            headless::renderer(ctx, &scene, (w, h)).with_context(|| format!("filter {filter}"))?;
        r.timing = true;
        let (mut frame, mut forward) = (Vec::new(), Vec::new());
        for f in 0..warmup + frames {
            eprint!("\r{filter:<14} frame {}/{}   ", f + 1, warmup + frames);
            r.render(&scene.camera)?;
            if f >= warmup {
                frame.push(r.last_times.frame_ms);
                forward.push(r.last_times.pass_ms("forward"));
            }
        }
        rows.push(FilterRow {
            filter,
            frame: Stats::from_samples(&mut frame),
            forward: Stats::from_samples(&mut forward),
            rmse,
        });
    }
    eprintln!();
    Ok(rows)
}

pub(super) fn run(args: &BenchArgs, scene_path: &Path, ctx: &Headless) -> Result<()> {
    let mut base = Scene::load_with(scene_path, &args.set)?;
    if let Some(size) = args.size {
        base.render.size = size;
    }
    let (w, h) = base.render.size;
    eprintln!(
        "gloss bench --filtering: {} at {w}x{h} on {} (max anisotropy {}), against {FACTOR}x{FACTOR} point samples; {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        ctx.info.max_anisotropy,
        args.warmup,
        args.frames
    );
    let reference = reference(ctx, &base)?;
    let rows = measure(ctx, &base, &reference, args.warmup, args.frames)?;
    println!("{}", table(&rows));
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let csv = args.out.join("filtering.csv");
    let mut text = String::from("filter,frame_ms,frame_p10,frame_p90,forward_ms,rmse_x255\n");
    for r in &rows {
        let _ = writeln!(
            text,
            "{},{:.4},{:.4},{:.4},{:.4},{:.4}",
            r.filter,
            r.frame.median,
            r.frame.p10,
            r.frame.p90,
            r.forward.median,
            r.rmse * 255.0
        );
    }
    std::fs::write(&csv, text).with_context(|| format!("writing {}", csv.display()))?;
    println!("wrote {}", csv.display());
    Ok(())
}

/// The table `gloss bench --filtering` prints.
pub fn table(rows: &[FilterRow]) -> String {
    let mut s = String::from("times: median (p10-p90) ms, cpu+glFinish\n");
    let _ = writeln!(
        s,
        "{:<14} {:>20} {:>20} {:>10}",
        "filter", "frame", "forward pass", "RMSE x255"
    );
    let t = |x: &Stats| format!("{:.2} ({:.2}-{:.2})", x.median, x.p10, x.p90);
    for r in rows {
        let _ = writeln!(
            s,
            "{:<14} {:>20} {:>20} {:>10.2}",
            r.filter.name(),
            t(&r.frame),
            t(&r.forward),
            r.rmse * 255.0
        );
    }
    s
}
