//! The post-processing chain (notes 01 §9 "Post processing"; notes 03
//! "Blur Pass and Merge Pass", "Gamma Correction Pass"; src/frame/post.rs,
//! src/techniques/post/).
//!
//! * every pass against its CPU twin, pixel by pixel, on images uploaded
//!   into the HDR target the chain starts from;
//! * the ping-pong and cascaded forms give the same image;
//! * no step of any chain samples a texture attached to the framebuffer it
//!   draws into (and the check does catch one that does);
//! * the chain's targets exist only when it needs them, bad chains are
//!   errors naming the pass and the key, and the HDR target keeps 256
//!   lights unclipped.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod chain;
mod forms;
