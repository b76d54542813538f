//! Lighting (notes 01 §8, notes 04 "Forward rendering"): forward shading
//! with flat, Gouraud and Phong models.

pub mod forward;
