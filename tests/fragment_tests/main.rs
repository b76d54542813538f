//! Fragment tests (notes 01 §4.4 "Depth Buffer / Depth Test"; notes 05,
//! "Fragment Tests" and "Depth Test and Operation"):
//!
//! * every depth function of notes 05 (never, less, equal, lequal, greater,
//!   notequal, gequal, always) per material, in forward and deferred, gives
//!   the image the CPU test predicts, and the state returns to GL_LESS;
//! * z-fighting (scenes/z-fighting.toml): with near = 0.01 a measurable
//!   fraction of the far quads' pixels shows the quad behind, with near = 1.0
//!   none; the depth-precision formula of src/math/depth.rs predicts both.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod depth_func;
mod depth_precision;
mod interpolation;
mod viewports;
