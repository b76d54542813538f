//! What the geometry passes sample a material's texture with (notes 01 §5):
//! a sampler object per wrap rule, filter and anisotropy the scene's
//! materials use (every filter is made, so `render.texture_filter` can
//! switch them in the demo without a reload), and, per texture size, a twin
//! whose mip levels are flat colours (`render.mip_colors`: which level
//! lambda picks, pixel by pixel).

use crate::gl::Gl;
use crate::gl::sampler::{Sampler, max_anisotropy};
use crate::gl::texture::{Sampling, Texture, level_size, max_level};
use crate::scene::RenderSettings;
use crate::scene::texturing::{TextureFilter, Texturing, Wrap};
use anyhow::Result;
use std::collections::HashMap;
use std::collections::hash_map::Entry;

/// The colour of mip level k in the twins (then repeating): red, green,
/// blue, yellow, magenta, cyan, white, black: every channel 0 or 255, so
/// the colour reads the same encoded or not.
pub const LEVEL_COLORS: [[u8; 3]; 8] = [
    [255, 0, 0],
    [0, 255, 0],
    [0, 0, 255],
    [255, 255, 0],
    [255, 0, 255],
    [0, 255, 255],
    [255, 255, 255],
    [0, 0, 0],
];

/// A sampler's settings: the wrap rule per axis, the filter, the
/// anisotropy, the last mip level (its bits).
type SamplerKey = ([Wrap; 2], TextureFilter, u32, u32);

/// The scene's samplers and mip-colour twins.
pub struct TextureSamplers {
    samplers: HashMap<SamplerKey, Sampler>,
    twins: HashMap<(i32, i32), Texture>,
    /// GL_MAX_TEXTURE_MAX_ANISOTROPY (1: the driver has no anisotropic filtering).
    pub max_anisotropy: f32,
}

impl TextureSamplers {
    /// The samplers `materials` need, for every filter, and a twin per size in `textures`.
    pub fn new(gl: &Gl, materials: &[Texturing], textures: &[Texture]) -> Result<TextureSamplers> {
        let max_anisotropy = max_anisotropy(gl);
        let mut samplers = HashMap::new();
        for t in materials {
            for &filter in TextureFilter::ALL {
                let key = key(t, filter, max_anisotropy);
                if let Entry::Vacant(e) = samplers.entry(key) {
                    let wrap = [t.wrap[0].gl(), t.wrap[1].gl()];
                    e.insert(Sampler::new(
                        gl,
                        wrap,
                        filter.gl(),
                        key.2 as f32,
                        t.max_lod,
                    )?);
                }
            }
        }
        let mut twins = HashMap::new();
        for t in textures {
            let size = (t.width, t.height);
            if let Entry::Vacant(e) = twins.entry(size) {
                e.insert(level_colors(gl, size.0, size.1)?);
            }
        }
        Ok(TextureSamplers {
            samplers,
            twins,
            max_anisotropy,
        })
    }

    /// The sampler a material with `t` reads its texture with under `r`.
    pub fn sampler(&self, t: &Texturing, r: &RenderSettings) -> Option<glow::Sampler> {
        let filter = r.texture_filter.apply(t.filter);
        self.samplers
            .get(&key(t, filter, self.max_anisotropy))
            .map(|s| s.id)
    }

    /// The mip-colour twin of a texture of `texture`'s size.
    pub fn twin(&self, texture: &Texture) -> Option<glow::Texture> {
        self.twins
            .get(&(texture.width, texture.height))
            .map(|t| t.id)
    }
}

/// The anisotropy a sampler gets: the material's, within what the driver
/// allows, and 1 for every filter but the anisotropic one.
fn key(t: &Texturing, filter: TextureFilter, max: f32) -> SamplerKey {
    let a = if filter == TextureFilter::Anisotropic {
        t.anisotropy.min(max).max(1.0)
    } else {
        1.0
    };
    (t.wrap, filter, a as u32, t.max_lod.to_bits())
}

/// A `width` x `height` RGBA8 texture whose level k is LEVEL_COLORS[k % 8]
/// throughout, uploaded level by level with glTexImage2D.
fn level_colors(gl: &Gl, width: i32, height: i32) -> Result<Texture> {
    let fill = |(w, h): (i32, i32), k: u32| -> Vec<u8> {
        let [r, g, b] = LEVEL_COLORS[k as usize % LEVEL_COLORS.len()];
        [r, g, b, 255].repeat((w * h) as usize)
    };
    let t = Texture::from_rgba8(
        gl,
        width as u32,
        height as u32,
        &fill((width, height), 0),
        false,
        Sampling::NEAREST_CLAMP,
    )?;
    for k in 1..=max_level(width, height) {
        let (w, h) = level_size(width, height, k);
        t.upload_level(k, w, h, &fill((w, h), k));
    }
    Ok(t)
}
