//! Lighting (notes 01 §8, notes 04 "Forward rendering"): forward shading
//! with flat, Gouraud and Phong models; and, beyond the notes, parallax
//! mapping of height-mapped materials (LearnOpenGL, Parallax Mapping) and
//! area lights with linearly transformed cosines (Heitz et al. 2016).

pub mod forward;
pub mod ltc_area_lights;
pub mod parallax_mapping;
