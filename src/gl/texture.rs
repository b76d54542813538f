//! 2D textures: loaded from PNG (sRGB or linear), or empty render targets.

use super::Gl;
use anyhow::{Result, bail};
use glow::{HasContext, PixelUnpackData};
use std::path::Path;

pub use super::image_file::{MAX_TEXTURE_SIDE, load_rgba8};

mod upload;

/// Wrap and filter settings (glTexParameteri), set when the texture is made.
#[derive(Clone, Copy, Debug)]
pub struct Sampling {
    pub wrap: u32,
    pub min_filter: u32,
    pub mag_filter: u32,
}

impl Sampling {
    /// Trilinear filtering (notes 01 §5.3.1) with repeat wrapping.
    pub const TRILINEAR_REPEAT: Sampling = Sampling {
        wrap: glow::REPEAT,
        min_filter: glow::LINEAR_MIPMAP_LINEAR,
        mag_filter: glow::LINEAR,
    };
    /// One texel per pixel: render targets read with texelFetch or at pixel centres.
    pub const NEAREST_CLAMP: Sampling = Sampling {
        wrap: glow::CLAMP_TO_EDGE,
        min_filter: glow::NEAREST,
        mag_filter: glow::NEAREST,
    };
    /// Bilinear within level 0, clamped: a light map.
    pub const BILINEAR_CLAMP: Sampling = Sampling {
        wrap: glow::CLAMP_TO_EDGE,
        min_filter: glow::LINEAR,
        mag_filter: glow::LINEAR,
    };
}

/// One GL_TEXTURE_2D.
pub struct Texture {
    gl: Gl,
    pub id: glow::Texture,
    pub width: i32,
    pub height: i32,
    pub internal_format: u32,
    /// Samples per pixel: 1 for a GL_TEXTURE_2D, more for a
    /// GL_TEXTURE_2D_MULTISAMPLE (`render_target_multisample`).
    pub samples: i32,
}

impl Texture {
    /// An empty texture to render into (an FBO attachment).
    pub fn render_target(
        gl: &Gl,
        width: i32,
        height: i32,
        internal_format: u32,
    ) -> Result<Texture> {
        let (format, ty) = upload_format(internal_format)?;
        unsafe {
            let id = super::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_2D, Some(id));
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                internal_format as i32,
                width,
                height,
                0,
                format,
                ty,
                PixelUnpackData::Slice(None),
            );
            set_sampling(gl, Sampling::NEAREST_CLAMP);
            gl.bind_texture(glow::TEXTURE_2D, None);
            Ok(Texture {
                gl: gl.clone(),
                id,
                width,
                height,
                internal_format,
                samples: 1,
            })
        }
    }

    /// An empty GL_TEXTURE_2D_MULTISAMPLE of `samples` samples per pixel to
    /// render into (MSAA, src/techniques/fragment_tests/msaa.rs): it is
    /// never sampled, only resolved with glBlitFramebuffer. GL may give more
    /// samples than asked; `samples` holds what it gave (GL_TEXTURE_SAMPLES).
    pub fn render_target_multisample(
        gl: &Gl,
        width: i32,
        height: i32,
        internal_format: u32,
        samples: i32,
    ) -> Result<Texture> {
        unsafe {
            let id = super::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(id));
            gl.tex_image_2d_multisample(
                glow::TEXTURE_2D_MULTISAMPLE,
                samples,
                internal_format as i32,
                width,
                height,
                true,
            );
            let given = gl.get_tex_level_parameter_i32(
                glow::TEXTURE_2D_MULTISAMPLE,
                0,
                glow::TEXTURE_SAMPLES,
            );
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
            Ok(Texture {
                gl: gl.clone(),
                id,
                width,
                height,
                internal_format,
                samples: given.max(samples),
            })
        }
    }

    /// GL_TEXTURE_2D, or GL_TEXTURE_2D_MULTISAMPLE for more than one sample.
    pub fn target(&self) -> u32 {
        if self.samples > 1 {
            glow::TEXTURE_2D_MULTISAMPLE
        } else {
            glow::TEXTURE_2D
        }
    }

    /// An RGBA8 image from memory; `srgb` stores it as GL_SRGB8_ALPHA8 so that
    /// sampling returns linear values (colour textures), otherwise GL_RGBA8
    /// (data such as normal maps). Mipmaps are generated when the filter uses them.
    pub fn from_rgba8(
        gl: &Gl,
        width: u32,
        height: u32,
        pixels: &[u8],
        srgb: bool,
        sampling: Sampling,
    ) -> Result<Texture> {
        if pixels.len() != (width * height * 4) as usize {
            bail!(
                "texture data is {} bytes, expected {width}x{height}x4",
                pixels.len()
            );
        }
        let internal = if srgb {
            glow::SRGB8_ALPHA8
        } else {
            glow::RGBA8
        };
        unsafe {
            let id = super::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_2D, Some(id));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                internal as i32,
                width as i32,
                height as i32,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                PixelUnpackData::Slice(Some(pixels)),
            );
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
            set_sampling(gl, sampling);
            if matches!(
                sampling.min_filter,
                glow::LINEAR_MIPMAP_LINEAR
                    | glow::LINEAR_MIPMAP_NEAREST
                    | glow::NEAREST_MIPMAP_LINEAR
                    | glow::NEAREST_MIPMAP_NEAREST
            ) {
                gl.generate_mipmap(glow::TEXTURE_2D);
            }
            gl.bind_texture(glow::TEXTURE_2D, None);
            Ok(Texture {
                gl: gl.clone(),
                id,
                width: width as i32,
                height: height as i32,
                internal_format: internal,
                samples: 1,
            })
        }
    }

    /// Load a PNG (through the `image` crate), flipped so that v = 0 is the bottom row as GL expects.
    pub fn load(gl: &Gl, path: &Path, srgb: bool, sampling: Sampling) -> Result<Texture> {
        let img = load_rgba8(path)?;
        Texture::from_rgba8(gl, img.width(), img.height(), img.as_raw(), srgb, sampling)
    }
}

impl Texture {
    /// An empty texture to render into at mip levels `first..=last` of a
    /// `width` x `height` image (level k is max(1, size >> k) each way), for
    /// passes that draw into one level each. GL_TEXTURE_BASE_LEVEL is
    /// `first` and GL_TEXTURE_MAX_LEVEL `last`: a shader counts levels from
    /// `first` (lod 0 is level `first`). Filtering is bilinear within a
    /// level (GL_LINEAR_MIPMAP_NEAREST: textureLod at a whole lod reads that
    /// level), clamped to the edge.
    ///
    /// The levels below `first` are allocated too, though nothing draws or
    /// samples them: GL 3.3 needs only base to max, but Mesa lays a texture
    /// out from level 0, guesses level 0 from the first level it is given,
    /// and answers GL_FRAMEBUFFER_UNSUPPORTED for a 1x1 level 1 of a 3x2
    /// image without it.
    pub fn render_target_levels(
        gl: &Gl,
        width: i32,
        height: i32,
        internal_format: u32,
        first: u32,
        last: u32,
    ) -> Result<Texture> {
        if first > last || last > max_level(width, height) {
            bail!(
                "a {width}x{height} texture has levels 0..={}, not {first}..={last}",
                max_level(width, height)
            );
        }
        let (format, ty) = upload_format(internal_format)?;
        unsafe {
            let id = super::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_2D, Some(id));
            for level in 0..=last {
                let (w, h) = level_size(width, height, level);
                gl.tex_image_2d(
                    glow::TEXTURE_2D,
                    level as i32,
                    internal_format as i32,
                    w,
                    h,
                    0,
                    format,
                    ty,
                    PixelUnpackData::Slice(None),
                );
            }
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_BASE_LEVEL, first as i32);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, last as i32);
            set_sampling(
                gl,
                Sampling {
                    wrap: glow::CLAMP_TO_EDGE,
                    min_filter: glow::LINEAR_MIPMAP_NEAREST,
                    mag_filter: glow::LINEAR,
                },
            );
            gl.bind_texture(glow::TEXTURE_2D, None);
            Ok(Texture {
                gl: gl.clone(),
                id,
                width,
                height,
                internal_format,
                samples: 1,
            })
        }
    }

    /// Read mip `level` back as RGBA f32 (glGetTexImage; row 0 = bottom),
    /// with its size.
    pub fn read_level_f32(&self, level: u32) -> (i32, i32, Vec<f32>) {
        let (w, h) = level_size(self.width, self.height, level);
        let mut out = vec![0f32; (w * h * 4) as usize];
        unsafe {
            self.gl.bind_texture(glow::TEXTURE_2D, Some(self.id));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.get_tex_image(
                glow::TEXTURE_2D,
                level as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(bytemuck_f32(&mut out))),
            );
            self.gl.bind_texture(glow::TEXTURE_2D, None);
        }
        (w, h, out)
    }
}

/// The size of mip `level` of a `width` x `height` image: each side halved
/// `level` times, rounded down, at least 1 (GL 3.3 §3.8.14).
pub fn level_size(width: i32, height: i32, level: u32) -> (i32, i32) {
    let shrink = |n: i32| (n >> level.min(31)).max(1);
    (shrink(width), shrink(height))
}

/// The last mip level of a `width` x `height` image: floor(log2(max side)),
/// where both sides are 1.
pub fn max_level(width: i32, height: i32) -> u32 {
    let side = width.max(height).max(1) as u32;
    31 - side.leading_zeros()
}

/// glTexParameteri for wrap and filters on the bound GL_TEXTURE_2D.
pub fn set_sampling(gl: &glow::Context, s: Sampling) {
    unsafe {
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_S, s.wrap as i32);
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_T, s.wrap as i32);
        gl.tex_parameter_i32(
            glow::TEXTURE_2D,
            glow::TEXTURE_MIN_FILTER,
            s.min_filter as i32,
        );
        gl.tex_parameter_i32(
            glow::TEXTURE_2D,
            glow::TEXTURE_MAG_FILTER,
            s.mag_filter as i32,
        );
    }
}

/// The (format, type) pair glTexImage2D wants for an internal format with no data.
fn upload_format(internal: u32) -> Result<(u32, u32)> {
    Ok(match internal {
        glow::RGBA8 | glow::SRGB8_ALPHA8 => (glow::RGBA, glow::UNSIGNED_BYTE),
        glow::RGBA16F | glow::RGBA32F | glow::RGB16F | glow::RGB32F | glow::R32F | glow::RG16F => {
            (glow::RGBA, glow::FLOAT)
        }
        glow::R16F => (glow::RED, glow::FLOAT),
        glow::DEPTH24_STENCIL8 => (glow::DEPTH_STENCIL, glow::UNSIGNED_INT_24_8),
        glow::DEPTH32F_STENCIL8 => (glow::DEPTH_STENCIL, glow::FLOAT_32_UNSIGNED_INT_24_8_REV),
        glow::DEPTH_COMPONENT24 | glow::DEPTH_COMPONENT32F => (glow::DEPTH_COMPONENT, glow::FLOAT),
        other => bail!("no upload format known for internal format {other:#x}"),
    })
}

impl Drop for Texture {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_texture(self.id);
            super::live::freed(super::live::Kind::Texture);
        }
    }
}

/// The bytes of `v`, for glReadPixels and glGetTexImage into floats.
pub fn bytemuck_f32(v: &mut [f32]) -> &mut [u8] {
    // f32 has no padding and any byte pattern is a valid f32.
    unsafe { std::slice::from_raw_parts_mut(v.as_mut_ptr() as *mut u8, std::mem::size_of_val(v)) }
}
