//! Notes 01 §7, "Animation": keyframes on the scene graph live in the
//! scene (src/scene/animation.rs, no GL); §7.1's skinned meshes are skinned
//! on the GPU here.

pub mod skinned_meshes;
