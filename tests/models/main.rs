//! Real models (docs/model_loading.md): OBJ files with their MTL materials,
//! JPEG / TGA / BMP textures, alpha-tested shadows, concave faces.
//!
//! * `mtl.rs`: an MTL colour and a map_Kd texel at the predicted pixels; a
//!   map_Ks darkens the highlight where it is black; a missing texture is a
//!   warning naming the material and the path; `material = ...` overrides.
//! * `alpha_shadows.rs`: an alpha cutoff splits a gradient quad at the
//!   predicted column, in the image and in its shadow, for a directional,
//!   a spot and a point light (six passes and the geometry shader).
//! * `concave.rs`: a C-shaped and a ring-shaped face keep their notch and hole.
//! * `images.rs`: JPEG, TGA and BMP files gloss writes decode to the texels
//!   written (JPEG within its tolerance), under the same limits as PNG.
//! * `scenes.rs`: the shipped model scenes agree on every render path.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod alpha_shadows;
mod concave;
mod images;
mod mtl;
mod scenes;

use std::path::{Path, PathBuf};

/// A fresh, empty directory for one test.
pub fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gloss-models-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("make the test folder");
    d
}

/// Write `text` to `dir/name`; returns the path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    if let Some(parent) = p.parent() {
        std::fs::create_dir_all(parent).unwrap();
    }
    std::fs::write(&p, text).unwrap();
    p
}

/// sRGB-encoded 8-bit value to linear (the GPU's decode of an sRGB texture).
pub fn srgb_to_linear(c: u8) -> f32 {
    let c = c as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The linear RGB at pixel (x, y), y counted from the top.
pub fn linear_at(r: &common::Rendered, x: u32, y: u32) -> [f32; 3] {
    let row = r.height - 1 - y;
    let i = 4 * (row * r.width + x) as usize;
    [r.linear[i], r.linear[i + 1], r.linear[i + 2]]
}
