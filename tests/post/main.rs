//! The post-processing chapter (notes 01 §9) and anti-aliasing the final
//! image (notes 01 §8.6): one module per technique file.

#[path = "../common/mod.rs"]
mod common;

mod aa;
