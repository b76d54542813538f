//! `gloss bench`: speed against error.
//!
//! For each setting (render path x light count x cutoff) it renders the same
//! frame many times after a warm-up and reports the median and spread of the
//! frame time and of each pass, and the error of the setting's image against
//! the reference: forward rendering, which has no cutoff. The error is RMSE,
//! max and, beside them, the mean FLIP (a perceptual error, src/image_compare/flip.rs).
//!
//! Clocks: on llvmpipe, GL_TIME_ELAPSED under-reports (rasterisation is
//! deferred until the driver flushes), so every figure here is the CPU clock
//! around glFinish ("cpu+glFinish"). On a real GPU the whole frame is also
//! timed with a GL_TIME_ELAPSED query ("gpu" column).
//!
//! `--aa`, `--filtering` and `--ssao` measure anti-aliasing, texture filtering
//! and SSAO against references instead (`aa`, `filtering`, `ssao`);
//! `--scaling`, how the paths' times grow with lights and pixels.
//! The files: `args`, `stats` (median and spread), `table`, `csv`, `plot`
//! (error against frame time), `floor` (each pass against the fill-rate
//! floor), `bound` (the far field's error bound), `pareto` (settings no
//! other beats), `overdraw` (fragments a pixel), `particles` (the geometry
//! shader's points against quads built on the CPU), `skinning` (the GPU's
//! skinning pass against the CPU reference), `instancing` (one instanced
//! draw against one draw per object).

pub mod aa;
mod args;
pub mod bloom;
pub mod bound;
mod csv;
pub mod filtering;
mod floor;
mod headless;
mod ibl;
mod instancing;
mod overdraw;
pub mod pareto;
mod particles;
mod plot;
mod post;
mod scaling;
pub mod shadows;
mod skinning;
pub mod ssao;
mod stats;
pub(crate) use stats::add_pass_times;
mod table;
mod variants;

pub use args::{BenchArgs, parse_size};
pub use csv::{csv, write_csv};
pub use plot::{PLOT_SIZE, plot};
pub use stats::Stats;
pub use table::{BenchRow, speedup_vs_forward, table};

use crate::gl::{Backend, Headless, query::TimerQuery};
use crate::image_compare::compare_rgba8;
use crate::scene::{RenderPath, Scene};
use anyhow::{Context as _, Result, bail};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use table::cutoff_label;

/// One setting to measure.
#[derive(Clone, Debug)]
struct Setting {
    path: RenderPath,
    lights: usize,
    cutoff: Option<f32>,
    stencil: bool,
    /// The deferred path as one pass over all the lights (notes 01 §8.6.2)
    /// rather than a pass per light (notes 04).
    single_pass: bool,
}

impl Setting {
    fn label(&self) -> String {
        let mut s = self.path.name().to_string();
        if self.single_pass {
            s.push_str(" single pass");
        }
        if self.stencil {
            s.push_str("+stencil");
        }
        if let Some(c) = self.cutoff {
            s.push_str(&format!(" cutoff {}", cutoff_label(c, None)));
        }
        s
    }
}

pub fn run(args: &BenchArgs, backend: Backend) -> Result<()> {
    if args.frames == 0 {
        bail!("--frames must be at least 1");
    }
    let default = match () {
        _ if args.aa => "scenes/antialiasing.toml",
        _ if args.filtering => "scenes/texture-filtering.toml",
        _ if args.ssao => "scenes/ambient-occlusion.toml",
        _ if args.ibl => "scenes/ibl.toml",
        _ if !args.particles.is_empty() => "scenes/particles.toml",
        _ if !args.skinning.is_empty() => "scenes/skinned-arm.toml",
        _ if !args.instancing.is_empty() => "scenes/instancing.toml",
        _ => "scenes/many-lights.toml",
    };
    let scene_path = (args.scene.clone()).unwrap_or_else(|| PathBuf::from(default));
    let scene_path = crate::assets::scene_path(&scene_path);
    let base = Scene::load_with(&scene_path, &args.set)?;
    // The bench runs the scene on several paths: only what holds on all.
    base.print_warnings(&base.warnings_on_every_path());
    let ctx = Headless::new(backend, false)?;
    let software = ctx.info.renderer.contains("llvmpipe") || ctx.info.renderer.contains("softpipe");
    // The other measurements, each in its own file.
    match () {
        _ if args.aa => return aa::run(args, &scene_path, &ctx),
        _ if args.filtering => return filtering::run(args, &scene_path, &ctx),
        _ if args.ssao => return ssao::run(args, &scene_path, &ctx),
        _ if args.ibl => return ibl::run(args, &scene_path, &ctx),
        _ if args.scaling => return scaling::run(args, &base, &ctx, software),
        _ if !args.particles.is_empty() => return particles::run(args, &base, &ctx),
        _ if !args.skinning.is_empty() => return skinning::run(args, &base, &ctx),
        _ if !args.instancing.is_empty() => return instancing::run(args, &base, &ctx),
        _ if !args.vary.is_empty() => return variants::run(args, &scene_path, &ctx, software),
        _ => {}
    }
    let (w, h) = args.size.unwrap_or(base.render.size);
    let light_counts = if args.lights.is_empty() {
        vec![base.lights.len()]
    } else {
        args.lights.clone()
    };
    let cutoffs = if args.cutoffs.is_empty() {
        vec![base.render.cutoff]
    } else {
        args.cutoffs.clone()
    };

    let mut settings = Vec::new();
    for &n in &light_counts {
        for &p in &args.paths {
            match p {
                RenderPath::Forward => settings.push(Setting {
                    path: p,
                    lights: n,
                    cutoff: None,
                    stencil: false,
                    single_pass: false,
                }),
                // Both forms of full-screen deferred: notes 04's pass per
                // light and notes 01 §8.6.2's one pass.
                RenderPath::Deferred => {
                    for single_pass in [false, true] {
                        settings.push(Setting {
                            path: p,
                            lights: n,
                            cutoff: None,
                            stencil: false,
                            single_pass,
                        });
                    }
                }
                RenderPath::Volumes | RenderPath::Prepass | RenderPath::Tiled => {
                    for &c in &cutoffs {
                        settings.push(Setting {
                            path: p,
                            lights: n,
                            cutoff: Some(c),
                            stencil: false,
                            single_pass: false,
                        });
                        if args.stencil && p == RenderPath::Volumes {
                            settings.push(Setting {
                                path: p,
                                lights: n,
                                cutoff: Some(c),
                                stencil: true,
                                single_pass: false,
                            });
                        }
                    }
                }
            }
        }
    }

    eprintln!(
        "gloss bench: {} at {w}x{h} on {} ({}), {} settings, {} warm-up + {} measured frames each",
        scene_path.display(),
        ctx.info.renderer,
        backend,
        settings.len(),
        args.warmup,
        args.frames
    );
    eprintln!(
        "clock: {}",
        if software {
            "CPU clock around glFinish (timer queries under-report on a software rasterizer)"
        } else {
            "CPU clock around glFinish per pass, and GL_TIME_ELAPSED for the whole frame"
        }
    );

    let mut references: Vec<(usize, image::RgbaImage)> = Vec::new();
    let mut rows = Vec::new();
    for (i, s) in settings.iter().enumerate() {
        let mut scene = base.clone();
        if scene.lights.len() != s.lights {
            scene.set_light_count(s.lights)?;
        }
        scene.render.size = (w, h);
        scene.render.path = s.path;
        scene.render.stencil_volumes = s.stencil;
        if s.single_pass {
            scene.render.deferred_lights = crate::scene::DeferredLights::SinglePass;
        }
        if let Some(c) = s.cutoff {
            scene.render.cutoff = c;
        }
        // The reference for this light count: forward, no cutoff.
        if !references.iter().any(|(n, _)| *n == s.lights) {
            let mut rs = scene.clone();
            rs.render.path = RenderPath::Forward;
            let mut r = headless::renderer(&ctx, &rs, (w, h))?;
            r.render(&rs.camera.clone())?;
            references.push((s.lights, r.read_image()));
        }
        let reference = &references
            .iter()
            .find(|(n, _)| *n == s.lights)
            .expect("made above")
            .1;

        let row = BenchRow {
            setting: s.label(),
            // The plot draws one series per path; the stencil variant is its own.
            path: if s.stencil {
                format!("{}+stencil", s.path.name())
            } else if s.single_pass {
                format!("{}+single", s.path.name())
            } else {
                s.path.name().to_string()
            },
            lights: s.lights,
            cutoff: s.cutoff,
            ..BenchRow::default()
        };
        let progress = format!(
            "[{}/{}] {:<32} {} lights",
            i + 1,
            settings.len(),
            s.label(),
            s.lights
        );
        rows.push(measure(
            &ctx,
            software,
            args,
            &scene,
            Some(reference),
            row,
            &progress,
        )?);
    }
    eprintln!();
    finish(&rows, args)?;
    let mut sized = base.clone();
    sized.render.size = (w, h);
    let floor_ms = post::full_screen_ms(&ctx, args, &sized)?;
    println!("{}", floor::table(&rows, floor_ms, (w, h)));
    if !base.post.is_empty() {
        let mut scene = base.clone();
        scene.render.size = (w, h);
        println!("{}", post::floor_table(&ctx, args, &scene)?);
    }
    Ok(())
}

/// Print the table, write the CSV and the plot.
fn finish(rows: &[BenchRow], args: &BenchArgs) -> Result<()> {
    println!("{}", table(rows));
    println!("{}", pareto::describe(rows, "max error", |r| r.max_abs));
    println!("{}", pareto::describe(rows, "RMSE", |r| r.rmse));
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let csv = args.out.join("bench.csv");
    let png = args.out.join("bench.png");
    write_csv(rows, &csv)?;
    plot(rows, &png)?;
    println!("wrote {} and {}", csv.display(), png.display());
    Ok(())
}

/// Render `scene` `args.warmup + args.frames` times, timing each pass, and
/// fill `row`'s times and its error against `reference` (None: the error is
/// not measured, and reads as incomparable).
fn measure(
    ctx: &Headless,
    software: bool,
    args: &BenchArgs,
    scene: &Scene,
    reference: Option<&image::RgbaImage>,
    row: BenchRow,
    progress: &str,
) -> Result<BenchRow> {
    let (w, h) = scene.render.size;
    let mut r = headless::renderer(ctx, scene, (w, h))
        .with_context(|| format!("setting {}", row.setting))?;
    r.timing = true;
    let query = if software {
        None
    } else {
        Some(TimerQuery::new(&ctx.gl)?)
    };
    let camera = scene.camera.clone();
    let mut frame = Vec::new();
    let mut gpu = Vec::new();
    let mut passes: Vec<(String, Vec<f64>)> = Vec::new();
    for f in 0..args.warmup + args.frames {
        eprint!(
            "\r{progress}: frame {}/{}   ",
            f + 1,
            args.warmup + args.frames
        );
        let _ = std::io::stderr().flush();
        if let Some(q) = &query {
            q.begin();
        }
        r.render(&camera)?;
        if let Some(q) = &query {
            q.end();
        }
        if f < args.warmup {
            continue;
        }
        if let Some(q) = &query {
            gpu.push(q.result_ns() as f64 / 1e6);
        }
        frame.push(r.last_times.frame_ms);
        add_pass_times(&mut passes, r.last_times.titled());
    }
    let image = r.read_image();
    let fragments = overdraw::fragments_per_pixel(ctx, &mut r, &camera)?;
    let m = match reference {
        Some(reference) => compare_rgba8(&image, reference, 1.0 / 255.0)?,
        None => crate::image_compare::Metrics::incomparable(1.0 / 255.0),
    };
    let flip = match reference {
        Some(reference) => Some(crate::image_compare::flip::flip(&image, reference)?.mean),
        None => None,
    };
    drop(r);
    let bound = bound::far_field(ctx, scene, &image)?;
    Ok(BenchRow {
        passes: passes
            .into_iter()
            .map(|(n, mut v)| (n, Stats::from_samples(&mut v)))
            .collect(),
        frame: Stats::from_samples(&mut frame),
        gpu_frame_ms: if gpu.is_empty() {
            None
        } else {
            Some(Stats::from_samples(&mut gpu))
        },
        clock: "cpu+glFinish".into(),
        rmse: m.rmse,
        max_abs: m.max_abs,
        pct_over_1: m.frac_over * 100.0,
        flip,
        bound,
        fragments_per_pixel: Some(fragments),
        ..row
    })
}

/// Creates `path`'s parent directory (for the CSV file and the plot).
fn create_parent(path: &Path) -> anyhow::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("creating directory {}", dir.display()))?;
    }
    Ok(())
}
