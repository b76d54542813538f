//! The `gloss` command line.

use anyhow::{Context as _, Result, anyhow, bail};
use clap::Parser as _;
use gloss::assets;
use gloss::cli::{Cli, Command, Inspect};
use gloss::gl::program::Sources;
use gloss::gl::{Backend, Headless};
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

fn main() -> ExitCode {
    // Rust ignores SIGPIPE, so printing into a closed pipe (`gloss plan |
    // head`) fails and println! panics; like any Unix tool, end quietly instead.
    #[cfg(unix)]
    // SAFETY: before any thread starts; SIG_DFL is a valid disposition.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    std::panic::set_hook(Box::new(|info| {
        eprintln!(
            "gloss: internal error: {info}\nplease report it with the command that caused it"
        );
    }));
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// The default scene: scenes/default.toml here if there is one, else the shipped one.
fn default_scene() -> PathBuf {
    assets::scene_path(Path::new("scenes/default.toml"))
}

fn headless_backend(b: Option<Backend>) -> Result<Backend> {
    match b {
        None => Ok(Backend::Egl),
        Some(Backend::Window) => {
            bail!("this command renders headless: use --backend egl or osmesa")
        }
        Some(b) => Ok(b),
    }
}

fn render_to_png(
    scene: &Scene,
    backend: Backend,
    debug: bool,
    out: &Path,
    inspect: Option<(Inspect, Option<usize>)>,
    target: Option<&str>,
) -> Result<()> {
    let ctx = Headless::new(backend, debug)?;
    let mut r = render_scene(&ctx, scene, Output::Srgb8)?;
    let (w, h) = (r.width as u32, r.height as u32);
    let img = match (inspect, target) {
        (None, Some(name)) => {
            gloss::demo::pictures::target_picture(&ctx.gl, &Sources::Embedded, &r, name)?
        }
        (None, None) => r.read_image(),
        (Some((Inspect::Stencil, None)), _) => {
            gloss::renderer::stencil_image(&r.read_stencil(), w, h)
        }
        (Some((Inspect::Stencil, Some(pass))), _) => {
            let stencil = r.stencil_after(&scene.camera, pass)?;
            gloss::renderer::stencil_image(&stencil, w, h)
        }
    };
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    // The whole PNG in memory first, then written without harming any other
    // file (src/assets/write.rs): a failed write leaves the old picture.
    let mut png = std::io::Cursor::new(Vec::new());
    img.write_to(&mut png, image::ImageFormat::Png)
        .with_context(|| format!("cannot write {}", out.display()))?;
    assets::write::write_file(out, png.get_ref())
}

fn load_scene(
    path: &Path,
    overrides: &[String],
    render_path: Option<RenderPath>,
    lights: Option<usize>,
) -> Result<Scene> {
    let mut scene = Scene::load_with(&assets::scene_path(path), overrides)?;
    if let Some(p) = render_path {
        scene.render.path = p;
    }
    if let Some(n) = lights {
        scene.set_light_count(n)?;
    }
    scene.print_warnings(&scene.warnings());
    Ok(scene)
}

fn run(mut cli: Cli) -> Result<()> {
    if let Some(t) = cli.time {
        if !t.is_finite() {
            bail!("--time {t}: expected a finite number of seconds");
        }
        // The scene checks it as it checks the file's own time; `{:?}`
        // writes 1e19 as TOML reads it (`{}` would write 20 digits, too
        // many for TOML's integers).
        cli.set.push(format!("animation.time={t:?}"));
    }
    match cli.command {
        None => {
            let scene_path = cli
                .scene
                .map(|s| assets::scene_path(&s))
                .unwrap_or_else(default_scene);
            let want_window = match cli.backend {
                Some(Backend::Window) => true,
                Some(_) => false,
                None => match gloss::gl::window::display_problem() {
                    None => true,
                    Some(why) => {
                        eprintln!("gloss: cannot open a window: {why}");
                        false
                    }
                },
            };
            if want_window {
                gloss::demo::run(
                    &scene_path,
                    gloss::demo::DemoOptions {
                        debug: cli.debug,
                        frames: cli.frames,
                        size: cli.window,
                        overrides: cli.set.clone(),
                        panel: !cli.no_panel,
                        pass_times: !cli.no_pass_times,
                    },
                )
            } else {
                let scene = Scene::load_with(&scene_path, &cli.set)?;
                scene.print_warnings(&scene.warnings());
                let out = std::env::current_dir()?.join(format!("gloss-{}.png", scene.name));
                let backend = headless_backend(cli.backend)?;
                render_to_png(&scene, backend, cli.debug, &out, None, None)?;
                println!(
                    "gloss: rendered {} headless ({backend}) instead, to {}",
                    scene_path.display(),
                    out.display()
                );
                Ok(())
            }
        }
        Some(Command::Render {
            scene,
            output,
            size,
            path,
            shading,
            lights,
            inspect,
            after,
            target,
        }) => {
            let mut s = load_scene(&scene, &cli.set, path, lights)?;
            if let Some(sh) = shading {
                s.render.shading = sh;
            }
            if let Some(sz) = size {
                s.render.size = sz;
            }
            render_to_png(
                &s,
                headless_backend(cli.backend)?,
                cli.debug,
                &output,
                inspect.map(|i| (i, after)),
                target.as_deref(),
            )?;
            println!("wrote {}", output.display());
            Ok(())
        }
        Some(Command::Info) => {
            let backend = cli.backend.unwrap_or(Backend::Egl);
            if backend == Backend::Window {
                let info = gloss::gl::window::query_info(cli.debug)?;
                println!("{info}");
                return Ok(());
            }
            let ctx = Headless::new(backend, cli.debug)?;
            println!("{}", ctx.info);
            Ok(())
        }
        Some(Command::Plan {
            scene,
            path,
            lights,
            dot,
        }) => {
            let s = load_scene(&scene, &cli.set, path, lights)?;
            let mut unchecked = gloss::frame::check::check_without_gl(&s)?;
            let plan = gloss::techniques::plan(&s);
            let (w, h) = s.render.size;
            unchecked.extend(gloss::frame::budget::check(&s, &plan.targets, w, h, None)?);
            print!("{plan}");
            if let Some(file) = dot {
                let text = gloss::frame::plan_graph::dot(&plan, &s.name);
                assets::write::write_file(&file, text.as_bytes())?;
                println!("wrote the data-flow diagram to {}", file.display());
            }
            let c = gloss::frame::culling::scene_stats(&s)?;
            println!(
                "frustum culling ({}): the camera sees {} of {} opaque objects, {} culled, in {} sphere and box tests",
                if s.render.frustum_culling {
                    "on"
                } else {
                    "off: every object is drawn"
                },
                c.drawn,
                c.objects,
                c.culled,
                c.tests
            );
            println!(
                "not checked without a GL context (gloss render checks them): {}",
                unchecked.join(", ")
            );
            Ok(())
        }
        Some(Command::Trace {
            scene,
            technique,
            pass,
            size,
            markdown,
            first_frame,
        }) => {
            gloss::gl::trace::enable();
            let ctx = Headless::new(headless_backend(cli.backend)?, cli.debug)?;
            let mut s = load_scene(&scene, &cli.set, None, None)?;
            if let Some(sz) = size {
                s.render.size = sz;
            }
            let calls = if first_frame {
                gloss::trace::trace_first_frame(&ctx, &s)?
            } else {
                gloss::trace::trace_frame(&ctx, &s)?
            };
            let filter = gloss::trace::listing::Filter { technique, pass };
            gloss::trace::docs::kept(&calls, &filter)?;
            print!(
                "{}",
                gloss::trace::listing::render(&calls, &filter, markdown)
            );
            Ok(())
        }
        Some(Command::Probe {
            scene,
            x,
            y,
            size,
            path,
        }) => {
            let mut s = load_scene(&scene, &cli.set, path, None)?;
            if let Some(sz) = size {
                s.render.size = sz;
            }
            let ctx = Headless::new(headless_backend(cli.backend)?, cli.debug)?;
            let r = gloss::renderer::render_scene(&ctx, &s, gloss::renderer::Output::Srgb8)?;
            print!("{}", r.probe(&s.camera, x, y)?);
            ctx.debug.check(&ctx.gl, "the probe's read-back")?;
            Ok(())
        }
        Some(Command::Scenes) => {
            for s in assets::shipped_scenes() {
                println!("{s}");
            }
            Ok(())
        }
        Some(Command::Bench(args)) => {
            let args = gloss::bench::BenchArgs {
                set: cli.set.clone(),
                ..args
            };
            gloss::bench::run(&args, headless_backend(cli.backend)?)
                .map_err(|e| anyhow!("bench: {e:#}"))
        }
    }
}
