//! Lighting (notes 01 §8, notes 04 "Forward rendering"): forward shading
//! with flat, Gouraud and Phong models; and, beyond the notes, parallax
//! mapping of height-mapped materials (LearnOpenGL, Parallax Mapping).

pub mod forward;
pub mod parallax_mapping;
