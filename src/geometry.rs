//! CPU-side meshes: the interleaved vertex layout, procedural shapes, OBJ loading
//! and tangent generation. `gl::mesh` uploads a `MeshData` into a VAO.

/// One interleaved vertex: position, normal, uv, tangent (xyz + handedness w).
/// 48 bytes; attribute locations 0..3 in every shader.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
    pub tangent: [f32; 4],
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}
