//! Notes 01 §9, Post processing; notes 03, Blur Pass and Merge Pass, Gamma
//! Correction Pass. The chain's plumbing (the HDR target, ping-pong or
//! cascaded framebuffers, one step after another) is src/frame/post.rs;
//! each file here is one kind of step.

pub mod bloom;
pub mod bloom_levels;
pub mod blur;
pub mod color_filters;
pub mod fxaa;
pub mod gamma_correction;
pub mod kernel;
pub mod tone_mapping;
