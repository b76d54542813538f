//! Notes 01 §3, "Vertex/Geometry Operation": amplification by the
//! tessellation shaders (§3.1) and generation by the geometry shader
//! (§3.2: particles; flat shading's geometry shader is in
//! lighting/forward.rs); beyond the notes, instancing (LearnOpenGL,
//! Instancing; Geometry Shader: visualizing normals, exploding objects).

pub mod exploding_objects;
pub mod instancing;
pub mod particles;
pub mod tessellation;
pub mod visualizing_normals;
