//! `gloss bench --ssao`: screen-space ambient occlusion (notes 03, "Ambient
//! Light"; src/techniques/deferred/ambient_light.rs) measured against its
//! CPU reference, at several sample counts.
//!
//! The reference (src/lighting/ambient_occlusion.rs): the same G-buffer
//! points, read back through glsl/common/gbuffer_read.glsl
//! (glsl/deferred/ambient_light_readback.frag: the normal and the depth the
//! pass saw, the position rebuilt from the depth), each with the same AO
//! definition (cosine-weighted visibility within r) ray traced against the
//! scene's triangles with `REFERENCE_RAYS` directions. The error of a
//! sample count is the mean and the 95th percentile of |AO_gpu - AO_ref|
//! over the pixels with a surface, AO_gpu being what the ambient term reads
//! (the blurred AO when the scene blurs). Times: the median and the
//! 10th-90th percentiles of the frame and of the two SSAO passes, on the CPU
//! clock around glFinish, and on a GPU also with GL_TIMESTAMP queries.

use super::headless;
use super::{BenchArgs, Stats};
use crate::frame::gbuffer;
use crate::gl::Headless;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::{Program, Sources};
use crate::lighting::ambient_occlusion::reference;
use crate::lighting::shadow_reference::SceneTriangles;
use crate::renderer::Renderer;
use crate::scene::ambient_occlusion::AmbientOcclusion;
use crate::scene::{RenderPath, Scene};
use crate::techniques::deferred::ambient_light::result_target;
use anyhow::{Context as _, Result, anyhow, bail};
use glam::{Mat4, Vec3};
use glow::HasContext;
use std::fmt::Write as _;
use std::path::Path;

/// The sample counts measured.
pub const COUNTS: [u32; 5] = [4, 8, 16, 32, 64];
/// Directions the reference traces per pixel.
pub const REFERENCE_RAYS: usize = 256;
/// The names of the SSAO passes in the plan.
const PASSES: [&str; 2] = ["ambient light", "ambient blur"];

/// One frame's AO and the G-buffer geometry it was computed from, rows
/// bottom-up (as glReadPixels gives them).
pub struct AoFrame {
    pub width: usize,
    pub height: usize,
    /// What the ambient term multiplies by, per pixel (1 on the background).
    pub ao: Vec<f32>,
    /// Window depth 0..1 (1: background).
    pub depth: Vec<f32>,
    pub normals: Vec<Vec3>,
    pub inverse_view_projection: Mat4,
}

impl AoFrame {
    /// The reference AO of every pixel with a surface (None: background),
    /// ray traced against `scene`'s triangles with `rays` directions.
    pub fn reference(&self, scene: &Scene, radius: f32, rays: usize) -> Result<Vec<Option<f32>>> {
        let tris = SceneTriangles::new(scene)?;
        Ok(reference(
            &tris,
            &self.depth,
            &self.normals,
            self.inverse_view_projection,
            self.width,
            self.height,
            radius,
            rays,
        ))
    }
}

/// |AO_gpu - AO_ref| over the pixels the reference has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AoError {
    pub mean: f64,
    pub p95: f64,
    pub pixels: usize,
}

pub fn error(gpu: &[f32], reference: &[Option<f32>]) -> AoError {
    let mut e: Vec<f64> = (gpu.iter().zip(reference))
        .filter_map(|(g, r)| r.map(|r| f64::from((g - r).abs())))
        .collect();
    let pixels = e.len();
    if pixels == 0 {
        return AoError {
            mean: 0.0,
            p95: 0.0,
            pixels,
        };
    }
    let mean = e.iter().sum::<f64>() / pixels as f64;
    e.sort_by(f64::total_cmp);
    let p95 = e[((pixels - 1) as f64 * 0.95).round() as usize];
    AoError { mean, p95, pixels }
}

/// Render `scene` at its size (its [ambient_occlusion] on) and read the AO
/// and the geometry back.
pub fn render_ao(ctx: &Headless, scene: &Scene) -> Result<AoFrame> {
    let (w, h) = scene.render.size;
    let mut r = headless::renderer(ctx, scene, (w, h))?;
    r.render(&scene.camera)?;
    read(ctx, &r)
}

/// The AO of the frame `r` rendered last, and the geometry it saw.
pub fn read(ctx: &Headless, r: &Renderer) -> Result<AoFrame> {
    let name = result_target(&r.scene).ok_or_else(|| {
        anyhow!(
            "{}: no ambient occlusion this frame",
            r.scene.path.display()
        )
    })?;
    let ao: Vec<f32> = (r.targets().get(name).read_rgba_f32(0).chunks(4))
        .map(|p| p[0])
        .collect();
    let (width, height) = (r.width as usize, r.height as usize);
    let uniforms = r.frame_uniforms(&r.scene.camera, &r.plan.views[0]);
    let gl = &ctx.gl;
    let program = Program::new(
        gl,
        &Sources::Embedded,
        &[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (
                glow::FRAGMENT_SHADER,
                "deferred/ambient_light_readback.frag",
            ),
        ],
        &[],
    )?;
    let target = Framebuffer::new(
        gl,
        "ambient_light_readback",
        r.width,
        r.height,
        &[glow::RGBA32F],
        None,
    )?;
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
        gl.viewport(0, 0, r.width, r.height);
        program.use_program();
        gbuffer::bind_for_reading(gl, &program, r.targets().get(gbuffer::NAME), &uniforms);
        program.set_mat4("u_mvp", &Mat4::IDENTITY);
        r.meshes().fullscreen.draw();
        gbuffer::unbind(gl);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    ctx.debug.check(gl, "reading the G-buffer back")?;
    let px = target.read_rgba_f32(0);
    Ok(AoFrame {
        width,
        height,
        ao,
        depth: px.chunks(4).map(|p| p[3]).collect(),
        normals: px.chunks(4).map(|p| Vec3::new(p[0], p[1], p[2])).collect(),
        inverse_view_projection: uniforms.inverse_view_projection,
    })
}

/// One sample count's figures.
pub struct SsaoRow {
    pub samples: u32,
    pub frame: Stats,
    /// The two SSAO passes together, CPU clock around glFinish.
    pub ssao: Stats,
    /// The same on the GPU's clock (None where timer queries are not trusted).
    pub ssao_gpu: Option<Stats>,
    pub error: AoError,
}

/// Every count of `counts` on `base` (whose AO settings but the count are
/// kept): error against the reference, times over `warmup` + `frames` frames.
pub fn measure(
    ctx: &Headless,
    base: &Scene,
    counts: &[u32],
    warmup: usize,
    frames: usize,
) -> Result<Vec<SsaoRow>> {
    let (w, h) = base.render.size;
    let ao = base
        .render
        .ambient_occlusion
        .unwrap_or(AmbientOcclusion::DEFAULT);
    let mut reference_ao = None;
    let mut rows = Vec::new();
    for &samples in counts {
        let mut scene = base.clone();
        scene.render.ambient_occlusion = Some(AmbientOcclusion { samples, ..ao });
        let mut r = headless::renderer(ctx, &scene, (w, h))
            .with_context(|| format!("{samples} samples"))?;
        r.render(&scene.camera)?;
        let got = read(ctx, &r)?;
        if reference_ao.is_none() {
            eprint!("\rreference: {REFERENCE_RAYS} rays a pixel ...   ");
            reference_ao = Some(got.reference(&scene, ao.radius, REFERENCE_RAYS)?);
        }
        let error = error(&got.ao, reference_ao.as_deref().unwrap_or_default());
        r.timing = true;
        let (mut frame, mut cpu, mut gpu) = (Vec::new(), Vec::new(), Vec::new());
        for f in 0..warmup + frames {
            eprint!(
                "\r{samples:>2} samples: frame {}/{}   ",
                f + 1,
                warmup + frames
            );
            r.render(&scene.camera)?;
            if f < warmup {
                continue;
            }
            let t = &r.last_times;
            frame.push(t.frame_ms);
            cpu.push(PASSES.iter().map(|p| t.pass_ms(p)).sum());
            if t.gpu.len() == t.passes.len() {
                let ms = (t.passes.iter().zip(&t.gpu))
                    .filter(|((name, _), _)| PASSES.contains(name))
                    .map(|(_, ms)| ms)
                    .sum();
                gpu.push(ms);
            }
        }
        rows.push(SsaoRow {
            samples,
            frame: Stats::from_samples(&mut frame),
            ssao: Stats::from_samples(&mut cpu),
            ssao_gpu: (!gpu.is_empty()).then(|| Stats::from_samples(&mut gpu)),
            error,
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
    if base.render.path == RenderPath::Forward {
        bail!(
            "{}: --ssao needs a path with a G-buffer (render.path = \"forward\" has none): --set render.path=deferred",
            scene_path.display()
        );
    }
    let ao = base
        .render
        .ambient_occlusion
        .unwrap_or(AmbientOcclusion::DEFAULT);
    base.render.ambient_occlusion = Some(ao);
    let (w, h) = base.render.size;
    eprintln!(
        "gloss bench --ssao: {} at {w}x{h} on {}, r = {}, bias {}, blur {}, against {REFERENCE_RAYS} ray-traced directions a pixel; {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        ao.radius,
        ao.bias,
        ao.blur,
        args.warmup,
        args.frames
    );
    let rows = measure(ctx, &base, &COUNTS, args.warmup, args.frames)?;
    println!("{}", table(&rows));
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let csv = args.out.join("ssao.csv");
    let mut text = String::from(
        "samples,frame_ms,frame_p10,frame_p90,ssao_ms,ssao_p10,ssao_p90,ssao_gpu_ms,mean_error,p95_error\n",
    );
    for r in &rows {
        let gpu = r
            .ssao_gpu
            .map_or(String::new(), |g| format!("{:.4}", g.median));
        let _ = writeln!(
            text,
            "{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{gpu},{:.5},{:.5}",
            r.samples,
            r.frame.median,
            r.frame.p10,
            r.frame.p90,
            r.ssao.median,
            r.ssao.p10,
            r.ssao.p90,
            r.error.mean,
            r.error.p95
        );
    }
    std::fs::write(&csv, text).with_context(|| format!("writing {}", csv.display()))?;
    println!("wrote {}", csv.display());
    Ok(())
}

/// The table `gloss bench --ssao` prints.
pub fn table(rows: &[SsaoRow]) -> String {
    let mut s = String::from(
        "times: median (p10-p90) ms; cpu+glFinish, and the GPU's GL_TIMESTAMP where trusted\n",
    );
    let _ = writeln!(
        s,
        "{:>7} {:>20} {:>20} {:>10} {:>10} {:>10}",
        "samples", "frame", "SSAO passes", "SSAO gpu", "mean err", "p95 err"
    );
    let t = |x: &Stats| format!("{:.2} ({:.2}-{:.2})", x.median, x.p10, x.p90);
    for r in rows {
        let gpu = r
            .ssao_gpu
            .map_or("-".into(), |g| format!("{:.3}", g.median));
        let _ = writeln!(
            s,
            "{:>7} {:>20} {:>20} {:>10} {:>10.4} {:>10.4}",
            r.samples,
            t(&r.frame),
            t(&r.ssao),
            gpu,
            r.error.mean,
            r.error.p95
        );
    }
    s
}
