//! The GL side of the shadow comparison (notes 01 §8.5): which pixels a
//! shadow-mapped render shows in shadow, from three renders of the same
//! scene and camera with one light: `with_shadows`, `without_shadows` (the
//! shadow test off) and `ambient_only` (the light off). With Y' the luma of
//! the stored 8-bit sRGB values and Y the luminance of the decoded linear
//! values (both with the Rec. 709 weights 0.2126, 0.7152, 0.0722):
//! ```text
//! considered  Y'(without) - Y'(ambient) > 8/255
//! shadowed    Y(with) - Y(ambient) < 0.5 (Y(without) - Y(ambient))
//! ```
//! Light adds linearly, so the ratio of the second line is the shadow factor
//! (0 in full shadow, 1 lit, between in a filtered penumbra): shadowed means
//! that less than half of the light arrives. A pixel the light visibly does
//! not reach (facing away, outside a spot's cone, too far) is `Ignored`: no
//! render can tell whether it is in shadow. The 8/255 keeps the ratio well
//! above the renders' rounding (one 8-bit step).
//!
//! The mask runs bottom row first, as glReadPixels and the depth buffer do.

use anyhow::{Result, bail};
use image::RgbaImage;

/// What the renders say about one pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlShadow {
    /// The light does not visibly reach it: not judged.
    Ignored,
    Lit,
    Shadowed,
}

/// Smallest luma the light must add for a pixel to be considered.
pub const CONSIDERED_LUMA: f32 = 8.0 / 255.0;
/// Below this shadow factor a pixel counts as shadowed.
pub const SHADOWED_BELOW: f32 = 0.5;

/// The GL shadow classification of every pixel, bottom row first.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadowMask {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<GlShadow>,
}

fn luma(p: &[u8]) -> f32 {
    (0.2126 * f32::from(p[0]) + 0.7152 * f32::from(p[1]) + 0.0722 * f32::from(p[2])) / 255.0
}

fn linear_luminance(p: &[u8]) -> f32 {
    let decode = |c: u8| {
        let c = f32::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * decode(p[0]) + 0.7152 * decode(p[1]) + 0.0722 * decode(p[2])
}

impl ShadowMask {
    /// The rule of the module header on one pixel (8-bit sRGB RGB(A)).
    pub fn classify(with_shadows: &[u8], without_shadows: &[u8], ambient_only: &[u8]) -> GlShadow {
        if luma(without_shadows) - luma(ambient_only) <= CONSIDERED_LUMA {
            return GlShadow::Ignored;
        }
        let ambient = linear_luminance(ambient_only);
        let lit = linear_luminance(without_shadows) - ambient;
        if linear_luminance(with_shadows) - ambient < SHADOWED_BELOW * lit {
            GlShadow::Shadowed
        } else {
            GlShadow::Lit
        }
    }

    /// The mask of three renders (module header), given as images are
    /// (top row first); the mask runs bottom row first, like the depth.
    pub fn from_renders(
        with_shadows: &RgbaImage,
        without_shadows: &RgbaImage,
        ambient_only: &RgbaImage,
    ) -> Result<ShadowMask> {
        let size = with_shadows.dimensions();
        if without_shadows.dimensions() != size || ambient_only.dimensions() != size {
            bail!(
                "shadow mask: the renders differ in size: {:?}, {:?}, {:?}",
                size,
                without_shadows.dimensions(),
                ambient_only.dimensions()
            );
        }
        let (width, height) = (size.0 as usize, size.1 as usize);
        let mut pixels = Vec::with_capacity(width * height);
        for y in (0..size.1).rev() {
            for x in 0..size.0 {
                pixels.push(ShadowMask::classify(
                    &with_shadows.get_pixel(x, y).0,
                    &without_shadows.get_pixel(x, y).0,
                    &ambient_only.get_pixel(x, y).0,
                ));
            }
        }
        Ok(ShadowMask {
            width,
            height,
            pixels,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use GlShadow as G;
    use image::Rgba;

    #[test]
    fn the_rule_classifies_in_linear_light() {
        let (black, white) = ([0, 0, 0, 255], [255, 255, 255, 255]);
        // sRGB 170 is linear 0.40 and sRGB 203 linear 0.60: by stored values
        // both are over half of 255, in light only the second is.
        assert_eq!(
            ShadowMask::classify(&[170, 170, 170, 255], &white, &black),
            G::Shadowed
        );
        assert_eq!(
            ShadowMask::classify(&[203, 203, 203, 255], &white, &black),
            G::Lit
        );
        assert_eq!(
            ShadowMask::classify(&[40, 40, 40, 255], &[140; 4], &[40; 4]),
            G::Shadowed
        );
        // The light adds 8/255 of luma or less: ignored.
        assert_eq!(
            ShadowMask::classify(&[40; 4], &[47; 4], &[40; 4]),
            G::Ignored
        );
        assert_eq!(
            ShadowMask::classify(&[40; 4], &[49; 4], &[40; 4]),
            G::Shadowed
        );
    }

    #[test]
    fn from_renders_runs_bottom_row_first() {
        // 1x2 images: the top pixel is in shadow, the bottom one lit.
        let ambient = RgbaImage::from_pixel(1, 2, Rgba([10, 10, 10, 255]));
        let without = RgbaImage::from_pixel(1, 2, Rgba([200, 200, 200, 255]));
        let mut with = without.clone();
        with.put_pixel(0, 0, Rgba([10, 10, 10, 255]));
        let m = ShadowMask::from_renders(&with, &without, &ambient).unwrap();
        assert_eq!((m.width, m.height), (1, 2));
        assert_eq!(m.pixels, vec![G::Lit, G::Shadowed]);
        let e = ShadowMask::from_renders(&with, &RgbaImage::new(2, 2), &ambient).unwrap_err();
        assert!(e.to_string().contains("differ in size"), "{e}");
    }
}
