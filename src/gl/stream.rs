//! A vertex buffer without indices, written whole: every frame (the
//! particles) or once (the tessellated terrain's patch corners). Notes 01
//! §1.3: a buffer written through a mapped pointer, beside
//! glBufferSubData. A VAO over one VBO, its attributes given as (location,
//! floats, byte offset) with one stride, drawn with glDrawArrays in any
//! mode (GL_POINTS, GL_TRIANGLES, GL_PATCHES: the pass that draws patches
//! sets GL_PATCH_VERTICES itself). Each write replaces the whole contents,
//! in one of two ways:
//!
//! - `write_mapped`: glMapBufferRange with GL_MAP_WRITE_BIT |
//!   GL_MAP_INVALIDATE_BUFFER_BIT (the old contents may be dropped, so the
//!   driver need not wait for draws still reading them), a copy, unmap;
//! - `write_subdata`: glBufferData with no data (orphaning: the same effect,
//!   asked for the old way), then glBufferSubData.
//!
//! The buffer grows (doubling) when a frame needs more than it holds.
//! `write` picks the way and says which one ran (`Upload`): a refused map
//! falls back to glBufferSubData, and the caller reports it; each thread
//! counts the writes `write` made of each kind (`uploads_on_this_thread`),
//! so a test can tell that a frame really mapped.

use super::Gl;
use anyhow::Result;
use glow::HasContext;
use std::cell::Cell;

/// How one write reached the buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Upload {
    /// Through glMapBufferRange's pointer.
    Mapped,
    /// With glBufferSubData, as asked.
    SubData,
    /// glMapBufferRange gave no pointer: written with glBufferSubData.
    MapRefused,
}

/// The writes this thread made, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UploadCounts {
    pub mapped: u64,
    pub subdata: u64,
    pub map_refused: u64,
}

thread_local! {
    static UPLOADS: Cell<UploadCounts> = Cell::new(UploadCounts::default());
}

/// The writes made by stream buffers on this thread so far.
pub fn uploads_on_this_thread() -> UploadCounts {
    UPLOADS.with(Cell::get)
}

pub struct StreamBuffer {
    gl: Gl,
    vao: glow::VertexArray,
    vbo: glow::Buffer,
    capacity: Cell<usize>,
}

impl StreamBuffer {
    pub fn new(gl: &Gl, attributes: &[(u32, i32, i32)], stride: i32) -> Result<StreamBuffer> {
        unsafe {
            let vao = super::live::new_vertex_array(gl)?;
            let vbo = super::live::new_buffer(gl)?;
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            gl.buffer_data_size(glow::ARRAY_BUFFER, 4096, glow::STREAM_DRAW);
            for &(loc, n, offset) in attributes {
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, n, glow::FLOAT, false, stride, offset);
            }
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            Ok(StreamBuffer {
                gl: gl.clone(),
                vao,
                vbo,
                capacity: Cell::new(4096),
            })
        }
    }

    /// Make room for `bytes` (contents dropped).
    fn reserve(&self, bytes: usize) {
        let mut cap = self.capacity.get();
        if bytes > cap {
            while cap < bytes {
                cap *= 2;
            }
            unsafe {
                self.gl
                    .buffer_data_size(glow::ARRAY_BUFFER, cap as i32, glow::STREAM_DRAW);
            }
            self.capacity.set(cap);
        }
    }

    /// Replace the contents through a mapped pointer. False if the GL
    /// refused to map (nothing written).
    pub fn write_mapped(&self, bytes: &[u8]) -> bool {
        if bytes.is_empty() {
            return true;
        }
        unsafe {
            self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            self.reserve(bytes.len());
            let ptr = self.gl.map_buffer_range(
                glow::ARRAY_BUFFER,
                0,
                bytes.len() as i32,
                glow::MAP_WRITE_BIT | glow::MAP_INVALIDATE_BUFFER_BIT,
            );
            let ok = !ptr.is_null();
            if ok {
                std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr, bytes.len());
                self.gl.unmap_buffer(glow::ARRAY_BUFFER);
            }
            self.gl.bind_buffer(glow::ARRAY_BUFFER, None);
            ok
        }
    }

    /// Replace the contents: through a mapped pointer if `map` (falling back
    /// to glBufferSubData if the GL refuses to map), else with
    /// glBufferSubData. Returns the way it went.
    pub fn write(&self, bytes: &[u8], map: bool) -> Upload {
        let how = if !map {
            self.write_subdata(bytes);
            Upload::SubData
        } else if self.write_mapped(bytes) {
            Upload::Mapped
        } else {
            self.write_subdata(bytes);
            Upload::MapRefused
        };
        UPLOADS.with(|u| {
            let mut c = u.get();
            match how {
                Upload::Mapped => c.mapped += 1,
                Upload::SubData => c.subdata += 1,
                Upload::MapRefused => c.map_refused += 1,
            }
            u.set(c);
        });
        how
    }

    /// The buffer's first `len` bytes, read back with glGetBufferSubData.
    pub fn read_back(&self, len: usize) -> Vec<u8> {
        let mut out = vec![0u8; len.min(self.capacity.get())];
        unsafe {
            self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            self.gl.get_buffer_sub_data(glow::ARRAY_BUFFER, 0, &mut out);
            self.gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
        out
    }

    /// Replace the contents with glBufferData (orphaning) and glBufferSubData.
    pub fn write_subdata(&self, bytes: &[u8]) {
        unsafe {
            self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            let cap = self.capacity.get().max(bytes.len());
            self.gl
                .buffer_data_size(glow::ARRAY_BUFFER, cap as i32, glow::STREAM_DRAW);
            self.capacity.set(cap);
            self.gl
                .buffer_sub_data_u8_slice(glow::ARRAY_BUFFER, 0, bytes);
            self.gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
    }

    /// glBindVertexArray + glDrawArrays(mode, 0, count).
    pub fn draw(&self, mode: u32, count: i32) {
        super::debug::check_feedback_before_draw(&self.gl);
        unsafe {
            self.gl.bind_vertex_array(Some(self.vao));
            self.gl.draw_arrays(mode, 0, count);
            self.gl.bind_vertex_array(None);
        }
    }
}

impl Drop for StreamBuffer {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_vertex_array(self.vao);
            super::live::freed(super::live::Kind::VertexArray);
            self.gl.delete_buffer(self.vbo);
            super::live::freed(super::live::Kind::Buffer);
        }
    }
}
