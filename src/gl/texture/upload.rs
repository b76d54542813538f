//! Textures filled from memory after they are made: a light map's floats,
//! and one mip level replaced (the mip-colour twins).

use super::{Sampling, Texture, set_sampling};
use crate::gl::Gl;
use anyhow::{Result, bail};
use glow::{HasContext, PixelUnpackData};

impl Texture {
    /// A GL_RGBA16F texture of linear values from memory (`rgb`, three
    /// floats a texel, row 0 at the bottom), with no mip maps: a light map.
    pub fn from_rgb_f32(
        gl: &Gl,
        width: u32,
        height: u32,
        rgb: &[f32],
        sampling: Sampling,
    ) -> Result<Texture> {
        if rgb.len() != (width * height * 3) as usize {
            bail!(
                "texture data is {} floats, expected {width}x{height}x3",
                rgb.len()
            );
        }
        let bytes: Vec<u8> = rgb.iter().flat_map(|f| f.to_le_bytes()).collect();
        unsafe {
            let id = crate::gl::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_2D, Some(id));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                glow::RGBA16F as i32,
                width as i32,
                height as i32,
                0,
                glow::RGB,
                glow::FLOAT,
                PixelUnpackData::Slice(Some(&bytes)),
            );
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
            set_sampling(gl, sampling);
            gl.bind_texture(glow::TEXTURE_2D, None);
            Ok(Texture {
                gl: gl.clone(),
                id,
                width: width as i32,
                height: height as i32,
                internal_format: glow::RGBA16F,
                samples: 1,
            })
        }
    }

    /// Replace mip level `level` (`width` x `height`, RGBA8) with glTexImage2D.
    pub fn upload_level(&self, level: u32, width: i32, height: i32, pixels: &[u8]) {
        unsafe {
            self.gl.bind_texture(glow::TEXTURE_2D, Some(self.id));
            self.gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            self.gl.tex_image_2d(
                glow::TEXTURE_2D,
                level as i32,
                self.internal_format as i32,
                width,
                height,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                PixelUnpackData::Slice(Some(pixels)),
            );
            self.gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
            self.gl.bind_texture(glow::TEXTURE_2D, None);
        }
    }
}
