//! Buffer textures (GL 3.1 core, `glTexBuffer`): a buffer object a shader
//! reads with `texelFetch(samplerBuffer, i)`, as long as
//! GL_MAX_TEXTURE_BUFFER_SIZE texels (at least 65536 in GL 3.3; 2^27 on
//! Mesa and the desktop drivers), where a uniform block stops at
//! GL_MAX_UNIFORM_BLOCK_SIZE bytes (at least 16384). Tiled shading keeps its
//! lights and per-tile light lists in these.
//!
//! The owner creates the buffer and the texture that views it, and uploads
//! with glBufferData (a fresh data store each time: the driver need not
//! wait for draws still reading the old one). Binding it for a pass is the
//! pass's own, visible glActiveTexture / glBindTexture(GL_TEXTURE_BUFFER).

use super::Gl;
use super::live::{Kind, freed};
use anyhow::{Result, bail};
use glow::HasContext;

pub struct TextureBuffer {
    gl: Gl,
    buffer: glow::Buffer,
    pub texture: glow::Texture,
    /// The texel format (GL_RGBA32F, GL_R32UI, ...).
    pub format: u32,
    texel_bytes: usize,
}

/// Bytes per texel of the buffer-texture formats gloss uses.
fn texel_bytes(format: u32) -> Result<usize> {
    Ok(match format {
        glow::R32UI | glow::R32F => 4,
        glow::RG32UI | glow::RG32F => 8,
        glow::RGBA32UI | glow::RGBA32F => 16,
        _ => bail!("texture buffer: format {format:#x} is not one gloss uses"),
    })
}

/// GL_MAX_TEXTURE_BUFFER_SIZE: the most texels one buffer texture holds.
pub fn max_texels(gl: &glow::Context) -> usize {
    unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_BUFFER_SIZE).max(0) as usize }
}

impl TextureBuffer {
    /// An empty buffer texture of texels in `format`.
    pub fn new(gl: &Gl, format: u32) -> Result<TextureBuffer> {
        let texel_bytes = texel_bytes(format)?;
        unsafe {
            let buffer = super::live::new_buffer(gl)?;
            let texture = match super::live::new_texture(gl) {
                Ok(t) => t,
                Err(e) => {
                    gl.delete_buffer(buffer);
                    freed(Kind::Buffer);
                    return Err(e);
                }
            };
            gl.bind_buffer(glow::TEXTURE_BUFFER, Some(buffer));
            gl.buffer_data_size(glow::TEXTURE_BUFFER, texel_bytes as i32, glow::STREAM_DRAW);
            gl.bind_buffer(glow::TEXTURE_BUFFER, None);
            gl.bind_texture(glow::TEXTURE_BUFFER, Some(texture));
            gl.tex_buffer(glow::TEXTURE_BUFFER, format, Some(buffer));
            gl.bind_texture(glow::TEXTURE_BUFFER, None);
            Ok(TextureBuffer {
                gl: gl.clone(),
                buffer,
                texture,
                format,
                texel_bytes,
            })
        }
    }

    /// Replace the contents with `bytes` (whole texels; an empty upload
    /// keeps one texel, since a zero-sized store is not allowed everywhere).
    pub fn write(&self, bytes: &[u8]) {
        assert!(
            bytes.len().is_multiple_of(self.texel_bytes),
            "texture buffer write of part of a texel"
        );
        let zero = vec![0u8; self.texel_bytes];
        let bytes = if bytes.is_empty() { &zero[..] } else { bytes };
        unsafe {
            self.gl.bind_buffer(glow::TEXTURE_BUFFER, Some(self.buffer));
            self.gl
                .buffer_data_u8_slice(glow::TEXTURE_BUFFER, bytes, glow::STREAM_DRAW);
            self.gl.bind_buffer(glow::TEXTURE_BUFFER, None);
        }
    }
}

impl Drop for TextureBuffer {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_texture(self.texture);
            freed(Kind::Texture);
            self.gl.delete_buffer(self.buffer);
            freed(Kind::Buffer);
        }
    }
}
