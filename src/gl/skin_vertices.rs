//! A skinned mesh's bind-pose vertices on the GPU, for the skinning pass
//! (notes 01 §7.1: "vertices require additional attributes, e.g. ...
//! weightings, joint indices"). One VAO over one VBO, 56 bytes a vertex:
//!
//! | location | attribute | type |
//! |---|---|---|
//! | 0 | position | 3 floats |
//! | 1 | normal | 3 floats |
//! | 2 | uv | 2 floats |
//! | 3 | joints | 4 unsigned shorts, read as integers (glVertexAttribIPointer) |
//! | 4 | weights | 4 floats |
//!
//! No indices: the skinning pass draws it as GL_POINTS, one per vertex, and
//! captures the skinned vertices with transform feedback into the mesh the
//! other passes draw (`gl::mesh`), in the same order.

use super::Gl;
use crate::geometry::skin::SkinnedMesh;
use anyhow::{Result, bail};
use glow::HasContext;

pub struct SkinVertices {
    gl: Gl,
    pub vao: glow::VertexArray,
    vbo: glow::Buffer,
    pub count: i32,
}

const STRIDE: i32 = 56;

impl SkinVertices {
    pub fn upload(gl: &Gl, skin: &SkinnedMesh) -> Result<SkinVertices> {
        if skin.mesh.vertices.is_empty() {
            bail!("skinned mesh has no vertices");
        }
        let mut bytes = Vec::with_capacity(skin.mesh.vertices.len() * STRIDE as usize);
        for (i, v) in skin.mesh.vertices.iter().enumerate() {
            let floats = v.position.iter().chain(&v.normal).chain(&v.uv);
            bytes.extend(floats.flat_map(|f| f.to_le_bytes()));
            bytes.extend(skin.joints[i].iter().flat_map(|j| j.to_le_bytes()));
            bytes.extend(skin.weights[i].iter().flat_map(|w| w.to_le_bytes()));
        }
        unsafe {
            let vao = super::live::new_vertex_array(gl)?;
            let vbo = super::live::new_buffer(gl)?;
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
            for (loc, n, off) in [(0u32, 3, 0), (1, 3, 12), (2, 2, 24), (4, 4, 40)] {
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, n, glow::FLOAT, false, STRIDE, off);
            }
            gl.enable_vertex_attrib_array(3);
            gl.vertex_attrib_pointer_i32(3, 4, glow::UNSIGNED_SHORT, STRIDE, 32);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            Ok(SkinVertices {
                gl: gl.clone(),
                vao,
                vbo,
                count: skin.mesh.vertices.len() as i32,
            })
        }
    }
}

impl Drop for SkinVertices {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_vertex_array(self.vao);
            super::live::freed(super::live::Kind::VertexArray);
            self.gl.delete_buffer(self.vbo);
            super::live::freed(super::live::Kind::Buffer);
        }
    }
}
