//! Notes 05: multi-pass techniques with the stencil buffer.

pub mod mirror;
mod mirror_order;
pub mod object_outlines;
