//! The post chain against its fill-rate floor: each post pass of a scene's
//! chain timed (median over the measured frames, glFinish around each
//! pass), against what filling its pixels would cost at the opaque
//! full-screen rate of this machine. A pass's pixels are its target's at
//! the mip level it draws into (`Pass::level`: bloom's blurs run at 1/4,
//! 1/16 ... of the image). The rate is measured in the same run: the
//! `invert` pass (one texel fetch, one RGBA16F write a pixel) of a chain
//! drawn at the same size.
//!
//! A pass near 1x is bound by filling pixels; far above, by its own work
//! per pixel (a blur's taps, bloom's levels).

use super::headless;
use super::{BenchArgs, Headless, Stats, add_pass_times};
use crate::frame::Runs;
use crate::gl::texture::level_size;
use crate::scene::Scene;
use crate::scene::post::chain;
use crate::techniques::ALL;
use anyhow::Result;

/// One post pass's (or one name's passes') time and size.
struct PostTime {
    name: String,
    /// Median over the measured frames.
    ms: f64,
    /// How many draws of this name a frame makes.
    steps: usize,
    /// The pixels they fill together.
    pixels: u64,
}

/// Each post pass's median time (ms) over `args.frames` frames after the
/// warm-up, in chain order, with the draws and pixels of its name.
fn post_times(ctx: &Headless, args: &BenchArgs, scene: &Scene) -> Result<Vec<PostTime>> {
    let (w, h) = scene.render.size;
    let mut r = headless::renderer(ctx, scene, (w, h))?;
    r.timing = true;
    let mut passes = Vec::new();
    for f in 0..args.warmup + args.frames.max(1) {
        r.render(&scene.camera)?;
        if f >= args.warmup {
            add_pass_times(&mut passes, r.last_times.named());
        }
    }
    // The post passes, by name, with the steps their entries take.
    let mut out: Vec<PostTime> = Vec::new();
    for p in r
        .plan
        .passes
        .iter()
        .filter(|p| ALL[p.technique].runs == Runs::AfterViews)
    {
        if out.iter().any(|t| t.name == p.name) {
            continue;
        }
        // A separable blur is two passes of one name; two entries of one
        // kind are summed (as `add_pass_times` sums their times).
        let alike: Vec<_> = (r.plan.passes.iter())
            .filter(|q| q.name == p.name)
            .collect();
        let pixels = (alike.iter())
            .map(|q| {
                let (lw, lh) = level_size(w as i32, h as i32, q.level);
                lw as u64 * lh as u64
            })
            .sum();
        let ms = (passes.iter_mut())
            .find(|(n, _)| n == p.name)
            .map_or(0.0, |(_, v)| Stats::from_samples(v).median);
        out.push(PostTime {
            name: p.name.to_string(),
            ms,
            steps: alike.len(),
            pixels,
        });
    }
    Ok(out)
}

/// The opaque full-screen floor at `scene`'s size, in ms: the median time
/// of one `invert` step (one texel fetch and one RGBA16F write a pixel) of
/// a chain drawn after the scene.
pub fn full_screen_ms(ctx: &Headless, args: &BenchArgs, scene: &Scene) -> Result<f64> {
    let mut probe = scene.clone();
    // The step's time does not depend on what the image shows: no lights,
    // so that the frames around it are quick.
    probe.lights.clear();
    probe.post = chain(&[
        toml::from_str("pass = \"invert\"")?,
        toml::from_str("pass = \"gamma\"")?,
    ])?;
    Ok(post_times(ctx, args, &probe)?
        .into_iter()
        .find(|t| t.name == "invert")
        .map_or(0.0, |t| t.ms))
}

/// The table: each post pass's time, its floor and the ratio, then the
/// whole chain's.
pub fn floor_table(ctx: &Headless, args: &BenchArgs, scene: &Scene) -> Result<String> {
    let (w, h) = scene.render.size;
    let step_ms = full_screen_ms(ctx, args, scene)?;
    let full = f64::from(w) * f64::from(h);
    let mut s = format!(
        "post chain at {w}x{h}: opaque full-screen rate {:.1} Mpixel/s (one invert step: {step_ms:.2} ms)\n",
        full / 1e6 / (step_ms / 1e3)
    );
    s.push_str(&format!(
        "  {:<18} {:>6} {:>8} {:>10} {:>10} {:>8}\n",
        "pass", "steps", "screens", "ms", "floor ms", "x floor"
    ));
    let (mut total, mut floor, mut screens) = (0.0, 0.0, 0.0);
    for t in post_times(ctx, args, scene)? {
        // Its pixels in full screens, at the full-screen rate.
        let n = t.pixels as f64 / full;
        let f = n * step_ms;
        s.push_str(&format!(
            "  {:<18} {:>6} {n:>8.3} {:>10.2} {f:>10.2} {:>8.2}\n",
            t.name,
            t.steps,
            t.ms,
            t.ms / f
        ));
        total += t.ms;
        floor += f;
        screens += n;
    }
    s.push_str(&format!(
        "  {:<18} {:>6} {screens:>8.3} {total:>10.2} {floor:>10.2} {:>8.2}\n",
        "whole chain",
        "",
        total / floor
    ));
    Ok(s)
}
