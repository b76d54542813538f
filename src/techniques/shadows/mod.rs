//! Notes 01 §8.5, Shadow mapping; notes 02, Rendering Cast Shadows.

pub mod cascaded_shadow_maps;
mod casters;
pub mod depth_pass;
pub mod shadow_map;
