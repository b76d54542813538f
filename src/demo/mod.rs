//! The interactive demo: a window that shows the renderer's frames live.
//!
//! Each frame the renderer draws into its own framebuffer (`Renderer::output`)
//! and the demo copies that to the window with glBlitFramebuffer, then swaps.
//! Left-drag orbits around the scene camera's target, the wheel zooms, Esc or
//! closing the window quits. The title shows the scene and the frame time,
//! measured with the CPU clock from one swap to the next.
//!
//! The files: `orbit` (the camera control), `shaders` (live shader reload),
//! `present` (the blit to the window), `clock` (the title's frame time).

mod clock;
mod orbit;
mod present;
mod shaders;

use crate::gl::program::Sources;
use crate::gl::window::{self, WindowContext};
use crate::renderer::Renderer;
use crate::scene::Scene;
use anyhow::{Context as _, Result, anyhow, bail};
use clock::TitleClock;
use orbit::Orbit;
use present::present;
use shaders::{shader_names, shader_sources};
use std::path::Path;
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

/// How the demo runs.
#[derive(Clone, Debug)]
pub struct DemoOptions {
    /// Debug context + KHR_debug checks; any GL error ends the demo with an error.
    pub debug: bool,
    /// Exit after this many frames (smoke tests); `None` runs until closed.
    pub frames: Option<u32>,
    /// Initial window size in pixels.
    pub size: (u32, u32),
}

/// Open a window on `scene_path` and run until it is closed (or for `options.frames` frames).
pub fn run(scene_path: &Path, options: DemoOptions) -> Result<()> {
    let (w, h) = options.size;
    if w == 0 || h == 0 || w > 16384 || h > 16384 {
        bail!("the window size must be between 1x1 and 16384x16384, not {w}x{h}");
    }
    // Load the scene before opening anything: a bad file fails fast.
    let scene = Scene::load(scene_path)?;
    let event_loop = window::event_loop()?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut demo = Demo {
        orbit: Orbit::new(&scene.camera),
        scene,
        options,
        sources: shader_sources(),
        running: None,
        error: None,
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
    scene: Scene,
    options: DemoOptions,
    sources: Sources,
    orbit: Orbit,
    running: Option<Running>,
    error: Option<anyhow::Error>,
}

/// Everything that lives while the window is open.
struct Running {
    // Declared before `ctx`: its GL objects are freed while the context lives.
    renderer: Renderer,
    ctx: WindowContext,
    frames: u32,
    left_down: bool,
    cursor: Option<PhysicalPosition<f64>>,
    title: TitleClock,
    /// Live shader reload: when glsl/ was last seen changed, and when we last looked.
    shaders_seen: Option<std::time::SystemTime>,
    shaders_checked: std::time::Instant,
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
        let (w, h) = self.options.size;
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
            to_i32(w),
            to_i32(h),
        )
        .with_context(|| format!("could not set up the renderer for {}", self.scene.name))?;
        Ok(Running {
            renderer,
            ctx,
            frames: 0,
            left_down: false,
            cursor: None,
            title: TitleClock::new(),
            shaders_seen: self.sources.modified(&shader_names()),
            shaders_checked: std::time::Instant::now(),
        })
    }

    /// Render, blit to the window, swap. Returns whether the demo should stop.
    fn frame(&mut self) -> Result<bool> {
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        if let Some(n) = self.options.frames
            && run.frames >= n
        {
            return Ok(true);
        }
        let (w, h) = run.ctx.size();
        if w == 0 || h == 0 {
            return Ok(false); // minimised
        }
        self.reload_shaders_if_changed();
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        run.renderer.render(&self.orbit.camera())?;
        present(&run.ctx, run.renderer.output(), to_i32(w), to_i32(h))?;
        run.ctx.swap_buffers()?;
        run.frames += 1;
        if let Some(ms) = run.title.tick() {
            run.ctx.window.set_title(&format!(
                "gloss — {} — {ms:.2} ms/frame ({:.0} fps)",
                self.scene.name,
                1000.0 / ms.max(1e-3)
            ));
        }
        Ok(self.options.frames.is_some_and(|n| run.frames >= n))
    }

    fn handle(&mut self, event_loop: &ActiveEventLoop, event: WindowEvent) -> Result<()> {
        let Some(run) = self.running.as_mut() else {
            return Ok(());
        };
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => event_loop.exit(),
            WindowEvent::KeyboardInput { event, .. }
                if event.state == ElementState::Pressed
                    && event.logical_key == Key::Named(NamedKey::Escape) =>
            {
                event_loop.exit()
            }
            // A zero size (minimised) keeps the old size until the window comes back.
            WindowEvent::Resized(size) if size.width > 0 && size.height > 0 => {
                run.ctx.resize(size.width, size.height);
                run.renderer
                    .resize(to_i32(size.width), to_i32(size.height))
                    .context("could not resize the renderer")?;
            }
            WindowEvent::MouseInput {
                button: MouseButton::Left,
                state,
                ..
            } => run.left_down = state == ElementState::Pressed,
            WindowEvent::CursorMoved { position, .. } => {
                if let (true, Some(last)) = (run.left_down, run.cursor) {
                    self.orbit
                        .rotate((position.x - last.x) as f32, (position.y - last.y) as f32);
                }
                run.cursor = Some(position);
            }
            WindowEvent::CursorLeft { .. } => run.cursor = None,
            WindowEvent::MouseWheel { delta, .. } => self.orbit.zoom(match delta {
                MouseScrollDelta::LineDelta(_, y) => y,
                MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
            }),
            WindowEvent::RedrawRequested if self.frame()? => event_loop.exit(),
            _ => {}
        }
        Ok(())
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
        // Free the renderer's GL objects, then the context, while the display is open.
        self.running = None;
    }
}

fn to_i32(v: u32) -> i32 {
    i32::try_from(v).unwrap_or(i32::MAX)
}
