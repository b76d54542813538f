//! Buffer objects: a uniform buffer for the std140 light array.

use super::Gl;
use anyhow::Result;
use glow::HasContext;

/// One buffer object (GL_UNIFORM_BUFFER here; the mesh owns its own VBO/EBO).
pub struct Buffer {
    gl: Gl,
    pub id: glow::Buffer,
    pub target: u32,
    pub size: usize,
}

impl Buffer {
    /// Create a buffer of `size` bytes for `target`, contents undefined.
    pub fn new(gl: &Gl, target: u32, size: usize, usage: u32) -> Result<Buffer> {
        unsafe {
            let id = super::live::new_buffer(gl)?;
            gl.bind_buffer(target, Some(id));
            gl.buffer_data_size(target, size as i32, usage);
            gl.bind_buffer(target, None);
            Ok(Buffer {
                gl: gl.clone(),
                id,
                target,
                size,
            })
        }
    }

    /// Upload `bytes` at offset 0 (glBufferSubData).
    pub fn write(&self, bytes: &[u8]) {
        assert!(bytes.len() <= self.size, "buffer write past its end");
        unsafe {
            self.gl.bind_buffer(self.target, Some(self.id));
            self.gl.buffer_sub_data_u8_slice(self.target, 0, bytes);
            self.gl.bind_buffer(self.target, None);
        }
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_buffer(self.id);
            super::live::freed(super::live::Kind::Buffer);
        }
    }
}
