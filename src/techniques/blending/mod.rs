//! Blending (notes 01 §4.5 "Blending", §6.1 "Handling Transparent Objects"):
//! transparent objects drawn over the finished opaque image, back to front;
//! or, beyond the notes, in any order (weighted blended OIT) or peeled layer
//! by layer (depth peeling), as `render.transparency` chooses.

pub mod depth_peeling;
pub mod transparency;
mod transparent_draws;
pub mod weighted_blended;
