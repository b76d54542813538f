//! Meshes on the GPU: a VAO with one interleaved VBO (position, normal, uv
//! at locations 0-2, 32 bytes a vertex), a second VBO of tangents
//! (location 3, xyz and the handedness w: bump mapping, notes 01 §8.4), a
//! third of vertex colours (location 4, RGB, white where the mesh has none:
//! notes 01 §4.1) and an EBO of u32 indices. The tangents have a buffer of their own so that
//! the skinning pass's transform feedback writes the 32-byte vertices it
//! always wrote (a skinned mesh keeps its bind pose's tangents).

use super::Gl;
use crate::geometry::{MeshData, Vertex};
use anyhow::{Result, bail};
use glow::HasContext;

pub struct Mesh {
    gl: Gl,
    pub vao: glow::VertexArray,
    vbo: glow::Buffer,
    tangents: glow::Buffer,
    colors: glow::Buffer,
    ebo: glow::Buffer,
    pub index_count: i32,
    /// How many vertices the VBO holds.
    pub vertex_count: i32,
}

/// A vertex as the GPU holds it: position, normal, uv (8 floats).
fn packed(data: &MeshData) -> Vec<[f32; 8]> {
    (data.vertices.iter())
        .map(|v: &Vertex| {
            let (p, n, t) = (v.position, v.normal, v.uv);
            [p[0], p[1], p[2], n[0], n[1], n[2], t[0], t[1]]
        })
        .collect()
}

impl Mesh {
    /// A mesh whose vertices never change (GL_STATIC_DRAW).
    pub fn upload(gl: &Gl, data: &MeshData) -> Result<Mesh> {
        Mesh::upload_as(gl, data, glow::STATIC_DRAW)
    }

    /// A mesh whose vertices are written again every frame: a skinned
    /// mesh, by transform feedback (GL_DYNAMIC_COPY: the GPU writes them,
    /// the GPU reads them) or by `write_vertices`.
    pub fn upload_dynamic(gl: &Gl, data: &MeshData) -> Result<Mesh> {
        Mesh::upload_as(gl, data, glow::DYNAMIC_COPY)
    }

    /// The VBO (transform feedback writes a skinned mesh's vertices into it).
    pub fn vertex_buffer(&self) -> glow::Buffer {
        self.vbo
    }

    /// glBufferSubData the vertices again (same count, same indices).
    pub fn write_vertices(&self, data: &MeshData) {
        let packed = packed(data);
        let n = packed.len().min(self.vertex_count as usize);
        unsafe {
            self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            self.gl
                .buffer_sub_data_u8_slice(glow::ARRAY_BUFFER, 0, as_bytes(&packed[..n]));
            self.gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
    }

    /// The vertices as the VBO holds them now (glGetBufferSubData), each
    /// position, normal, uv: what transform feedback wrote into a skinned
    /// mesh (the tests and `gloss bench --skinning` compare it with the CPU's).
    pub fn read_vertices(&self) -> Vec<[f32; 8]> {
        let mut bytes = vec![0u8; self.vertex_count as usize * 32];
        unsafe {
            self.gl.bind_buffer(glow::ARRAY_BUFFER, Some(self.vbo));
            self.gl
                .get_buffer_sub_data(glow::ARRAY_BUFFER, 0, &mut bytes);
            self.gl.bind_buffer(glow::ARRAY_BUFFER, None);
        }
        (bytes.chunks_exact(32))
            .map(|v| {
                std::array::from_fn(|k| f32::from_le_bytes(v[4 * k..4 * k + 4].try_into().unwrap()))
            })
            .collect()
    }

    fn upload_as(gl: &Gl, data: &MeshData, usage: u32) -> Result<Mesh> {
        if data.indices.is_empty() {
            bail!("mesh has no triangles");
        }
        let packed = packed(data);
        let stride = std::mem::size_of::<[f32; 8]>() as i32;
        unsafe {
            let vao = super::live::new_vertex_array(gl)?;
            let vbo = super::live::new_buffer(gl)?;
            let tangents = super::live::new_buffer(gl)?;
            let colors = super::live::new_buffer(gl)?;
            let ebo = super::live::new_buffer(gl)?;
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, as_bytes(&packed), usage);
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ebo));
            gl.buffer_data_u8_slice(
                glow::ELEMENT_ARRAY_BUFFER,
                as_bytes(&data.indices),
                glow::STATIC_DRAW,
            );
            // location, components, byte offset
            for (loc, n, off) in [(0u32, 3, 0), (1, 3, 12), (2, 2, 24)] {
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, n, glow::FLOAT, false, stride, off);
            }
            let t: Vec<[f32; 4]> = data.vertices.iter().map(|v| v.tangent).collect();
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(tangents));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, as_bytes(&t), glow::STATIC_DRAW);
            gl.enable_vertex_attrib_array(3);
            gl.vertex_attrib_pointer_f32(3, 4, glow::FLOAT, false, 16, 0);
            let mut c = data.colors.clone();
            c.resize(data.vertices.len(), [1.0; 3]);
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(colors));
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, as_bytes(&c), glow::STATIC_DRAW);
            gl.enable_vertex_attrib_array(4);
            gl.vertex_attrib_pointer_f32(4, 3, glow::FLOAT, false, 12, 0);
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, None);
            Ok(Mesh {
                gl: gl.clone(),
                vao,
                vbo,
                tangents,
                colors,
                ebo,
                index_count: data.indices.len() as i32,
                vertex_count: packed.len() as i32,
            })
        }
    }

    /// glBindVertexArray + glDrawElements(GL_TRIANGLES, ...). With GL
    /// checks on, first looks for a feedback loop (gl/debug.rs).
    pub fn draw(&self) {
        super::debug::check_feedback_before_draw(&self.gl);
        unsafe {
            self.gl.bind_vertex_array(Some(self.vao));
            self.gl
                .draw_elements(glow::TRIANGLES, self.index_count, glow::UNSIGNED_INT, 0);
            self.gl.bind_vertex_array(None);
        }
    }
}

fn as_bytes<T: Copy>(v: &[T]) -> &[u8] {
    // Vertex is repr(C) floats and u32 indices: plain old data with no padding.
    unsafe { std::slice::from_raw_parts(v.as_ptr() as *const u8, std::mem::size_of_val(v)) }
}

impl Drop for Mesh {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_vertex_array(self.vao);
            super::live::freed(super::live::Kind::VertexArray);
            self.gl.delete_buffer(self.vbo);
            super::live::freed(super::live::Kind::Buffer);
            self.gl.delete_buffer(self.tangents);
            super::live::freed(super::live::Kind::Buffer);
            self.gl.delete_buffer(self.colors);
            super::live::freed(super::live::Kind::Buffer);
            self.gl.delete_buffer(self.ebo);
            super::live::freed(super::live::Kind::Buffer);
        }
    }
}
