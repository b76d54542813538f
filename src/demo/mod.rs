//! The interactive demo: a window where the course is explored. Each frame
//! the renderer runs the frame plan into its own framebuffer; the demo shows
//! that (or, in the pass inspector, one of the plan's targets) in the window,
//! draws the panel (egui) over it, restores the GL state egui changed, and
//! swaps.
//!
//! The files: `panel/` (the egui panel: scene, techniques and their
//! settings, inspector, timings, plan, keys), `actions` (carrying out what
//! the panel and the keys ask), `inspector` (the view pass, over the views
//! of `inspect_views`; its shadow-map
//! and light-volume views in `shadow_views` and `volume_views`), `keys`,
//! `screenshot`, `orbit` (the camera), `shaders` (live reload of glsl/),
//! `present` (the blit to the window and the state restore after egui),
//! `pictures` (`gloss render --target` for the shadow maps and mip levels),
//! `post_chain` (the panel's chain edits checked, the chain's images named),
//! `layout` (where the panel's widgets are, for the window tests).

mod actions;
mod clock;
pub mod compare;
mod frame;
mod input;
mod inspect_views;
pub mod inspector;
mod keys;
pub mod layout;
mod orbit;
pub mod panel;
mod panel_layer;
pub mod pictures;
pub mod post_chain;
mod present;
mod probe;

pub use frame::frame_views;
pub use present::restore_after_egui;
mod screenshot;
mod shaders;
pub mod shadow_views;
mod stencil_marks;
mod thumbnails;
pub mod volume_views;

use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Sources;
use crate::gl::window::{self, WindowContext};
use crate::renderer::Renderer;
use crate::scene::Scene;
use anyhow::{Context as _, Result, anyhow, bail};
use clock::TitleClock;
use inspector::Inspector;
use orbit::Orbit;
use panel::PanelState;
use shaders::{shader_names, shader_sources};
use std::path::{Path, PathBuf};
use std::time::Instant;
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow};
use winit::window::{Window, WindowId};

/// How the demo runs.
#[derive(Clone, Debug)]
pub struct DemoOptions {
    /// Debug context + KHR_debug checks; any GL error ends the demo with an error.
    pub debug: bool,
    /// Exit after this many frames (smoke tests); `None` runs until closed.
    pub frames: Option<u32>,
    /// Initial window size in pixels (None: the scene's render.size
    /// beside the panel, fitted to the screen).
    pub size: Option<(u32, u32)>,
    /// `--set KEY=VALUE` overrides of the scene file.
    pub overrides: Vec<String>,
    /// Start with the panel shown.
    pub panel: bool,
    /// Time each pass while the panel is shown.
    pub pass_times: bool,
}

/// Open a window on `scene_path` and run until it is closed (or for `options.frames` frames).
pub fn run(scene_path: &Path, options: DemoOptions) -> Result<()> {
    if let Some((w, h)) = options.size
        && (w == 0 || h == 0 || w > 16384 || h > 16384)
    {
        bail!("--window: the window size must be between 1x1 and 16384x16384, not {w}x{h}");
    }
    // Load the scene before opening anything: a bad file fails fast.
    let scene = Scene::load_with(scene_path, &options.overrides)?;
    scene.print_warnings(&scene.warnings());
    let event_loop = window::event_loop()?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut demo = Demo {
        orbit: Orbit::new(&scene.camera),
        scene_path: scene_path.to_path_buf(),
        scene_seen: modified(scene_path),
        scene,
        options,
        sources: shader_sources(),
        running: None,
        error: None,
        message: None,
        status: None,
    };
    event_loop
        .run_app(&mut demo)
        .map_err(|e| anyhow!("the window's event loop failed: {e}"))?;
    // Normally gone already (`exiting`); the renderer goes before the context.
    demo.running = None;
    match demo.error {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

struct Demo {
    scene_path: PathBuf,
    /// The scene as loaded, with the panel's edits.
    scene: Scene,
    scene_seen: Option<std::time::SystemTime>,
    options: DemoOptions,
    sources: Sources,
    orbit: Orbit,
    running: Option<Running>,
    /// The error that ends the demo.
    error: Option<anyhow::Error>,
    /// The last error shown in the panel (a scene that failed to load, a
    /// shader that failed to compile); the old state keeps running.
    message: Option<String>,
    /// The last thing done, shown in the panel (a screenshot's path).
    status: Option<String>,
}

/// Everything that lives while the window is open. Declared in drop order:
/// GL objects before `ctx`, whose context they need.
struct Running {
    renderer: Renderer,
    egui: egui_glow::EguiGlow,
    panel: PanelState,
    inspector: Inspector,
    volume_views: volume_views::VolumeViews,
    shadow_views: shadow_views::ShadowViews,
    thumbnails: thumbnails::Thumbnails,
    /// The last "compare with reference", until the settings or scene change.
    comparison: Option<compare::Comparison>,
    /// The view the inspector showed last frame (see `inspector::follow`).
    inspected: Option<inspector::View>,
    /// What the inspector draws into (never one of the renderer's targets).
    inspect_fb: Option<Framebuffer>,
    /// The panel, drawn when due and laid over every frame.
    panel_layer: panel_layer::PanelLayer,
    /// Where the panel's widgets are, written after each egui pass
    /// (`GLOSS_DEMO_LAYOUT`).
    layout: Option<layout::Layout>,
    ctx: WindowContext,
    /// What the panel lists and names, found once: the shipped scenes, the GL.
    shipped: Vec<String>,
    gl_info: String,
    frames: u32,
    left_down: bool,
    /// Right or middle button held: pan.
    pan_down: bool,
    /// Fly mode (F): the drag turns the view, W A S D Q E move.
    fly: bool,
    /// The fly-mode keys held down.
    held: std::collections::HashSet<char>,
    cursor: Option<PhysicalPosition<f64>>,
    /// Where the left button went down in the view (a click or a drag).
    pressed_at: Option<PhysicalPosition<f64>>,
    /// The probed pixel of the frame (from the top left), what the probe
    /// read there this frame, and whether to print it (after a click).
    probe_at: Option<(u32, u32)>,
    probe: Option<crate::renderer::Probe>,
    probe_log: bool,
    /// The 3D view's rectangle in the window (x, y from the top left,
    /// width, height, in pixels): beside the panel, or the whole window.
    view: [i32; 4],
    title: TitleClock,
    last_swap: Instant,
    /// A screenshot asked for: Some(true) with the panel, Some(false) without.
    screenshot: Option<bool>,
    modifiers: winit::keyboard::ModifiersState,
    /// Live reload: when glsl/ and the scene file were last looked at.
    shaders_seen: Option<std::time::SystemTime>,
    checked: Instant,
}

fn modified(path: &Path) -> Option<std::time::SystemTime> {
    std::fs::metadata(path).and_then(|m| m.modified()).ok()
}

impl Demo {
    /// Record the first error and stop the loop.
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        if self.error.is_none() {
            self.error = Some(error);
        }
        event_loop.exit();
    }

    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<Running> {
        let screen = (event_loop.primary_monitor())
            .or_else(|| event_loop.available_monitors().next())
            .map(|m| (m.size().width, m.size().height));
        let (w, h) = self.options.size.unwrap_or_else(|| {
            let panel = if self.options.panel {
                u32::from(panel::PANEL_WIDTH)
            } else {
                0
            };
            fit_window(self.scene.render.size, panel, screen)
        });
        let attributes = Window::default_attributes()
            .with_title(format!("gloss — {}", self.scene.name))
            .with_inner_size(PhysicalSize::new(w, h));
        let ctx = WindowContext::new(event_loop, attributes, self.options.debug)?;
        println!(
            "gloss: {} ({}), OpenGL {}.{} core",
            ctx.info.renderer, ctx.info.vendor, ctx.info.major, ctx.info.minor
        );
        let (w, h) = ctx.size();
        let renderer = Renderer::new(
            &ctx.gl,
            &ctx.debug,
            &self.scene,
            &self.sources,
            to_i32(w.max(1)),
            to_i32(h.max(1)),
        )
        .with_context(|| format!("could not set up the renderer for {}", self.scene.name))?;
        let egui = egui_glow::EguiGlow::new(event_loop, ctx.gl.clone(), None, None, true);
        // No animations: at a few frames a second (llvmpipe) they only
        // leave the panel half open when a screenshot is taken.
        egui.egui_ctx.all_styles_mut(|s| s.animation_time = 0.0);
        let layout = layout::Layout::from_env(&egui.egui_ctx);
        let mut panel = PanelState::new(&self.scene_path.display().to_string());
        panel.open = self.options.panel;
        panel.pass_times = self.options.pass_times;
        Ok(Running {
            renderer,
            egui,
            panel,
            inspector: Inspector::new(&ctx.gl, &self.sources)?,
            volume_views: volume_views::VolumeViews::new(&ctx.gl, &self.sources)?,
            shadow_views: shadow_views::ShadowViews::new(&ctx.gl, &self.sources)?,
            comparison: None,
            thumbnails: thumbnails::Thumbnails::new(),
            inspected: None,
            inspect_fb: None,
            panel_layer: panel_layer::PanelLayer::new(&ctx.gl, &self.sources)?,
            layout,
            shipped: crate::assets::shipped_scenes(),
            gl_info: format!(
                "{} — OpenGL {}.{} core",
                ctx.info.renderer, ctx.info.major, ctx.info.minor
            ),
            ctx,
            frames: 0,
            left_down: false,
            pan_down: false,
            fly: false,
            held: Default::default(),
            cursor: None,
            pressed_at: None,
            probe_at: None,
            probe: None,
            probe_log: false,
            view: [0, 0, to_i32(w), to_i32(h)],
            title: TitleClock::new(),
            last_swap: Instant::now(),
            screenshot: None,
            modifiers: Default::default(),
            shaders_seen: self.sources.modified(&shader_names()),
            checked: Instant::now(),
        })
    }
}

impl ApplicationHandler for Demo {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() || self.error.is_some() {
            return;
        }
        match self.open(event_loop) {
            Ok(run) => self.running = Some(run),
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        if let Err(e) = self.handle(event_loop, event) {
            self.fail(event_loop, e);
        }
    }

    fn about_to_wait(&mut self, _event_loop: &ActiveEventLoop) {
        if let Some(run) = &self.running {
            run.ctx.window.request_redraw();
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        // Free egui's and the renderer's GL objects, then the context, while
        // the display is open.
        if let Some(run) = self.running.as_mut() {
            if let Some(ms) = run.panel.timings.median() {
                println!(
                    "gloss: {} frames, median {ms:.2} ms/frame ({:.1} fps), panel {}",
                    run.frames,
                    1000.0 / ms.max(1e-3),
                    if run.panel.open { "shown" } else { "hidden" }
                );
            }
            run.egui.destroy();
        }
        self.running = None;
    }
}

/// The window for a view of the scene's `size` with a panel `panel` pixels
/// wide beside it, scaled down (keeping its shape) to fit a `screen` of
/// that size when one is known.
pub fn fit_window((w, h): (u32, u32), panel: u32, screen: Option<(u32, u32)>) -> (u32, u32) {
    let (w, h) = (w.max(1) + panel, h.max(1));
    let Some((sw, sh)) = screen.filter(|&(sw, sh)| sw > 0 && sh > 0) else {
        return (w, h);
    };
    let s = (f64::from(sw) / f64::from(w))
        .min(f64::from(sh) / f64::from(h))
        .min(1.0);
    let fit = |v: u32| ((f64::from(v) * s).floor() as u32).max(1);
    (fit(w), fit(h))
}

fn to_i32(v: u32) -> i32 {
    i32::try_from(v).unwrap_or(i32::MAX)
}
