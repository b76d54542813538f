//! The `gloss` command line, as clap parses it: the library holds it so
//! that tests can parse argument vectors (`Cli::try_parse_from`) without
//! running the binary; src/main.rs runs what it parses.

use crate::gl::Backend;
use crate::scene::{RenderPath, Shading};
use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "gloss",
    version,
    about = "OpenGL 3.3 core reference renderer for a real-time graphics course"
)]
pub struct Cli {
    /// egl | osmesa | window (default: window when a display exists, else egl)
    #[arg(long, global = true, value_enum)]
    pub backend: Option<Backend>,
    /// GL debug output on; any GL error is fatal.
    #[arg(long, global = true)]
    pub debug: bool,
    /// Set a scene-file key, as if written in the file: render.cutoff=0.01,
    /// render.path=volumes, render.ambient=[0.1,0.1,0.1]. Repeatable.
    #[arg(long = "set", global = true, value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// The instant of the scene's animation to show, in seconds (the same as
    /// --set animation.time=SECONDS).
    #[arg(
        long,
        global = true,
        value_name = "SECONDS",
        allow_negative_numbers = true
    )]
    pub time: Option<f32>,
    /// Demo: start with the panel hidden (Tab shows it).
    #[arg(long)]
    pub no_panel: bool,
    /// Demo: do not time each pass (glFinish after every pass) while the panel is shown.
    #[arg(long)]
    pub no_pass_times: bool,
    /// Demo: the window's size, WIDTHxHEIGHT (default: the scene's
    /// render.size beside the panel, fitted to the screen).
    #[arg(long, value_name = "WxH", value_parser = crate::bench::parse_size)]
    pub window: Option<(u32, u32)>,
    /// Demo: exit after this many frames (smoke tests).
    #[arg(long)]
    pub frames: Option<u32>,
    /// Demo / default render: the scene (default scenes/default.toml).
    pub scene: Option<PathBuf>,
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// A buffer `gloss render --inspect` writes instead of the image.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Inspect {
    /// The output's stencil buffer at the end of the frame.
    Stencil,
}

#[derive(Subcommand)]
pub enum Command {
    /// Render a scene headless to a PNG.
    Render {
        scene: PathBuf,
        #[arg(short, long)]
        output: PathBuf,
        /// WIDTHxHEIGHT (default: the scene's render.size)
        #[arg(long, value_parser = crate::bench::parse_size)]
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
        /// Write one render target's attachment at the end of the frame
        /// instead of the image: TARGET or TARGET.ATTACHMENT, as `gloss plan`
        /// names them (gbuffer.normal_shininess, ambient_occlusion_blurred,
        /// hdr). Made visible: normals as (n + 1) / 2, light sRGB-encoded
        /// and clamped, data (gAlpha, gConvert, the AO) as stored. Also
        /// shadow_map.N (light N's map, a cube unfolded into a cross) and
        /// TARGET.N for a target's mip level N (bloom_levels.1 .. 4), as the
        /// demo's inspector draws them.
        #[arg(long, conflicts_with = "inspect")]
        target: Option<String>,
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
        /// Also write the frame's data-flow diagram (passes, the targets
        /// they read and write) to this file in Graphviz DOT; `dot -Tsvg`
        /// draws it.
        #[arg(long)]
        dot: Option<PathBuf>,
    },
    /// Print what one pixel of the frame holds: every render target's value
    /// there, its depth and the view-space and world position it rebuilds,
    /// its stencil, each casting light's shadow-map lookup (coordinate,
    /// stored and compared depth, lit or in shadow), and on the light-volume
    /// and tiled paths the lights that reach it (docs/demo.md, "Pixel
    /// probe"). X and Y are pixel coordinates in the rendered image, (0, 0)
    /// the top-left pixel, y growing downwards.
    Probe {
        scene: PathBuf,
        /// Column, 0 at the left.
        x: u32,
        /// Row, 0 at the top.
        y: u32,
        /// WIDTHxHEIGHT (default: the scene's render.size)
        #[arg(long, value_parser = crate::bench::parse_size)]
        size: Option<(u32, u32)>,
        /// Override the scene's render path.
        #[arg(long, value_enum)]
        path: Option<RenderPath>,
    },
    /// List the scenes shipped inside gloss (usable from any directory by name).
    Scenes,
    /// Measure speed against error for render paths, light counts and cutoffs.
    Bench(crate::bench::BenchArgs),
    /// List one frame's GL calls in order: each with its arguments as GL
    /// names, the source line that made it, and its pass, technique and
    /// notes section (docs/trace.md).
    Trace {
        scene: PathBuf,
        /// Keep only the passes of this technique (as `gloss plan` and the
        /// docs name it: light_volumes, shadow_map, ...).
        #[arg(long)]
        technique: Option<String>,
        /// Keep only the passes of this name (lighting, gbuffer, ...).
        #[arg(long)]
        pass: Option<String>,
        /// WIDTHxHEIGHT (default: the scene's render.size)
        #[arg(long, value_parser = crate::bench::parse_size)]
        size: Option<(u32, u32)>,
        /// Markdown, as docs/ shows it.
        #[arg(long)]
        markdown: bool,
        /// The first frame (with what is drawn only when something changed,
        /// such as the sky's cube map) rather than the second.
        #[arg(long)]
        first_frame: bool,
    },
}
