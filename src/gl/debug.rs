//! GL error reporting: KHR_debug output where the driver has it, glGetError otherwise.
//!
//! Tests and `--debug` turn this on; any error it records fails the test or the run.

use anyhow::{Result, bail};
use glow::HasContext;
use std::cell::{Cell, RefCell};
use std::sync::{Arc, Mutex};

thread_local! {
    /// Whether draws on this thread check for feedback loops (set by a
    /// DebugLog installed with checks on; the context is current on this thread).
    static CHECK_FEEDBACK: Cell<bool> = const { Cell::new(false) };
    /// Feedback loops found since the last `DebugLog::check`.
    static FEEDBACK_LOOPS: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

/// Messages the driver reported. Errors (and high-severity messages) are
/// kept; performance notes and the like are dropped.
#[derive(Clone, Default)]
pub struct DebugLog {
    messages: Arc<Mutex<Vec<String>>>,
    pub enabled: bool,
    pub khr_debug: bool,
}

impl DebugLog {
    /// Install the KHR_debug callback on a fresh context (needs `&mut`).
    pub fn install(gl: &mut glow::Context, enabled: bool) -> DebugLog {
        let khr = gl.supported_extensions().contains("GL_KHR_debug");
        let log = DebugLog {
            messages: Arc::default(),
            enabled,
            khr_debug: khr && enabled,
        };
        CHECK_FEEDBACK.with(|c| c.set(enabled));
        if log.khr_debug {
            let sink = log.messages.clone();
            unsafe {
                gl.enable(glow::DEBUG_OUTPUT);
                gl.enable(glow::DEBUG_OUTPUT_SYNCHRONOUS);
                gl.debug_message_callback(move |source, ty, id, severity, msg| {
                    let keep =
                        ty == glow::DEBUG_TYPE_ERROR || severity == glow::DEBUG_SEVERITY_HIGH;
                    if keep {
                        sink.lock().unwrap_or_else(|p| p.into_inner()).push(format!(
                            "GL debug (source {source:#x}, type {ty:#x}, id {id}): {msg}"
                        ));
                    }
                });
            }
        }
        log
    }

    /// Check for errors after `what`: drains glGetError and the KHR_debug
    /// messages, and fails with all of them.
    pub fn check(&self, gl: &glow::Context, what: &str) -> Result<()> {
        if !self.enabled {
            return Ok(());
        }
        let mut errors = Vec::new();
        loop {
            let e = unsafe { gl.get_error() };
            if e == glow::NO_ERROR {
                break;
            }
            errors.push(format!("glGetError: {} ({e:#x})", error_name(e)));
            if errors.len() > 16 {
                break;
            }
        }
        errors.append(&mut self.messages.lock().unwrap_or_else(|p| p.into_inner()));
        FEEDBACK_LOOPS.with(|f| errors.append(&mut f.borrow_mut()));
        if !errors.is_empty() {
            bail!(
                "OpenGL reported errors during {what}:\n  {}",
                errors.join("\n  ")
            );
        }
        Ok(())
    }
}

/// With checks on, before a draw: is any texture bound to a texture unit
/// (on any of its targets: 2D, cube map, array, multisample, 3D, ...) also
/// attached to the framebuffer being drawn into (a face of a cube map, a
/// layer of an array, a multisampled image)? Sampling it there is a
/// feedback loop, undefined in GL 3.3 (§4.4.3) even where a driver forgives
/// it, so it is reported as an error at the next `DebugLog::check`. Only
/// queries state (glGet*), changes none.
pub fn check_feedback_before_draw(gl: &glow::Context) {
    if !CHECK_FEEDBACK.with(Cell::get) {
        return;
    }
    let found = feedback_loops(gl);
    if !found.is_empty() {
        FEEDBACK_LOOPS.with(|f| f.borrow_mut().extend(found));
    }
}

/// The textures both bound for sampling and attached to the current draw
/// framebuffer, described.
pub fn feedback_loops(gl: &glow::Context) -> Vec<String> {
    unsafe {
        let fb = gl.get_parameter_i32(glow::DRAW_FRAMEBUFFER_BINDING);
        if fb == 0 {
            return Vec::new();
        }
        let mut attached = Vec::new();
        let points = (0..8)
            .map(|i| glow::COLOR_ATTACHMENT0 + i)
            .chain([glow::DEPTH_ATTACHMENT, glow::STENCIL_ATTACHMENT]);
        for at in points {
            let ty = gl.get_framebuffer_attachment_parameter_i32(
                glow::DRAW_FRAMEBUFFER,
                at,
                glow::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
            );
            if ty as u32 == glow::TEXTURE {
                let name = gl.get_framebuffer_attachment_parameter_i32(
                    glow::DRAW_FRAMEBUFFER,
                    at,
                    glow::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                );
                attached.push((at, name));
            }
        }
        if attached.is_empty() {
            return Vec::new();
        }
        let active = gl.get_parameter_i32(glow::ACTIVE_TEXTURE);
        let units = gl
            .get_parameter_i32(glow::MAX_COMBINED_TEXTURE_IMAGE_UNITS)
            .min(32);
        let mut found = Vec::new();
        for u in 0..units as u32 {
            gl.active_texture(glow::TEXTURE0 + u);
            for (binding, target) in BINDINGS {
                let bound = gl.get_parameter_i32(binding);
                if bound == 0 {
                    continue;
                }
                for &(at, name) in &attached {
                    if name == bound {
                        found.push(format!(
                            "feedback loop: texture {bound} is bound as {target} to texture unit {u} and attached to the draw framebuffer {fb} at {}",
                            attachment_name(at)
                        ));
                    }
                }
            }
        }
        gl.active_texture(active as u32);
        found
    }
}

/// Every texture target a unit can hold a texture on in GL 3.3 core, as
/// (its binding query, its name). Texture names are shared by all
/// targets, so a match on any of them is the attached texture.
const BINDINGS: [(u32, &str); 9] = [
    (glow::TEXTURE_BINDING_2D, "GL_TEXTURE_2D"),
    (glow::TEXTURE_BINDING_CUBE_MAP, "GL_TEXTURE_CUBE_MAP"),
    (glow::TEXTURE_BINDING_2D_ARRAY, "GL_TEXTURE_2D_ARRAY"),
    (
        glow::TEXTURE_BINDING_2D_MULTISAMPLE,
        "GL_TEXTURE_2D_MULTISAMPLE",
    ),
    (
        glow::TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY,
        "GL_TEXTURE_2D_MULTISAMPLE_ARRAY",
    ),
    (glow::TEXTURE_BINDING_3D, "GL_TEXTURE_3D"),
    (glow::TEXTURE_BINDING_1D, "GL_TEXTURE_1D"),
    (glow::TEXTURE_BINDING_1D_ARRAY, "GL_TEXTURE_1D_ARRAY"),
    (glow::TEXTURE_BINDING_RECTANGLE, "GL_TEXTURE_RECTANGLE"),
];

/// The name of a framebuffer attachment point.
fn attachment_name(at: u32) -> String {
    match at {
        glow::DEPTH_ATTACHMENT => "GL_DEPTH_ATTACHMENT".to_string(),
        glow::STENCIL_ATTACHMENT => "GL_STENCIL_ATTACHMENT".to_string(),
        c => format!("GL_COLOR_ATTACHMENT{}", c - glow::COLOR_ATTACHMENT0),
    }
}

/// The name of a glGetError code.
pub fn error_name(e: u32) -> &'static str {
    match e {
        glow::INVALID_ENUM => "GL_INVALID_ENUM",
        glow::INVALID_VALUE => "GL_INVALID_VALUE",
        glow::INVALID_OPERATION => "GL_INVALID_OPERATION",
        glow::INVALID_FRAMEBUFFER_OPERATION => "GL_INVALID_FRAMEBUFFER_OPERATION",
        glow::OUT_OF_MEMORY => "GL_OUT_OF_MEMORY",
        glow::STACK_OVERFLOW => "GL_STACK_OVERFLOW",
        glow::STACK_UNDERFLOW => "GL_STACK_UNDERFLOW",
        _ => "unknown GL error",
    }
}
