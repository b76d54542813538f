//! Pass timing: glFinish, then the CPU clock. On llvmpipe GL_TIME_ELAPSED
//! under-reports (rasterisation is deferred), so the renderer times passes
//! this way; `gloss bench` adds GL_TIME_ELAPSED on real GPUs.

use glow::HasContext;
use std::time::Instant;

/// Wall-clock time of each pass, measured around glFinish. Only when
/// `Renderer::timing` is on.
#[derive(Clone, Debug, Default)]
pub struct PassTimes {
    pub passes: Vec<(&'static str, f64)>,
    pub frame_ms: f64,
}

/// Splits a frame into passes for timing: glFinish, then the CPU clock.
pub struct PassTimer<'a> {
    gl: &'a glow::Context,
    on: bool,
    start: Instant,
    last: Instant,
    times: PassTimes,
}

impl<'a> PassTimer<'a> {
    pub fn new(gl: &'a glow::Context, on: bool) -> PassTimer<'a> {
        if on {
            unsafe { gl.finish() };
        }
        let now = Instant::now();
        PassTimer {
            gl,
            on,
            start: now,
            last: now,
            times: PassTimes::default(),
        }
    }

    /// The pass `name` has been issued: wait for it and note its time.
    pub fn mark(&mut self, name: &'static str) {
        if !self.on {
            return;
        }
        unsafe { self.gl.finish() };
        let now = Instant::now();
        self.times
            .passes
            .push((name, (now - self.last).as_secs_f64() * 1000.0));
        self.last = now;
    }

    pub fn finish(mut self) -> PassTimes {
        if self.on {
            unsafe { self.gl.finish() };
            self.times.frame_ms = self.start.elapsed().as_secs_f64() * 1000.0;
        }
        self.times
    }
}
