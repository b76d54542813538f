//! `gloss bench --ibl`: image-based lighting (render.ibl; Karis 2013,
//! src/techniques/sky/image_based_lighting.rs) measured against its CPU
//! references (src/lighting/image_based_lighting.rs). Times, on the CPU
//! clock around glFinish: the frame with the constant ambient, with
//! image-based lighting (the maps made once: the per-frame term), and with
//! the maps made again every frame (the precompute). Errors: the GPU's maps,
//! read back, against Monte Carlo integrals of the environment the GPU
//! rendered (irradiance at 16 normals, each prefiltered level at 8
//! directions) and the split-sum table against the quadrature of gloss's
//! BRDF (N.V >= 0.1).

use super::{BenchArgs, Stats, headless};
use crate::frame::image_based_lighting::wanted;
use crate::gl::Headless;
use crate::gl::cube_map::CubeMap;
use crate::lighting::image_based_lighting as ibl;
use crate::math::cube_map::CubeImage;
use crate::scene::Scene;
use anyhow::{Result, anyhow, bail};
use glam::DVec3;
use glow::HasContext;
use std::path::Path;
use std::time::Instant;

pub(super) fn run(args: &BenchArgs, scene_path: &Path, ctx: &Headless) -> Result<()> {
    let mut base = Scene::load_with(scene_path, &args.set)?;
    if let Some(size) = args.size {
        base.render.size = size;
    }
    base.render.ibl = true;
    if !wanted(&base) {
        bail!(
            "{}: --ibl needs an environment to light with: add a [sky] or a [skybox]",
            scene_path.display()
        );
    }
    let mut off = base.clone();
    off.render.ibl = false;
    let (w, h) = base.render.size;
    eprintln!(
        "gloss bench --ibl: {} at {w}x{h} on {}; {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        args.warmup,
        args.frames
    );
    let constant = frame_times(ctx, &off, args, false)?;
    let steady = frame_times(ctx, &base, args, false)?;
    let again = frame_times(ctx, &base, args, true)?;
    let ms = |s: &Stats| format!("{:.2} ({:.2}-{:.2})", s.median, s.p10, s.p90);
    println!("| frame | median ms (p10-p90) |");
    println!("|---|---|");
    println!("| constant ambient | {} |", ms(&constant));
    println!("| image-based lighting, maps made once | {} |", ms(&steady));
    println!(
        "| image-based lighting, maps made every frame | {} |",
        ms(&again)
    );
    println!(
        "\nper-frame term {:.2} ms, precompute {:.2} ms (differences of medians)\n",
        steady.median - constant.median,
        again.median - steady.median
    );
    errors(ctx, &base)
}

/// Frame times; `precompute`: the maps made again before each frame.
fn frame_times(ctx: &Headless, scene: &Scene, args: &BenchArgs, precompute: bool) -> Result<Stats> {
    let mut r = headless::renderer(ctx, scene, scene.render.size)?;
    let mut samples = Vec::new();
    for i in 0..args.warmup + args.frames {
        if let (true, Some(m)) = (precompute, &r.draws().environment.ibl) {
            *m.made_for.borrow_mut() = None;
        }
        let t = Instant::now();
        r.render(&scene.camera)?;
        unsafe { ctx.gl.finish() };
        if i >= args.warmup {
            samples.push(t.elapsed().as_secs_f64() * 1e3);
        }
    }
    Ok(Stats::from_samples(&mut samples))
}

fn level_image(c: &CubeMap, level: u32) -> CubeImage {
    let size = (c.size >> level).max(1) as usize;
    let faces = std::array::from_fn(|f| {
        let v = c.read_face_f32(f as u32, level);
        v.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
    });
    CubeImage { size, faces }
}

/// `n` directions spread over the sphere (a Fibonacci lattice).
fn directions(n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let phi = i as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt());
            let r = (1.0 - y * y).sqrt();
            DVec3::new(r * phi.cos(), y, r * phi.sin())
        })
        .collect()
}

/// The maps' errors against the CPU references, as a table.
fn errors(ctx: &Headless, scene: &Scene) -> Result<()> {
    let mut r = headless::renderer(ctx, scene, scene.render.size)?;
    r.render(&scene.camera)?;
    let environment = &r.draws().environment;
    let (Some(cube), Some(maps)) = (&environment.cube, &environment.ibl) else {
        return Err(anyhow!("the renderer made no image-based lighting maps"));
    };
    let env = cube.read_image();
    let lookup = ibl::cube_environment(&env);
    let rgb = |c: [f64; 4]| DVec3::new(c[0], c[1], c[2]);
    let rel = |g: DVec3, w: DVec3| (g - w).abs().max_element() / w.max_element().max(1e-6);
    println!("| map | reference | mean relative error | worst |");
    println!("|---|---|---|---|");
    let row = |name: String, reference: &str, e: &[f64]| {
        let mean = e.iter().sum::<f64>() / e.len() as f64;
        let worst = e.iter().copied().fold(0.0, f64::max);
        println!("| {name} | {reference} | {mean:.2e} | {worst:.2e} |");
    };
    let irradiance = level_image(&maps.irradiance, 0);
    let e: Vec<f64> = (directions(16).into_iter())
        .map(|n| {
            rel(
                rgb(irradiance.sample(n, true)),
                ibl::irradiance_mc(&lookup, n, 200_000, 1),
            )
        })
        .collect();
    row(
        "irradiance (E / pi)".into(),
        "Monte Carlo, 200k cosine samples",
        &e,
    );
    for level in 1..maps.levels() {
        let alpha = ibl::level_alpha(level);
        let image = level_image(&maps.prefiltered, level as u32);
        let e: Vec<f64> = (directions(8).into_iter())
            .map(|d| {
                rel(
                    rgb(image.sample(d, true)),
                    ibl::prefiltered_mc(&lookup, d, alpha, 50_000, 2),
                )
            })
            .collect();
        row(
            format!("prefiltered level {level}, alpha {alpha:.2}"),
            "Monte Carlo, 50k GGX samples",
            &e,
        );
    }
    let (w, h, texels) = maps.brdf.read_level_f32(0);
    let mut e = Vec::new();
    for j in (0..h as usize).step_by(4) {
        for i in (0..w as usize).step_by(4) {
            let nv = (i as f64 + 0.5) / f64::from(w);
            let rough = (j as f64 + 0.5) / f64::from(h);
            if nv < 0.1 {
                continue;
            }
            let (a, b) = ibl::brdf_table_reference(nv, rough * rough);
            let t = (j * w as usize + i) * 4;
            e.push(
                (f64::from(texels[t]) - a)
                    .abs()
                    .max((f64::from(texels[t + 1]) - b).abs()),
            );
        }
    }
    println!(
        "| split-sum table (A, B), absolute | quadrature of gloss's f_s | {:.2e} | {:.2e} |",
        e.iter().sum::<f64>() / e.len() as f64,
        e.iter().copied().fold(0.0, f64::max)
    );
    Ok(())
}
