//! Timer queries (GL_TIME_ELAPSED). On llvmpipe they under-report badly
//! (rasterization is deferred), so `gloss bench` times with the CPU clock
//! around glFinish there and reports these only on real GPUs.

use super::Gl;
use anyhow::{Result, anyhow};
use glow::HasContext;

/// One GL_TIME_ELAPSED query object.
pub struct TimerQuery {
    gl: Gl,
    pub id: glow::Query,
}

impl TimerQuery {
    pub fn new(gl: &Gl) -> Result<TimerQuery> {
        let id = unsafe { gl.create_query() }.map_err(|e| anyhow!("glGenQueries: {e}"))?;
        super::live::made(super::live::Kind::Query);
        Ok(TimerQuery { gl: gl.clone(), id })
    }

    /// glBeginQuery(GL_TIME_ELAPSED, id)
    pub fn begin(&self) {
        unsafe { self.gl.begin_query(glow::TIME_ELAPSED, self.id) }
    }

    /// glEndQuery(GL_TIME_ELAPSED)
    pub fn end(&self) {
        unsafe { self.gl.end_query(glow::TIME_ELAPSED) }
    }

    /// Wait for the result; nanoseconds.
    pub fn result_ns(&self) -> u64 {
        unsafe { self.gl.get_query_parameter_u64(self.id, glow::QUERY_RESULT) }
    }
}

impl Drop for TimerQuery {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_query(self.id);
            super::live::freed(super::live::Kind::Query);
        }
    }
}

/// One GL_TIMESTAMP query (GL 3.3 core): `record` asks for the GPU's clock
/// at the moment every command issued before it has finished.
pub struct Timestamp {
    gl: Gl,
    pub id: glow::Query,
}

impl Timestamp {
    pub fn new(gl: &Gl) -> Result<Timestamp> {
        let id = unsafe { gl.create_query() }.map_err(|e| anyhow!("glGenQueries: {e}"))?;
        super::live::made(super::live::Kind::Query);
        Ok(Timestamp { gl: gl.clone(), id })
    }

    /// glQueryCounter(id, GL_TIMESTAMP)
    pub fn record(&self) {
        unsafe { self.gl.query_counter(self.id, glow::TIMESTAMP) }
    }

    /// Wait for the result; nanoseconds on the GPU's clock.
    pub fn result_ns(&self) -> u64 {
        unsafe { self.gl.get_query_parameter_u64(self.id, glow::QUERY_RESULT) }
    }
}

impl Drop for Timestamp {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_query(self.id);
            super::live::freed(super::live::Kind::Query);
        }
    }
}

/// One GL_SAMPLES_PASSED occlusion query: how many samples passed the
/// depth test between `begin` and `end`. Over a frame, divided by its
/// pixels, the fragments shaded a pixel: the overdraw that drawing front
/// to back (notes 01 §6.2) cuts.
pub struct SamplesQuery {
    gl: Gl,
    pub id: glow::Query,
}

impl SamplesQuery {
    pub fn new(gl: &Gl) -> Result<SamplesQuery> {
        let id = unsafe { gl.create_query() }.map_err(|e| anyhow!("glGenQueries: {e}"))?;
        super::live::made(super::live::Kind::Query);
        Ok(SamplesQuery { gl: gl.clone(), id })
    }

    /// glBeginQuery(GL_SAMPLES_PASSED, id)
    pub fn begin(&self) {
        unsafe { self.gl.begin_query(glow::SAMPLES_PASSED, self.id) }
    }

    /// glEndQuery(GL_SAMPLES_PASSED)
    pub fn end(&self) {
        unsafe { self.gl.end_query(glow::SAMPLES_PASSED) }
    }

    /// Wait for the result: the samples that passed.
    pub fn result(&self) -> u64 {
        unsafe { self.gl.get_query_parameter_u64(self.id, glow::QUERY_RESULT) }
    }
}

impl Drop for SamplesQuery {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_query(self.id);
            super::live::freed(super::live::Kind::Query);
        }
    }
}
