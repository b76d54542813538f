//! Reading the finished frame back: as an 8-bit sRGB image (PNG order) or
//! as linear floats (for error measurements).

use super::Renderer;
use crate::lighting;

/// How the final image is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// RGBA8 holding sRGB-encoded colour: what PNGs and the window show.
    Srgb8,
    /// RGBA32F holding linear colour: for error measurements.
    Linear32F,
}

impl Output {
    /// The output target's colour format.
    pub fn format(self) -> u32 {
        match self {
            Output::Srgb8 => glow::RGBA8,
            Output::Linear32F => glow::RGBA32F,
        }
    }
}

impl Renderer {
    /// The output as an sRGB PNG-ready image (top row first).
    pub fn read_image(&self) -> image::RgbaImage {
        match self.output_kind {
            Output::Srgb8 => self.output().read_rgba8_top_down(0),
            Output::Linear32F => {
                let f = self.output().read_rgba_f32(0);
                let (w, h) = (self.width as u32, self.height as u32);
                let px = |c: f32| (lighting::srgb_encode(c) * 255.0).round() as u8;
                image::RgbaImage::from_fn(w, h, |x, y| {
                    let i = (((h - 1 - y) * w + x) * 4) as usize;
                    image::Rgba([px(f[i]), px(f[i + 1]), px(f[i + 2]), 255])
                })
            }
        }
    }

    /// The output as linear RGBA floats, bottom row first (Linear32F output only
    /// gives the unquantised values).
    pub fn read_linear(&self) -> Vec<f32> {
        let f = self.output().read_rgba_f32(0);
        match self.output_kind {
            Output::Linear32F => f,
            Output::Srgb8 => f
                .chunks(4)
                .flat_map(|p| {
                    [
                        lighting::srgb_decode(p[0]),
                        lighting::srgb_decode(p[1]),
                        lighting::srgb_decode(p[2]),
                        p[3],
                    ]
                })
                .collect(),
        }
    }
}
