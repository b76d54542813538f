//! Blending (notes 01 §4.5 "Blending", §6.1 "Handling Transparent Objects"):
//! transparent objects drawn over the finished opaque image, back to front.

pub mod transparency;
