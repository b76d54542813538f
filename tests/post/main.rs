//! The post-processing chain (notes 01 §9; notes 03, Blur Pass and Merge
//! Pass): one module per technique file.

#[path = "../common/mod.rs"]
mod common;

mod bloom;
