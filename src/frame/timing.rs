//! Pass timing. Always the CPU clock around glFinish: on llvmpipe,
//! GL_TIME_ELAPSED and GL_TIMESTAMP under-report (rasterisation is
//! deferred), so that is the clock there. Where the driver's timer queries
//! are trustworthy (a GPU), also a GL_TIMESTAMP before the frame and after
//! each pass, read when the frame ends.

use crate::gl::Gl;
use crate::gl::query::Timestamp;
use glow::HasContext;
use std::time::Instant;

/// The time of each pass, measured around glFinish (and on the GPU's clock
/// where `gpu` is not empty). Only when `Renderer::timing` is on.
#[derive(Clone, Debug, Default)]
pub struct PassTimes {
    /// Each pass's technique name ("shadow map") and time (ms), in frame order.
    pub passes: Vec<(&'static str, f64)>,
    /// Each pass named by what it draws, as `gloss plan` names it
    /// (`FramePlan::title`: "shadow map (light 1, face +X)"), one per entry
    /// of `passes`.
    pub titles: Vec<String>,
    /// Per pass, from GL_TIMESTAMP queries (ms); empty where not measured.
    pub gpu: Vec<f64>,
    pub frame_ms: f64,
    /// What frustum culling kept of the camera's opaque objects (None: off).
    pub culling: Option<crate::frame::culling::CullStats>,
    /// The same for the shadow passes' casters, summed over the shadow
    /// maps' faces (None: off, or no shadow map).
    pub shadow_culling: Option<crate::frame::culling::CullStats>,
}

impl PassTimes {
    /// The CPU-clock time of the passes named `name`, added up (ms).
    pub fn pass_ms(&self, name: &str) -> f64 {
        (self.passes.iter())
            .filter(|(n, _)| *n == name)
            .map(|(_, ms)| ms)
            .sum()
    }

    /// Each pass's time under its title (`titles`), in frame order.
    pub fn titled(&self) -> impl Iterator<Item = (&str, f64)> {
        (self.titles.iter().zip(&self.passes)).map(|(t, (_, ms))| (t.as_str(), *ms))
    }

    /// Each pass's time under its technique's name for it, in frame order.
    pub fn named(&self) -> impl Iterator<Item = (&str, f64)> {
        self.passes.iter().map(|&(n, ms)| (n, ms))
    }
}

/// Does this renderer's timer-query clock tell the truth? Not on Mesa's
/// software rasterisers.
pub fn timer_queries_trustworthy(renderer: &str) -> bool {
    let r = renderer.to_lowercase();
    !["llvmpipe", "softpipe", "lavapipe", "swrast"]
        .iter()
        .any(|s| r.contains(s))
}

/// Splits a frame into passes for timing: glFinish, then the CPU clock;
/// with `gpu`, a GL_TIMESTAMP after each pass too.
pub struct PassTimer<'a> {
    gl: &'a Gl,
    on: bool,
    start: Instant,
    last: Instant,
    stamps: Vec<Timestamp>,
    times: PassTimes,
}

impl<'a> PassTimer<'a> {
    pub fn new(gl: &'a Gl, on: bool, gpu: bool) -> PassTimer<'a> {
        let mut stamps = Vec::new();
        if on {
            unsafe { gl.finish() };
            if gpu && let Ok(t) = Timestamp::new(gl) {
                t.record();
                stamps.push(t);
            }
        }
        let now = Instant::now();
        PassTimer {
            gl,
            on,
            start: now,
            last: now,
            stamps,
            times: PassTimes::default(),
        }
    }

    /// The pass `name` (titled `title`) has been issued: note its GPU time
    /// stamp, wait for it and note its CPU time.
    pub fn mark(&mut self, name: &'static str, title: String) {
        if !self.on {
            return;
        }
        if !self.stamps.is_empty()
            && let Ok(t) = Timestamp::new(self.gl)
        {
            t.record();
            self.stamps.push(t);
        }
        unsafe { self.gl.finish() };
        let now = Instant::now();
        self.times
            .passes
            .push((name, (now - self.last).as_secs_f64() * 1000.0));
        self.times.titles.push(title);
        self.last = now;
    }

    pub fn finish(mut self) -> PassTimes {
        if self.on {
            unsafe { self.gl.finish() };
            self.times.frame_ms = self.start.elapsed().as_secs_f64() * 1000.0;
            if self.stamps.len() == self.times.passes.len() + 1 {
                let ns: Vec<u64> = self.stamps.iter().map(Timestamp::result_ns).collect();
                self.times.gpu = ns
                    .windows(2)
                    .map(|w| w[1].saturating_sub(w[0]) as f64 / 1e6)
                    .collect();
            }
        }
        self.times
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn software_rasterisers_timer_queries_are_not_trusted() {
        assert!(!timer_queries_trustworthy(
            "llvmpipe (LLVM 15.0.6, 256 bits)"
        ));
        assert!(!timer_queries_trustworthy("softpipe"));
        assert!(timer_queries_trustworthy("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
        assert!(timer_queries_trustworthy(
            "AMD Radeon RX 7900 XTX (radeonsi, navi31)"
        ));
    }
}
