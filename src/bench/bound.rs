//! The far field's error bound beside its measured error: the frame drawn
//! once more with `render.far_field_bound`, where tiled shading writes, per
//! pixel, a bound on |far part interpolated - far part| in linear light
//! (glsl/common/far_field.glsl derives it; docs/deferred/far_field.md). Here
//! each pixel's bound goes through the 8-bit sRGB encoding around the
//! pixel's own value, as the measured error does: the widest of
//! encode(v + b) - encode(v) and encode(v) - encode(v - b).

use crate::frame::targets::LIGHT_ACCUMULATION;
use crate::gl::Headless;
use crate::lighting::{srgb_decode, srgb_encode};
use crate::renderer::{Output, render_scene};
use crate::scene::{RenderPath, Scene};
use anyhow::Result;

/// The bound over a frame, in 8-bit sRGB units (0..1): its largest value,
/// and the percentage of pixels where it exceeds 1/255.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameBound {
    pub max: f64,
    pub pct_over_1: f64,
}

/// The bound of `scene`'s far field, whose 8-bit image is `image`; None
/// when the scene has no far field.
pub fn far_field(
    ctx: &Headless,
    scene: &Scene,
    image: &image::RgbaImage,
) -> Result<Option<FrameBound>> {
    Ok(far_field_pixels(ctx, scene, image)?.map(|b| FrameBound::of(&b)))
}

/// Each pixel's bound in 8-bit sRGB units (0..1), top row first, for
/// `scene`'s far field whose 8-bit image is `image`; None when the scene
/// has no far field.
pub fn far_field_pixels(
    ctx: &Headless,
    scene: &Scene,
    image: &image::RgbaImage,
) -> Result<Option<Vec<f64>>> {
    if scene.render.path != RenderPath::Tiled || scene.render.far_field == 0 {
        return Ok(None);
    }
    let mut s = scene.clone();
    s.render.far_field_bound = true;
    let r = render_scene(ctx, &s, Output::Srgb8)?;
    let Some(light) = r.targets().find(LIGHT_ACCUMULATION) else {
        return Ok(None);
    };
    Ok(Some(encode_bound(&light.read_rgba_f32(0), image)))
}

impl FrameBound {
    /// The largest of per-pixel bounds and the share above 1/255.
    pub fn of(pixels: &[f64]) -> FrameBound {
        let max = pixels.iter().copied().fold(0.0, f64::max);
        let over = pixels.iter().filter(|&&b| b > 1.0 / 255.0).count();
        FrameBound {
            max,
            pct_over_1: 100.0 * over as f64 / (pixels.len() as f64).max(1.0),
        }
    }
}

/// Each pixel's linear bound (the red channel of `bound`, bottom row
/// first) through the sRGB encoding around `image`'s values, top row first.
pub fn encode_bound(bound: &[f32], image: &image::RgbaImage) -> Vec<f64> {
    let (w, h) = image.dimensions();
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let b = bound[(((h - 1 - y) * w + x) * 4) as usize].max(0.0);
            let px = image.get_pixel(x, y);
            let mut worst = 0.0f64;
            for c in 0..3 {
                let v = f32::from(px[c]) / 255.0;
                let lin = srgb_decode(v);
                let up = srgb_encode((lin + b).min(1.0)) - v;
                let down = v - srgb_encode((lin - b).max(0.0));
                worst = worst.max(f64::from(up.max(down)));
            }
            out.push(worst);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_widens_through_the_encoding_where_the_image_is_dark() {
        // Two pixels, one black and one mid-grey, each with a bound of 1e-3.
        let image = image::RgbaImage::from_fn(2, 1, |x, _| {
            let v = if x == 0 { 0 } else { 128 };
            image::Rgba([v, v, v, 255])
        });
        let bound = [1e-3, 0.0, 0.0, 1.0, 1e-3, 0.0, 0.0, 1.0];
        let b = FrameBound::of(&encode_bound(&bound, &image));
        // Near black the encoding's slope is 12.92: 1e-3 -> 0.0129.
        assert!((b.max - 12.92e-3).abs() < 1e-5, "{b:?}");
        assert_eq!(b.pct_over_1, 50.0);
        let zero = FrameBound::of(&encode_bound(&[0.0; 8], &image));
        assert_eq!(zero.max, 0.0);
    }
}
