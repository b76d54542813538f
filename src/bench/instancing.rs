//! `gloss bench --instancing 1000,10000,100000`: instanced draws against one
//! draw per object (LearnOpenGL, Instancing; techniques/vertex_geometry/
//! instancing.rs). For each rock count, both ways on the same field: the
//! CPU time to issue the rocks' GL calls (CPU clock around the calls, no
//! glFinish: what the application thread spends), the pass's time and the
//! frame's (CPU clock around glFinish), the bytes of transforms sent each
//! frame (64 a rock as uniforms; none instanced, after the one upload) and
//! the largest difference between the two images (they must be equal).

use super::headless;
use super::{BenchArgs, Headless, Stats};
use crate::scene::Scene;
use crate::scene::instancing::MAX_ROCKS;
use crate::techniques::vertex_geometry::instancing::{bytes_per_frame, last_submit_ms};
use anyhow::{Result, bail};

struct Row {
    count: u32,
    form: &'static str,
    bytes: usize,
    submit_ms: f64,
    pass_ms: f64,
    frame_ms: f64,
    max_diff: u8,
}

pub(super) fn run(args: &BenchArgs, base: &Scene, ctx: &Headless) -> Result<()> {
    let Some(f0) = base.instancing.clone() else {
        bail!(
            "{}: has no [instancing] table to measure",
            base.path.display()
        );
    };
    let (w, h) = args.size.unwrap_or(base.render.size);
    let mut rows = Vec::new();
    for &count in &args.instancing {
        let count = (count as u32).clamp(1, MAX_ROCKS);
        let mut images = Vec::new();
        for (instanced, form) in [(true, "instanced"), (false, "one draw per rock")] {
            let mut s = base.clone();
            let mut field = f0.clone();
            field.count = count;
            s.instancing = Some(field.clone());
            s.render.instancing = instanced;
            s.render.size = (w, h);
            let mut r = headless::renderer(ctx, &s, (w, h))?;
            r.timing = true;
            let (mut submit, mut pass, mut frame) = (Vec::new(), Vec::new(), Vec::new());
            for i in 0..args.warmup + args.frames.max(1) {
                eprint!("\r{count} rocks, {form}: frame {}   ", i + 1);
                r.render(&s.camera)?;
                if i < args.warmup {
                    continue;
                }
                submit.push(last_submit_ms());
                pass.push(r.last_times.pass_ms("instancing"));
                frame.push(r.last_times.frame_ms);
            }
            images.push(r.read_image());
            rows.push(Row {
                count,
                form,
                bytes: bytes_per_frame(&field, instanced),
                submit_ms: Stats::from_samples(&mut submit).median,
                pass_ms: Stats::from_samples(&mut pass).median,
                frame_ms: Stats::from_samples(&mut frame).median,
                max_diff: 0,
            });
        }
        let max_diff = (images[0].pixels().zip(images[1].pixels()))
            .flat_map(|(a, b)| (0..3).map(move |c| a[c].abs_diff(b[c])))
            .max()
            .unwrap_or(0);
        let n = rows.len();
        rows[n - 1].max_diff = max_diff;
    }
    eprintln!();
    println!("{}", table(&rows));
    Ok(())
}

fn table(rows: &[Row]) -> String {
    let mut s = format!(
        "{:>7}  {:<18} {:>12} {:>10} {:>9} {:>9} {:>9}\n",
        "rocks", "draws", "bytes/frame", "CPU ms", "pass ms", "frame ms", "max diff"
    );
    for r in rows {
        s.push_str(&format!(
            "{:>7}  {:<18} {:>12} {:>10.3} {:>9.2} {:>9.2} {:>9}\n",
            r.count, r.form, r.bytes, r.submit_ms, r.pass_ms, r.frame_ms, r.max_diff
        ));
    }
    for pair in rows.chunks(2) {
        if let [a, b] = pair {
            s.push_str(&format!(
                "{} rocks: instanced issues its calls in {:.3} ms against {:.3} ms ({:.0}x less CPU time), frame {:.2} ms against {:.2} ms; {} bytes of transforms a frame against {}; images differ by at most {}/255\n",
                a.count,
                a.submit_ms,
                b.submit_ms,
                b.submit_ms / a.submit_ms.max(1e-6),
                a.frame_ms,
                b.frame_ms,
                a.bytes,
                b.bytes,
                b.max_diff
            ));
        }
    }
    s
}
