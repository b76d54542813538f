//! The interactive demo: a window that shows the renderer's frames live.
//!
//! Each frame the renderer draws into its own framebuffer (`Renderer::output`)
//! and the demo copies that to the window with glBlitFramebuffer, then swaps.
//! Left-drag orbits around the scene camera's target, the wheel zooms, Esc or
//! closing the window quits. The title shows the scene and the frame time,
//! measured with the CPU clock from one swap to the next.

use crate::gl::program::{self, Sources};
use crate::gl::window::{self, WindowContext};
use crate::renderer::Renderer;
use crate::scene::{Camera, Projection, Scene};
use anyhow::{Context as _, Result, anyhow, bail};
use glam::{Quat, Vec3};
use glow::HasContext;
use std::f32::consts::PI;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
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

/// `./glsl` when it is gloss's shader directory (running from the crate, so
/// edited shaders are picked up), else the shaders compiled into the binary.
/// Every shader file gloss embeds (the ones live reload watches).
fn shader_names() -> Vec<&'static str> {
    static NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    NAMES
        .get_or_init(program::embedded_names)
        .iter()
        .map(String::as_str)
        .collect()
}

fn shader_sources() -> Sources {
    let dir = PathBuf::from("glsl");
    let names = program::embedded_names();
    if dir.is_dir() && !names.is_empty() && names.iter().all(|n| dir.join(n).is_file()) {
        let dir = dir.canonicalize().unwrap_or(dir);
        println!("gloss: shaders from {}", dir.display());
        Sources::Directory(dir)
    } else {
        Sources::Embedded
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

    /// Live shader reload: twice a second, look at glsl/'s modification times;
    /// when a file changed, build a new renderer from the new sources. A
    /// shader that fails to compile is reported (file and line) and the old
    /// renderer keeps running, so an edit never closes the window.
    fn reload_shaders_if_changed(&mut self) {
        let Some(run) = self.running.as_mut() else {
            return;
        };
        if run.shaders_checked.elapsed() < std::time::Duration::from_millis(500) {
            return;
        }
        run.shaders_checked = std::time::Instant::now();
        let now = self.sources.modified(&shader_names());
        if now == run.shaders_seen {
            return;
        }
        run.shaders_seen = now;
        let (w, h) = run.ctx.size();
        match Renderer::new(
            &run.ctx.gl,
            &run.ctx.debug,
            &self.scene,
            &self.sources,
            to_i32(w.max(1)),
            to_i32(h.max(1)),
        ) {
            Ok(r) => {
                run.renderer = r;
                eprintln!("gloss: shaders reloaded from glsl/");
            }
            Err(e) => eprintln!("gloss: shader reload failed, keeping the old shaders:\n{e:#}"),
        }
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

/// Copy the renderer's colour attachment 0 to the window's back buffer.
///
/// The output already holds sRGB-encoded bytes, so GL_FRAMEBUFFER_SRGB stays
/// off (no second encoding); the scissor test would clip the blit, so it is off too.
fn present(
    ctx: &WindowContext,
    output: &crate::gl::framebuffer::Framebuffer,
    width: i32,
    height: i32,
) -> Result<()> {
    let gl = &ctx.gl;
    unsafe {
        gl.disable(glow::FRAMEBUFFER_SRGB);
        gl.disable(glow::SCISSOR_TEST);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(output.id));
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
        if (output.width, output.height) != (width, height) {
            // A resize is on its way; avoid showing stale pixels at the edges.
            gl.clear_color(0.0, 0.0, 0.0, 1.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
        }
        gl.blit_framebuffer(
            0,
            0,
            output.width,
            output.height,
            0,
            0,
            width,
            height,
            glow::COLOR_BUFFER_BIT,
            glow::NEAREST,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    ctx.debug.check(gl, "presenting the frame")
}

fn to_i32(v: u32) -> i32 {
    i32::try_from(v).unwrap_or(i32::MAX)
}

/// Mean frame time over about half a second, for the title.
struct TitleClock {
    since: Instant,
    frames: u32,
}

impl TitleClock {
    fn new() -> TitleClock {
        TitleClock {
            since: Instant::now(),
            frames: 0,
        }
    }

    /// Count a frame; every ~0.5 s returns the mean ms per frame since the last report.
    fn tick(&mut self) -> Option<f64> {
        self.frames += 1;
        let elapsed = self.since.elapsed();
        if elapsed < Duration::from_millis(500) {
            return None;
        }
        let ms = elapsed.as_secs_f64() * 1000.0 / f64::from(self.frames);
        *self = TitleClock::new();
        Some(ms)
    }
}

/// An orbit around the scene camera's target: the eye moves on a sphere
/// about `target`, with the camera's `up` as the pole.
#[derive(Clone, Debug)]
struct Orbit {
    base: Camera,
    up: Vec3,
    /// Unit vector from the target to the eye.
    direction: Vec3,
    distance: f32,
    base_distance: f32,
}

/// Radians per pixel of mouse drag.
const ORBIT_SPEED: f32 = 0.01;
/// Keep this far (radians) from the poles, where look-at degenerates.
const POLE_MARGIN: f32 = 0.01;

impl Orbit {
    fn new(camera: &Camera) -> Orbit {
        let up = camera.up.normalize_or(Vec3::Y);
        let offset = camera.eye - camera.target;
        let (direction, distance) = if offset.is_finite() && offset.length() > 1e-6 {
            (offset.normalize(), offset.length())
        } else {
            (up.any_orthonormal_vector(), 1.0)
        };
        Orbit {
            base: camera.clone(),
            up,
            direction,
            distance,
            base_distance: distance,
        }
    }

    /// Drag by (dx, dy) pixels: dx turns around `up`, dy tilts toward or away from it.
    fn rotate(&mut self, dx: f32, dy: f32) {
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        let yaw = Quat::from_axis_angle(self.up, -dx * ORBIT_SPEED);
        let mut d = yaw * self.direction;
        let theta = d.angle_between(self.up);
        let new_theta = (theta - dy * ORBIT_SPEED).clamp(POLE_MARGIN, PI - POLE_MARGIN);
        let axis = self.up.cross(d);
        let axis = if axis.length_squared() > 1e-12 {
            axis.normalize()
        } else {
            self.up.any_orthonormal_vector()
        };
        d = Quat::from_axis_angle(axis, new_theta - theta) * d;
        self.direction = d.normalize_or(self.direction);
    }

    /// Wheel `steps` (positive: closer), within 1/100 and 100 times the scene's distance.
    fn zoom(&mut self, steps: f32) {
        if !steps.is_finite() {
            return;
        }
        self.distance = (self.distance * 0.9f32.powf(steps))
            .clamp(self.base_distance * 0.01, self.base_distance * 100.0);
    }

    /// The scene camera moved to the orbit's eye. Zooming also scales an
    /// orthographic view and pushes the far plane out.
    fn camera(&self) -> Camera {
        let mut c = self.base.clone();
        let scale = self.distance / self.base_distance;
        c.eye = c.target + self.direction * self.distance;
        c.up = self.up;
        if let Projection::Orthographic { half_height } = c.projection {
            c.projection = Projection::Orthographic {
                half_height: half_height * scale,
            };
        }
        c.far = self.base.far * scale.max(1.0);
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            eye: Vec3::new(0.0, 2.0, 5.0),
            target: Vec3::new(0.0, 1.0, 0.0),
            up: Vec3::Y,
            projection: Projection::Perspective {
                fov_y_degrees: 45.0,
            },
            near: 0.1,
            far: 50.0,
        }
    }

    #[test]
    fn orbit_starts_at_the_scene_camera() {
        let c = Orbit::new(&camera()).camera();
        assert!((c.eye - camera().eye).length() < 1e-5);
        assert_eq!(c.target, camera().target);
    }

    #[test]
    fn orbit_keeps_distance_and_stays_off_the_poles() {
        let mut o = Orbit::new(&camera());
        let r = (camera().eye - camera().target).length();
        o.rotate(123.0, -40.0);
        assert!(((o.camera().eye - o.base.target).length() - r).abs() < 1e-4);
        o.rotate(0.0, -10_000.0); // far past the pole
        let theta = o.direction.angle_between(Vec3::Y);
        assert!((POLE_MARGIN - 1e-3..=PI - POLE_MARGIN + 1e-3).contains(&theta));
        o.rotate(f32::NAN, 1.0);
        assert!(o.direction.is_finite());
    }

    #[test]
    fn zoom_is_bounded() {
        let mut o = Orbit::new(&camera());
        o.zoom(1e6);
        assert!(o.distance >= o.base_distance * 0.01 - 1e-6);
        o.zoom(-1e6);
        assert!(o.distance <= o.base_distance * 100.0 + 1e-3);
        assert!(o.camera().far >= camera().far);
    }

    #[test]
    fn degenerate_camera_still_orbits() {
        let mut c = camera();
        c.eye = c.target;
        c.up = Vec3::ZERO;
        let mut o = Orbit::new(&c);
        o.rotate(10.0, 10.0);
        o.zoom(3.0);
        assert!(o.camera().eye.is_finite());
    }
}
