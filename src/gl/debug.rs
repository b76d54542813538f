//! GL error reporting: KHR_debug output where the driver has it, glGetError otherwise.
//!
//! Tests and `--debug` turn this on; any error it records fails the test or the run.

use anyhow::{Result, bail};
use glow::HasContext;
use std::sync::{Arc, Mutex};

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
        if !errors.is_empty() {
            bail!(
                "OpenGL reported errors during {what}:\n  {}",
                errors.join("\n  ")
            );
        }
        Ok(())
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
