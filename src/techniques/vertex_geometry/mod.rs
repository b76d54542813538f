//! Notes 01 §3, "Vertex/Geometry Operation": amplification by the
//! tessellation shaders (§3.1). gloss's geometry shader is flat shading's
//! (lighting/forward.rs).

pub mod tessellation;
