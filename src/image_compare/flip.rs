//! FLIP, the perceptual difference of two images (Andersson et al., "FLIP: A
//! Difference Evaluator for Alternating Images", HPG 2020), beside RMSE and
//! max: a per-pixel error in `0..1` that weighs colour differences as a
//! viewer sees them (after the eye's contrast sensitivity blurs them) and
//! adds edges and points that appear or vanish.
//!
//! gloss calls NVlabs' reference implementation through the `nv-flip` crate
//! (the C++ compiled by the `cc` crate), the one wgpu's and rend3's image
//! tests use, rather than a port of its own. Images are compared as 8-bit
//! sRGB RGB (alpha ignored) at the default 67 pixels per degree (a 0.7 m
//! viewing distance from a 24" 4K screen, as the paper assumes).

use anyhow::bail;
use image::{RgbImage, RgbaImage};

/// The FLIP error of a test image against its reference.
pub struct Flip {
    /// Mean of the per-pixel FLIP errors: the single number the paper's
    /// authors recommend.
    pub mean: f64,
    /// Largest per-pixel FLIP error.
    pub max: f64,
    /// The per-pixel errors drawn with the magma map (black: no visible
    /// difference, light yellow: 1).
    pub map: RgbImage,
}

fn rgb8(img: &RgbaImage) -> nv_flip::FlipImageRgb8 {
    let rgb: Vec<u8> = img.pixels().flat_map(|p| [p[0], p[1], p[2]]).collect();
    nv_flip::FlipImageRgb8::with_data(img.width(), img.height(), &rgb)
}

/// FLIP of `test` against `reference`. Errors if the sizes differ or an
/// image is empty.
pub fn flip(test: &RgbaImage, reference: &RgbaImage) -> anyhow::Result<Flip> {
    if test.dimensions() != reference.dimensions() {
        bail!(
            "cannot compute FLIP of images of different sizes: {}x{} vs {}x{}",
            test.width(),
            test.height(),
            reference.width(),
            reference.height()
        );
    }
    if test.width() == 0 || test.height() == 0 {
        bail!("cannot compute FLIP of an empty image");
    }
    let errors = nv_flip::flip(
        rgb8(reference),
        rgb8(test),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    );
    let pool = nv_flip::FlipPool::from_image(&errors);
    let colour = errors.apply_color_lut(&nv_flip::magma_lut());
    let map = RgbImage::from_raw(colour.width(), colour.height(), colour.to_vec())
        .expect("the colour map has the image's size");
    Ok(Flip {
        mean: f64::from(pool.mean()),
        max: f64::from(pool.max_value()),
        map,
    })
}

#[cfg(test)]
#[path = "flip_tests.rs"]
mod tests;
