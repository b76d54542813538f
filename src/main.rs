//! The `gloss` command line.

use anyhow::{Context as _, Result, anyhow, bail};
use clap::{Parser, Subcommand};
use gloss::assets;
use gloss::gl::{Backend, Headless};
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene, Shading};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "gloss",
    version,
    about = "OpenGL 3.3 core reference renderer for a real-time graphics course"
)]
struct Cli {
    /// egl | osmesa | window (default: window when a display exists, else egl)
    #[arg(long, global = true, value_enum)]
    backend: Option<Backend>,
    /// GL debug output on; any GL error is fatal.
    #[arg(long, global = true)]
    debug: bool,
    /// Set a scene-file key, as if written in the file: render.cutoff=0.01,
    /// render.path=volumes, render.ambient=[0.1,0.1,0.1]. Repeatable.
    #[arg(long = "set", global = true, value_name = "KEY=VALUE")]
    set: Vec<String>,
    /// Demo: start with the panel hidden (Tab shows it).
    #[arg(long)]
    no_panel: bool,
    /// Demo: do not time each pass (glFinish after every pass) while the panel is shown.
    #[arg(long)]
    no_pass_times: bool,
    /// Demo: exit after this many frames (smoke tests).
    #[arg(long)]
    frames: Option<u32>,
    /// Demo / default render: the scene (default scenes/default.toml).
    scene: Option<PathBuf>,
    #[command(subcommand)]
    command: Option<Command>,
}

/// A buffer `gloss render --inspect` writes instead of the image.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Inspect {
    /// The output's stencil buffer at the end of the frame.
    Stencil,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene headless to a PNG.
    Render {
        scene: PathBuf,
        #[arg(short, long)]
        output: PathBuf,
        /// WIDTHxHEIGHT (default: the scene's render.size)
        #[arg(long, value_parser = gloss::bench::parse_size)]
        size: Option<(u32, u32)>,
        /// Override the scene's render path.
        #[arg(long, value_enum)]
        path: Option<RenderPath>,
        /// Override the scene's shading mode.
        #[arg(long, value_enum)]
        shading: Option<Shading>,
        /// Number of generated lights (scenes with a [light_grid]).
        #[arg(long)]
        lights: Option<usize>,
        /// Write a buffer other than the image: `stencil` (each stencil
        /// value its own colour, 0 black).
        #[arg(long, value_enum)]
        inspect: Option<Inspect>,
        /// With --inspect: the buffer as it is after this pass (1-based, as
        /// `gloss plan` numbers them) rather than at the end of the frame.
        #[arg(long, requires = "inspect")]
        after: Option<usize>,
    },
    /// Print GL_VERSION, GL_RENDERER, GLSL version, backend and context flags.
    Info,
    /// Print the passes and render targets a scene's frame uses.
    Plan {
        scene: PathBuf,
        #[arg(long, value_enum)]
        path: Option<RenderPath>,
        #[arg(long)]
        lights: Option<usize>,
    },
    /// List the scenes shipped inside gloss (usable from any directory by name).
    Scenes,
    /// Measure speed against error for render paths, light counts and cutoffs.
    Bench(gloss::bench::BenchArgs),
}

fn main() -> ExitCode {
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
) -> Result<()> {
    let ctx = Headless::new(backend, debug)?;
    let mut r = render_scene(&ctx, scene, Output::Srgb8)?;
    let (w, h) = (r.width as u32, r.height as u32);
    let img = match inspect {
        None => r.read_image(),
        Some((Inspect::Stencil, None)) => gloss::renderer::stencil_image(&r.read_stencil(), w, h),
        Some((Inspect::Stencil, Some(pass))) => {
            let stencil = r.stencil_after(&scene.camera, pass)?;
            gloss::renderer::stencil_image(&stencil, w, h)
        }
    };
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    // Write to a temporary name and rename, so a failed write never leaves half a file
    // where the user's old picture was.
    // On any failure the temporary file goes too.
    if out.is_dir() {
        bail!("cannot write {}: it is a directory", out.display());
    }
    let tmp = out.with_extension("png.tmp");
    let written = img
        .save_with_format(&tmp, image::ImageFormat::Png)
        .map_err(anyhow::Error::from)
        .and_then(|()| std::fs::rename(&tmp, out).map_err(anyhow::Error::from));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(e.context(format!("cannot write {}", out.display())));
    }
    Ok(())
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
    Ok(scene)
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        None => {
            let scene_path = cli
                .scene
                .map(|s| assets::scene_path(&s))
                .unwrap_or_else(default_scene);
            let want_window = match cli.backend {
                Some(Backend::Window) => true,
                Some(_) => false,
                None => gloss::gl::window::display_available(),
            };
            if want_window {
                gloss::demo::run(
                    &scene_path,
                    gloss::demo::DemoOptions {
                        debug: cli.debug,
                        frames: cli.frames,
                        size: (1280, 720),
                        overrides: cli.set.clone(),
                        panel: !cli.no_panel,
                        pass_times: !cli.no_pass_times,
                    },
                )
            } else {
                let scene = Scene::load_with(&scene_path, &cli.set)?;
                let out = std::env::current_dir()?.join(format!("gloss-{}.png", scene.name));
                let backend = headless_backend(cli.backend)?;
                render_to_png(&scene, backend, cli.debug, &out, None)?;
                println!(
                    "no display: rendered {} headless ({backend}) to {}",
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
        }) => {
            let s = load_scene(&scene, &cli.set, path, lights)?;
            print!("{}", gloss::techniques::plan(&s));
            Ok(())
        }
        Some(Command::Scenes) => {
            for s in assets::shipped_scenes() {
                println!("{s}");
            }
            Ok(())
        }
        Some(Command::Bench(args)) => gloss::bench::run(&args, headless_backend(cli.backend)?)
            .map_err(|e| anyhow!("bench: {e:#}")),
    }
}
