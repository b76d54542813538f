//! `gloss bench --skinning 1000,10000,...`: skinned meshes (notes 01 §7.1)
//! skinned on the GPU by the skinning pass against the CPU reference, at
//! about these many skinned vertices. The scene's skinned objects are
//! copied (side by side, behind one another) until the count is reached;
//! every frame moves the clip's time on, so that both ways pose every
//! frame, as the demo does while it plays.
//!
//! For each count, method (linear blend, dual quaternions) and place:
//! - "pose ms": the CPU time of taking the new instant
//!   (`Renderer::set_scene_values`: the joint matrices, and on the CPU the
//!   skinning and the glBufferSubData of every vertex);
//! - "bytes/frame": what goes to the GPU for the skins each frame;
//! - "pass ms": the skinning pass (glFinish after; 0 on the CPU);
//! - "frame ms": the whole frame after it;
//! - "max error": the largest distance between a vertex the GPU skinned and
//!   the CPU reference's, read back from the transform feedback buffers.

use super::headless;
use super::{BenchArgs, Headless, Stats};
use crate::renderer::Renderer;
use crate::scene::{Scene, SkinMethod, SkinningOn};
use anyhow::{Result, bail};
use glow::HasContext;
use std::time::Instant;

struct Row {
    vertices: usize,
    method: SkinMethod,
    on: SkinningOn,
    bytes: usize,
    pose_ms: f64,
    pass_ms: f64,
    frame_ms: f64,
    error: f32,
}

/// `base` with its skinned objects copied `copies` times in all.
fn copied(base: &Scene, copies: usize, method: SkinMethod, on: SkinningOn) -> Scene {
    let mut s = base.clone();
    s.render.skinning_on = on;
    let skinned: Vec<_> = (s.objects.iter())
        .filter(|o| o.skin.is_some() && o.parent.is_none())
        .cloned()
        .collect();
    s.objects.retain(|o| o.skin.is_none());
    for k in 0..copies {
        let mut o = skinned[k % skinned.len()].clone();
        let row = (k / skinned.len()) as f32;
        o.name = format!("{} {k}", o.name);
        o.position.z -= 0.6 * row;
        o.skin.as_mut().unwrap().method = method;
        s.objects.push(o);
    }
    crate::scene::update_models(&mut s.objects);
    s
}

pub(super) fn run(args: &BenchArgs, base: &Scene, ctx: &Headless) -> Result<()> {
    let Some(one) = base.objects.iter().find_map(|o| o.skin.as_ref()) else {
        bail!("{}: has no skinned object to measure", base.path.display());
    };
    let per = one.mesh.mesh.vertices.len();
    let (w, h) = args.size.unwrap_or(base.render.size);
    let (first, last) = base.skin_span().unwrap_or((0.0, 1.0));
    let mut rows = Vec::new();
    for &count in &args.skinning {
        let copies = count.div_ceil(per).clamp(1, 4096);
        for method in [SkinMethod::Linear, SkinMethod::DualQuaternion] {
            for on in [SkinningOn::Gpu, SkinningOn::Cpu] {
                let mut s = copied(base, copies, method, on);
                s.render.size = (w, h);
                let mut r = headless::renderer(ctx, &s, (w, h))?;
                r.timing = true;
                let (mut pose_ms, mut pass_ms, mut frame_ms) = (Vec::new(), Vec::new(), Vec::new());
                let frames = args.warmup + args.frames.max(1);
                for f in 0..frames {
                    eprint!(
                        "\r{} vertices, {method}, {on}: frame {}   ",
                        copies * per,
                        f + 1
                    );
                    let t = first + (last - first) * f as f32 / frames as f32;
                    s.set_time(t)?;
                    let clock = Instant::now();
                    r.set_scene_values(&s)?;
                    unsafe { ctx.gl.finish() };
                    let posing = clock.elapsed().as_secs_f64() * 1e3;
                    r.render(&s.camera)?;
                    if f < args.warmup {
                        continue;
                    }
                    pose_ms.push(posing);
                    frame_ms.push(r.last_times.frame_ms);
                    pass_ms.push(r.last_times.pass_ms("skinning"));
                }
                let joints: usize = (r.draws().skins.iter()).map(|d| d.joints.len()).sum();
                rows.push(Row {
                    vertices: copies * per,
                    method,
                    on,
                    bytes: match on {
                        SkinningOn::Gpu => joints * 64,
                        SkinningOn::Cpu => copies * per * 32,
                    },
                    pose_ms: Stats::from_samples(&mut pose_ms).median,
                    pass_ms: Stats::from_samples(&mut pass_ms).median,
                    frame_ms: Stats::from_samples(&mut frame_ms).median,
                    error: max_error(&r),
                });
            }
        }
    }
    eprintln!();
    println!("{}", table(&rows));
    Ok(())
}

/// The largest distance between a skinned vertex in the GPU's buffers and
/// the CPU reference's, for the renderer's last pose.
fn max_error(r: &Renderer) -> f32 {
    let draws = r.draws();
    let mut worst = 0f32;
    for s in &draws.skins {
        let gpu = draws.meshes[draws.items[s.item].mesh].read_vertices();
        let cpu = (s.skin.mesh).skinned(&s.joints, s.skin.method == SkinMethod::DualQuaternion);
        for (g, v) in gpu.iter().zip(&cpu.vertices) {
            let g = glam::Vec3::new(g[0], g[1], g[2]);
            worst = worst.max((g - glam::Vec3::from(v.position)).length());
        }
    }
    worst
}

fn table(rows: &[Row]) -> String {
    let mut s = format!(
        "{:>9}  {:<16} {:<4} {:>12} {:>9} {:>9} {:>10} {:>10}\n",
        "vertices", "method", "on", "bytes/frame", "pose ms", "pass ms", "frame ms", "max error"
    );
    for r in rows {
        s.push_str(&format!(
            "{:>9}  {:<16} {:<4} {:>12} {:>9.3} {:>9.3} {:>10.2} {:>10.2e}\n",
            r.vertices,
            r.method.name(),
            r.on.name(),
            r.bytes,
            r.pose_ms,
            r.pass_ms,
            r.frame_ms,
            r.error
        ));
    }
    for pair in rows.chunks(2) {
        if let [gpu, cpu] = pair {
            s.push_str(&format!(
                "{} vertices, {}: the GPU poses in {:.3} ms + a {:.3} ms pass, the CPU in {:.3} ms; {} against {} bytes a frame\n",
                gpu.vertices,
                gpu.method.name(),
                gpu.pose_ms,
                gpu.pass_ms,
                cpu.pose_ms,
                gpu.bytes,
                cpu.bytes
            ));
        }
    }
    s
}
