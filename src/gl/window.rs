//! A window with an OpenGL 3.3 core context: winit 0.30 + glutin 0.32 (../shared/stack-facts.md).
//!
//! winit allows one event loop per process, and a failed attempt to make one
//! uses up that chance. So [`display_available`] keeps the loop it made (on
//! this thread) and [`event_loop`] hands it out later.
//!
//! [`WindowContext::new`] runs inside `ApplicationHandler::resumed`: it opens
//! the GL display (GLX under X11, EGL as the fallback and under Wayland), picks
//! a config with depth 24 / stencil 8, creates the window with that config's
//! visual (glutin-winit's `finalize_window`), a 3.3 core context and a window
//! surface, makes them current and loads glow.

use super::{Backend, Gl, GlInfo, debug::DebugLog};
use anyhow::{Context as _, Result, anyhow, bail};
use glutin::config::{Api, Config, ConfigTemplateBuilder, GlConfig};
use glutin::context::{
    ContextApi, ContextAttributesBuilder, GlProfile, NotCurrentGlContext, PossiblyCurrentContext,
    Version,
};
use glutin::display::{Display, DisplayApiPreference, GlDisplay};
use glutin::surface::{GlSurface, Surface, SurfaceAttributesBuilder, SwapInterval, WindowSurface};
use raw_window_handle::{HasDisplayHandle, HasWindowHandle};
use std::cell::RefCell;
use std::ffi::CString;
use std::num::NonZeroU32;
use std::sync::Arc;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::window::{Window, WindowAttributes};

const INSTALL_HINT: &str = "install Mesa's OpenGL drivers: \
     apt-get install libgl1 libglx-mesa0 libegl1 libegl-mesa0 libgl1-mesa-dri";

thread_local! {
    // The event loop display_available made (or why it could not), kept for event_loop().
    static EVENT_LOOP: RefCell<Option<Result<EventLoop<()>, String>>> = const { RefCell::new(None) };
}

fn env_set(name: &str) -> bool {
    std::env::var_os(name).is_some_and(|v| !v.is_empty())
}

fn new_event_loop() -> Result<EventLoop<()>, String> {
    if !(env_set("DISPLAY") || env_set("WAYLAND_DISPLAY") || env_set("WAYLAND_SOCKET")) {
        return Err("no display: neither DISPLAY nor WAYLAND_DISPLAY is set \
                    (run under a desktop session or xvfb-run, or use --backend egl)"
            .to_owned());
    }
    let mut builder = EventLoop::builder();
    // Only the demo thread ever touches the loop; allowing other threads
    // turns winit's "not the main thread" panic into something tests can use.
    winit::platform::x11::EventLoopBuilderExtX11::with_any_thread(&mut builder, true);
    builder.build().map_err(|e| match e {
        winit::error::EventLoopError::RecreationAttempt => {
            "winit allows one event loop per process and this process already made one \
             (call display_available and demo::run on the same thread)"
                .to_owned()
        }
        e => format!("could not connect to the display ({e}); check DISPLAY / WAYLAND_DISPLAY"),
    })
}

/// Whether a window can be opened: DISPLAY or WAYLAND_DISPLAY is set and
/// winit can connect to it. The CLI falls back to headless when this is false.
///
/// The event loop made to find out is kept for [`event_loop`] on this thread.
pub fn display_available() -> bool {
    display_problem().is_none()
}

/// Why no window can be opened, in the window backend's own words (None:
/// one can). The CLI prints it before it falls back to headless.
pub fn display_problem() -> Option<String> {
    EVENT_LOOP.with(|cell| {
        let mut cell = cell.borrow_mut();
        cell.get_or_insert_with(new_event_loop)
            .as_ref()
            .err()
            .cloned()
    })
}

/// The event loop for the window: the one [`display_available`] made on this
/// thread, or a new one.
pub fn event_loop() -> Result<EventLoop<()>> {
    let cached = EVENT_LOOP.with(|cell| cell.borrow_mut().take());
    cached
        .unwrap_or_else(new_event_loop)
        .map_err(|e| anyhow!("cannot open a window: {e}"))
}

/// A window, its surface and a current 3.3 core context.
///
/// Drop every GL object made from `gl` before this.
pub struct WindowContext {
    pub gl: Gl,
    pub info: GlInfo,
    pub debug: DebugLog,
    // Dropped in this order: surface, context, then the window itself.
    surface: Surface<WindowSurface>,
    context: PossiblyCurrentContext,
    pub window: Window,
}

impl WindowContext {
    /// Open a window with `attributes` and make its 3.3 core context current.
    /// `debug` asks for a debug context (retrying without one if the driver
    /// refuses) and installs the KHR_debug callback. Vsync is turned off where
    /// the driver allows it, so frame times mean something.
    pub fn new(
        event_loop: &ActiveEventLoop,
        attributes: WindowAttributes,
        debug: bool,
    ) -> Result<WindowContext> {
        let display = open_display(event_loop)?;
        let config = pick_config(&display)?;
        let window = glutin_winit::finalize_window(event_loop, attributes, &config)
            .map_err(|e| anyhow!("could not create the window ({e})"))?;
        let raw_window = window
            .window_handle()
            .map_err(|e| anyhow!("the window has no native handle ({e})"))?
            .as_raw();

        let attributes = |debug: bool| {
            ContextAttributesBuilder::new()
                .with_context_api(ContextApi::OpenGl(Some(Version::new(3, 3))))
                .with_profile(GlProfile::Core)
                .with_debug(debug)
                .build(Some(raw_window))
        };
        let context = match unsafe { display.create_context(&config, &attributes(debug)) } {
            Ok(c) => c,
            Err(_) if debug => unsafe { display.create_context(&config, &attributes(false)) }
                .map_err(|e| {
                    anyhow!("could not create an OpenGL 3.3 core context ({e}); {INSTALL_HINT}")
                })?,
            Err(e) => {
                bail!("could not create an OpenGL 3.3 core context ({e}); {INSTALL_HINT}")
            }
        };

        let size = window.inner_size();
        let surface_attributes = SurfaceAttributesBuilder::<WindowSurface>::new().build(
            raw_window,
            non_zero(size.width),
            non_zero(size.height),
        );
        let surface = unsafe { display.create_window_surface(&config, &surface_attributes) }
            .map_err(|e| anyhow!("could not create the window's GL surface ({e})"))?;
        let context = context
            .make_current(&surface)
            .map_err(|e| anyhow!("could not make the window's GL context current ({e})"))?;
        // Not every driver lets us turn vsync off; the demo works either way.
        let _ = surface.set_swap_interval(&context, SwapInterval::DontWait);

        let mut gl = unsafe {
            glow::Context::from_loader_function(|name| match CString::new(name) {
                Ok(name) => display.get_proc_address(&name) as *const _,
                Err(_) => std::ptr::null(),
            })
        };
        let info = GlInfo::query(&gl, Backend::Window);
        info.require_33_core()?;
        let debug = DebugLog::install(&mut gl, debug);
        Ok(WindowContext {
            gl: Arc::new(gl),
            info,
            debug,
            surface,
            context,
            window,
        })
    }

    /// The window's drawable size in pixels.
    pub fn size(&self) -> (u32, u32) {
        let s = self.window.inner_size();
        (s.width, s.height)
    }

    /// Resize the surface after the window's size changed (no-op for a zero size).
    pub fn resize(&self, width: u32, height: u32) {
        if let (Some(w), Some(h)) = (NonZeroU32::new(width), NonZeroU32::new(height)) {
            self.surface.resize(&self.context, w, h);
        }
    }

    /// Present the back buffer.
    pub fn swap_buffers(&self) -> Result<()> {
        self.surface
            .swap_buffers(&self.context)
            .context("could not swap the window's buffers")
    }
}

/// Open a small hidden window, make its context and report what it is
/// (`gloss info --backend window`). Uses up this process's event loop.
pub fn query_info(debug: bool) -> Result<GlInfo> {
    struct Probe {
        debug: bool,
        result: Option<Result<GlInfo>>,
    }
    impl winit::application::ApplicationHandler for Probe {
        fn resumed(&mut self, event_loop: &ActiveEventLoop) {
            if self.result.is_none() {
                let attributes = Window::default_attributes()
                    .with_title("gloss info")
                    .with_visible(false)
                    .with_inner_size(winit::dpi::PhysicalSize::new(64u32, 64u32));
                self.result =
                    Some(WindowContext::new(event_loop, attributes, self.debug).map(|c| c.info));
            }
            event_loop.exit();
        }
        fn window_event(
            &mut self,
            _: &ActiveEventLoop,
            _: winit::window::WindowId,
            _: winit::event::WindowEvent,
        ) {
        }
    }
    let mut probe = Probe {
        debug,
        result: None,
    };
    event_loop()?
        .run_app(&mut probe)
        .map_err(|e| anyhow!("the window's event loop failed: {e}"))?;
    probe
        .result
        .unwrap_or_else(|| Err(anyhow!("the window system never let gloss create a window")))
}

fn non_zero(v: u32) -> NonZeroU32 {
    NonZeroU32::new(v).unwrap_or(NonZeroU32::MIN)
}

#[cfg(target_os = "linux")]
fn open_display(event_loop: &ActiveEventLoop) -> Result<Display> {
    let handle = event_loop
        .display_handle()
        .map_err(|e| anyhow!("the event loop has no display handle ({e})"))?
        .as_raw();
    // GLX first under X11 (what glutin-winit's DisplayBuilder does by
    // default), EGL when GLX fails and under Wayland.
    let preference =
        DisplayApiPreference::GlxThenEgl(Box::new(winit::platform::x11::register_xlib_error_hook));
    unsafe { Display::new(handle, preference) }.map_err(|e| {
        anyhow!(
            "could not open an OpenGL display (GLX or EGL): {e}; {INSTALL_HINT} \
                 (under Xvfb, the screen must be 24-bit: -screen 0 1280x720x24)"
        )
    })
}

#[cfg(not(target_os = "linux"))]
fn open_display(_event_loop: &ActiveEventLoop) -> Result<Display> {
    bail!("the window backend is written for Linux (GLX / EGL); use --backend egl")
}

/// An OpenGL config with depth 24 and stencil 8, single-sampled where possible.
fn pick_config(display: &Display) -> Result<Config> {
    let template = ConfigTemplateBuilder::new()
        .with_api(Api::OPENGL)
        .with_depth_size(24)
        .with_stencil_size(8)
        .with_transparency(false)
        .build();
    let configs: Vec<Config> = unsafe { display.find_configs(template) }
        .map_err(|e| anyhow!("the display has no OpenGL config ({e}); {INSTALL_HINT}"))?
        .collect();
    // gloss renders into its own FBOs and blits: multisampling the window
    // would only cost time.
    configs
        .iter()
        .find(|c| c.num_samples() <= 1)
        .or(configs.first())
        .cloned()
        .ok_or_else(|| {
            anyhow!(
                "the display offers no OpenGL window config with a 24-bit depth and \
                 8-bit stencil buffer (under Xvfb use -screen 0 1280x720x24); {INSTALL_HINT}"
            )
        })
}
