//! Billboards and the alpha test (notes 05, "Alpha Test", "Billboards",
//! "Alpha Test and Billboards"):
//!
//! * `billboards.rs`: the notes' "big problem" is in the unsorted blend
//!   image and not in the alpha-test one (bounds stated there); sorted
//!   blending does not depend on the scene's order; the deferred paths draw
//!   the same billboards as forward; `gloss plan`; GL state restored.
//! * `facing.rs`: a spherical billboard is an axis-aligned screen rectangle
//!   of the predicted size; a cylindrical one stays upright; the sort order.
//! * `alpha_test.rs`: every op of the GLSL alpha test against its CPU twin,
//!   just below, at and above the reference; a material's alpha test in the
//!   forward and deferred paths.
//! * `scene.rs`: scene-file errors name the key.
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod alpha_test;
mod billboards;
mod facing;
mod scene;

use std::path::{Path, PathBuf};

/// A fresh, empty directory for one test.
pub fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gloss-billboards-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create temp dir");
    d
}

/// Write an opaque (alpha 255) solid white `w` x `h` PNG sprite.
pub fn solid_sprite(dir: &Path, name: &str, w: u32, h: u32) -> PathBuf {
    let p = dir.join(name);
    image::RgbaImage::from_pixel(w, h, image::Rgba([255, 255, 255, 255]))
        .save(&p)
        .expect("write sprite");
    p
}

/// Pixels of `img` brighter than half in any channel.
pub fn lit_pixels(img: &image::RgbaImage) -> Vec<(u32, u32)> {
    img.enumerate_pixels()
        .filter(|(_, _, p)| p.0[..3].iter().any(|&c| c > 128))
        .map(|(x, y, _)| (x, y))
        .collect()
}

/// The bounding box [x0, x1] x [y0, y1] of `pixels` (inclusive).
pub fn bounds(pixels: &[(u32, u32)]) -> (u32, u32, u32, u32) {
    let x0 = pixels.iter().map(|p| p.0).min().expect("some pixels");
    let x1 = pixels.iter().map(|p| p.0).max().unwrap();
    let y0 = pixels.iter().map(|p| p.1).min().unwrap();
    let y1 = pixels.iter().map(|p| p.1).max().unwrap();
    (x0, x1, y0, y1)
}
