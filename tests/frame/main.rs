//! The frame (src/frame/): the plan, and what every pass must do: restore
//! the GL state it changed, raise no GL error, and never sample a texture
//! attached to the framebuffer it draws into.

#[path = "../common/mod.rs"]
mod common;

mod animation;
mod clip_planes;
mod culling;
mod exploding_objects;
mod face_culling;
mod feedback;
mod instancing;
mod particles;
mod passes;
mod plan;
mod skinning;
mod tessellation;
mod timing;
mod unit_check;
mod visualizing_normals;
