//! Patches for the tessellator (notes 01 §3.1, GL 4.0): a VAO with one VBO
//! of patch corners (position at location 0), drawn with GL_PATCHES. The
//! pass that draws them sets GL_PATCH_VERTICES itself (glPatchParameteri):
//! this owner hides no state change.

use super::Gl;
use anyhow::{Result, anyhow, bail};
use glow::HasContext;

pub struct Patches {
    gl: Gl,
    vao: glow::VertexArray,
    vbo: glow::Buffer,
    /// Corners in all.
    pub count: i32,
}

impl Patches {
    /// Upload `corners` (x, y, z each), `per_patch` to a patch.
    pub fn upload(gl: &Gl, corners: &[[f32; 3]], per_patch: usize) -> Result<Patches> {
        if corners.is_empty() || per_patch == 0 || !corners.len().is_multiple_of(per_patch) {
            bail!(
                "{} patch corners do not make patches of {per_patch}",
                corners.len()
            );
        }
        let bytes: Vec<u8> = (corners.iter().flatten())
            .flat_map(|f| f.to_ne_bytes())
            .collect();
        unsafe {
            let vao = gl
                .create_vertex_array()
                .map_err(|e| anyhow!("glGenVertexArrays: {e}"))?;
            super::live::made(super::live::Kind::VertexArray);
            let vbo = gl
                .create_buffer()
                .map_err(|e| anyhow!("glGenBuffers: {e}"))?;
            super::live::made(super::live::Kind::Buffer);
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, 12, 0);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            Ok(Patches {
                gl: gl.clone(),
                vao,
                vbo,
                count: corners.len() as i32,
            })
        }
    }

    /// glBindVertexArray + glDrawArrays(GL_PATCHES, ...).
    pub fn draw(&self) {
        super::debug::check_feedback_before_draw(&self.gl);
        unsafe {
            self.gl.bind_vertex_array(Some(self.vao));
            self.gl.draw_arrays(glow::PATCHES, 0, self.count);
            self.gl.bind_vertex_array(None);
        }
    }
}

impl Drop for Patches {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_vertex_array(self.vao);
            super::live::freed(super::live::Kind::VertexArray);
            self.gl.delete_buffer(self.vbo);
            super::live::freed(super::live::Kind::Buffer);
        }
    }
}
