//! `gloss bench --scaling`: how each lighting path's frame time grows with
//! the number of lights and with the number of pixels.
//!
//! 1. Lights: the scene's `[light_grid]` at 16, 64, 256, 1024 and 4096
//!    lights, each light's intensity set so that its radius at the cutoff
//!    shrinks as 1/sqrt(count). The lights then cover the floor about as
//!    thickly at every count, and about as many reach each pixel: a path
//!    whose cost follows the lights that reach a pixel stays flat, one
//!    whose cost follows the number of lights grows with it. Beside the
//!    times: the mean length of the tiled path's cluster lists, which says
//!    how many lights do reach a pixel. Paths that read the lights from the
//!    uniform block stop at its size.
//! 2. Pixels: the scene's own lights at half to twice the size measured
//!    (640x360 up to 2560x1440 for a 1280x720 scene).
//!
//! The images are not compared (each count is a different scene); the
//! paths' errors are what `gloss bench` without `--scaling` measures.

use super::headless;
use super::plot::{ScalingSeries, plot_scaling};
use super::{BenchArgs, BenchRow, measure};
use crate::frame::clusters::{Grid, bin};
use crate::frame::lights::{FrameLights, max_lights};
use crate::gl::Headless;
use crate::lighting::attenuation;
use crate::scene::{DeferredLights, RenderPath, Scene};
use crate::techniques::deferred::tiled_shading::light_bounds;
use anyhow::{Result, bail};
use glam::Vec3;
use glow::HasContext;

const LIGHT_COUNTS: [usize; 5] = [16, 64, 256, 1024, 4096];
/// Frame sizes, as multiples of the measured size (`--size`, else the
/// scene's): 1280x720 gives 640x360 to 2560x1440.
const SCALES: [f32; 4] = [0.5, 1.0, 1.5, 2.0];

/// The paths measured, as (label, path, one pass over the lights).
const PATHS: [(&str, RenderPath, bool); 4] = [
    ("forward", RenderPath::Forward, false),
    ("deferred single pass", RenderPath::Deferred, true),
    ("volumes", RenderPath::Volumes, false),
    ("tiled", RenderPath::Tiled, false),
];

fn on_path(scene: &Scene, path: RenderPath, single: bool) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    if single {
        s.render.deferred_lights = DeferredLights::SinglePass;
    }
    s
}

/// `base` with `count` grid lights whose radius is `radius_at_base *
/// sqrt(base count / count)`: each light's intensity solves the notes'
/// radius equation backwards, I = cutoff (Kc + Kl r + Kq r^2).
fn with_lights(base: &Scene, count: usize) -> Result<(Scene, f32)> {
    let Some(grid) = base.light_grid.clone() else {
        bail!(
            "{}: --scaling needs a [light_grid] to vary the light count of",
            base.path.display()
        );
    };
    let [kc, kl, kq] = grid.attenuation;
    let cutoff = base.render.cutoff;
    let Some(r0) = attenuation::light_volume_radius(kc, kl, kq, grid.intensity, cutoff) else {
        bail!("--scaling: the grid's lights have no finite radius (Kl = Kq = 0)");
    };
    let r = r0 * (grid.count as f32 / count as f32).sqrt();
    let mut s = base.clone();
    s.set_light_grid(crate::scene::LightGrid {
        count,
        intensity: cutoff * (kc + kl * r + kq * r * r),
        ..grid
    })?;
    Ok((s, r))
}

/// How many lights reach a pixel's surface (it lies within their radius),
/// on average over up to 4000 pixels spread over the image: the surface
/// points come from a frame's depth buffer (the tiled path, which takes
/// any light count).
fn mean_reaching(ctx: &Headless, scene: &Scene) -> Result<f32> {
    let s = on_path(scene, RenderPath::Tiled, false);
    let (w, h) = s.render.size;
    let mut r = headless::renderer(ctx, &s, (w, h))?;
    r.render(&s.camera)?;
    let depth = r.read_depth();
    let inverse = (s.camera.projection(w as f32 / h as f32) * s.camera.view()).inverse();
    let lights = FrameLights::new(&s);
    let step = ((w * h) as usize / 4000).max(1);
    let (mut pixels, mut reached) = (0usize, 0usize);
    for i in (0..depth.len()).step_by(step) {
        if depth[i] >= 1.0 {
            continue;
        }
        let (x, y) = ((i as u32 % w) as f32 + 0.5, (i as u32 / w) as f32 + 0.5);
        let ndc = Vec3::new(x / w as f32, y / h as f32, depth[i]) * 2.0 - Vec3::ONE;
        let p = inverse.project_point3(ndc);
        pixels += 1;
        reached += (s.lights.iter().zip(&lights.lights))
            .filter(|(l, f)| {
                f.radius
                    .is_none_or(|radius| l.position.distance(p) <= radius)
            })
            .count();
    }
    Ok(if pixels == 0 {
        0.0
    } else {
        reached as f32 / pixels as f32
    })
}

/// The mean number of lights the tiled path lists for a non-empty cluster
/// of `scene`'s camera view (16-pixel tiles, 16 slices).
fn mean_listed(scene: &Scene) -> f32 {
    let (w, h) = scene.render.size;
    let c = &scene.camera;
    let grid = Grid::new(w, h, 16, 16, c.near, c.far);
    let lights = FrameLights::new(scene);
    let bounds = light_bounds(scene, &lights, &[]);
    let projection = c.projection(w as f32 / h as f32);
    bin(&grid, c.view(), projection, (w, h), &bounds).mean_per_cluster()
}

fn time(
    ctx: &Headless,
    software: bool,
    args: &BenchArgs,
    scene: &Scene,
    what: &str,
) -> Result<f64> {
    let row = BenchRow {
        setting: what.to_string(),
        ..BenchRow::default()
    };
    let r = measure(ctx, software, args, scene, None, row, what)?;
    Ok(r.frame.median)
}

pub(super) fn run(args: &BenchArgs, base: &Scene, ctx: &Headless, software: bool) -> Result<()> {
    let block = max_lights(unsafe { ctx.gl.get_parameter_i32(glow::MAX_UNIFORM_BLOCK_SIZE) });
    let size = args.size.unwrap_or(base.render.size);
    eprintln!(
        "gloss bench --scaling: {} on {}, {} warm-up + {} measured frames each (CPU clock around glFinish{})",
        base.path.display(),
        ctx.info.renderer,
        args.warmup,
        args.frames,
        if software {
            ""
        } else {
            "; GPU timer queries too"
        }
    );

    // 1. Lights.
    let mut by_lights: Vec<ScalingSeries> = PATHS
        .iter()
        .map(|(label, ..)| ScalingSeries::new(label))
        .collect();
    let mut table = format!(
        "frame ms against light count at {}x{} (radius shrinks as 1/sqrt(count); reach: lights that reach a pixel, mean; listed: lights in a tiled cluster's list, mean; in brackets: the frame's ns per light and pixel)\n{:>7} {:>8} {:>7} {:>8}",
        size.0, size.1, "lights", "radius", "reach", "listed"
    );
    for (label, ..) in PATHS {
        table.push_str(&format!(" {label:>21}"));
    }
    for &n in &LIGHT_COUNTS {
        let (mut scene, r) = with_lights(base, n)?;
        scene.render.size = size;
        table.push_str(&format!(
            "\n{n:>7} {r:>8.3} {:>7.1} {:>8.1}",
            mean_reaching(ctx, &scene)?,
            mean_listed(&scene)
        ));
        for (k, &(label, path, single)) in PATHS.iter().enumerate() {
            if path != RenderPath::Tiled && n > block {
                table.push_str(&format!(" {:>21}", "— (uniform block)"));
                continue;
            }
            let what = format!("{label}, {n} lights");
            let ms = time(ctx, software, args, &on_path(&scene, path, single), &what)?;
            by_lights[k].points.push((n as f64, ms));
            let ns = ms * 1e6 / (n as f64 * f64::from(size.0) * f64::from(size.1));
            table.push_str(&format!(" {:>21}", format!("{ms:.2} ({ns:.3})")));
        }
    }

    // 2. Pixels.
    let mut by_pixels: Vec<ScalingSeries> = PATHS
        .iter()
        .map(|(label, ..)| ScalingSeries::new(label))
        .collect();
    table.push_str(&format!(
        "\n\nframe ms against frame size with the scene's {} lights\n{:>10} {:>8}",
        base.lights.len(),
        "size",
        "Mpixel"
    ));
    for (label, ..) in PATHS {
        table.push_str(&format!(" {label:>21}"));
    }
    for scale in SCALES {
        let (w, h) = (
            ((size.0 as f32 * scale) as u32).max(1),
            ((size.1 as f32 * scale) as u32).max(1),
        );
        let mut scene = base.clone();
        scene.render.size = (w, h);
        let mp = (w * h) as f64 / 1e6;
        table.push_str(&format!("\n{:>10} {mp:>8.3}", format!("{w}x{h}")));
        for (k, &(label, path, single)) in PATHS.iter().enumerate() {
            let what = format!("{label}, {w}x{h}");
            let ms = time(ctx, software, args, &on_path(&scene, path, single), &what)?;
            by_pixels[k].points.push((mp, ms));
            table.push_str(&format!(" {ms:>21.2}"));
        }
    }
    eprintln!();
    println!("{table}");
    let lights_png = args.out.join("scaling-lights.png");
    let pixels_png = args.out.join("scaling-pixels.png");
    plot_scaling(
        &by_lights,
        "Frame time against light count (radii shrink: as many lights reach a pixel)",
        "lights (log scale)",
        &lights_png,
    )?;
    plot_scaling(
        &by_pixels,
        "Frame time against frame size",
        "Mpixel (log scale)",
        &pixels_png,
    )?;
    println!(
        "wrote {} and {}",
        lights_png.display(),
        pixels_png.display()
    );
    Ok(())
}
