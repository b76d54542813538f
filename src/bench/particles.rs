//! `gloss bench --particles 1000,10000,...`: notes 01 §3.2's claim that
//! turning points into quads in the geometry shader "saves (~75%) CPU time
//! copying primitives to the GPU", measured. For each particle count and
//! each way (points and the geometry shader, or quads built on the CPU;
//! the buffer written through a mapped pointer, or with glBufferSubData):
//! the bytes sent a frame, the CPU time to build them (median over the
//! frames, clock around `pack`), the particle pass's time (simulation,
//! packing, upload and draw, glFinish after), and the frame's.
//!
//! The scene's emitter is kept; its rate is set so that `count` particles
//! are alive, and the time to a full lifetime on.

use super::headless;
use super::{BenchArgs, Headless, Stats};
use crate::frame::particles;
use crate::scene::Scene;
use crate::techniques::vertex_geometry::particles::pack;
use anyhow::{Result, bail};
use std::time::Instant;

struct Row {
    count: usize,
    form: &'static str,
    stream: &'static str,
    bytes: usize,
    pack_ms: f64,
    pass_ms: f64,
    frame_ms: f64,
}

pub(super) fn run(args: &BenchArgs, base: &Scene, ctx: &Headless) -> Result<()> {
    let Some(p0) = base.particles.clone() else {
        bail!(
            "{}: has no [particles] table to measure",
            base.path.display()
        );
    };
    let (w, h) = args.size.unwrap_or(base.render.size);
    let mut rows = Vec::new();
    for &count in &args.particles {
        for (gs, form) in [
            (true, "points + geometry shader"),
            (false, "quads built on the CPU"),
        ] {
            for (map, stream) in [(true, "glMapBufferRange"), (false, "glBufferSubData")] {
                let mut s = base.clone();
                let mut p = p0.clone();
                p.count = count.clamp(1, crate::scene::particles::MAX_PARTICLES as usize) as u32;
                p.rate = p.count as f32 / p.lifetime;
                p.geometry_shader = gs;
                p.map = map;
                s.particles = Some(p.clone());
                s.set_time(p.lifetime + 0.25)?;
                s.render.size = (w, h);
                let mut r = headless::renderer(ctx, &s, (w, h))?;
                r.timing = true;
                let (mut pack_ms, mut pass_ms, mut frame_ms) = (Vec::new(), Vec::new(), Vec::new());
                let alive = particles::alive(&p, s.animation.time);
                let view = s.camera.view();
                let mut bytes = Vec::new();
                for f in 0..args.warmup + args.frames.max(1) {
                    eprint!("\r{count} particles, {form}, {stream}: frame {}   ", f + 1);
                    let t = Instant::now();
                    pack(&p, &alive, &view, &mut bytes);
                    let packing = t.elapsed().as_secs_f64() * 1e3;
                    r.render(&s.camera)?;
                    if f < args.warmup {
                        continue;
                    }
                    pack_ms.push(packing);
                    frame_ms.push(r.last_times.frame_ms);
                    pass_ms.push(r.last_times.pass_ms("particles"));
                }
                rows.push(Row {
                    count: alive.len(),
                    form,
                    stream,
                    bytes: bytes.len(),
                    pack_ms: Stats::from_samples(&mut pack_ms).median,
                    pass_ms: Stats::from_samples(&mut pass_ms).median,
                    frame_ms: Stats::from_samples(&mut frame_ms).median,
                });
            }
        }
    }
    eprintln!();
    println!("{}", table(&rows));
    Ok(())
}

fn table(rows: &[Row]) -> String {
    let mut s = format!(
        "{:>9}  {:<26} {:<17} {:>12} {:>9} {:>10} {:>10}\n",
        "particles", "form", "stream", "bytes/frame", "build ms", "pass ms", "frame ms"
    );
    for r in rows {
        s.push_str(&format!(
            "{:>9}  {:<26} {:<17} {:>12} {:>9.3} {:>10.2} {:>10.2}\n",
            r.count, r.form, r.stream, r.bytes, r.pack_ms, r.pass_ms, r.frame_ms
        ));
    }
    // Per count: what the points save against the CPU's quads (mapped).
    for chunk in rows.chunks(4) {
        if let [gs, _, cpu, _] = chunk {
            let saved = |a: f64, b: f64| if b > 0.0 { 100.0 * (1.0 - a / b) } else { 0.0 };
            s.push_str(&format!(
                "{} particles: the geometry shader sends {:.0}% fewer bytes and builds them in {:.0}% less CPU time; its pass takes {:.2} ms against {:.2} ms (both mapped)\n",
                gs.count,
                saved(gs.bytes as f64, cpu.bytes as f64),
                saved(gs.pack_ms, cpu.pack_ms),
                gs.pass_ms,
                cpu.pass_ms,
            ));
        }
    }
    s
}
