//! Shadow mapping (notes 01 §8.5, notes 02 "Rendering Cast Shadows";
//! src/techniques/shadows/shadow_map.rs, glsl/common/shadow.glsl).
//!
//! * every lighting path gives the forward image of every shadow scene, and
//!   a point light's six passes give the geometry shader's one pass;
//! * `gloss plan` has one shadow pass per casting light, with its map size,
//!   and none when no light casts; the passes restore the GL state;
//! * the shadows match an exact CPU reference (a ray from each pixel's
//!   surface point to the light), on the shipped scenes and the hard cases.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod cascade_colors;
mod cascaded_shadow_maps;
mod culling;
mod depth_only;
mod face_passes;
mod hard_cases;
mod paths;
mod pcf;
mod reference;
