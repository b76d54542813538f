//! Sampler objects (GL 3.3 core): the wrap and filter state a texture unit
//! samples with, apart from the texture. One texture can then be read with
//! different wrap rules and filters by different materials. A pass binds one
//! with glBindSampler(unit, sampler) next to glBindTexture, and binds 0 again
//! when it is done (0: the texture's own parameters).

use super::Gl;
use anyhow::{Result, anyhow};
use glow::HasContext;

/// One sampler object.
pub struct Sampler {
    gl: Gl,
    pub id: glow::Sampler,
}

impl Sampler {
    /// glGenSamplers and glSamplerParameter*: wrap along s and t, the
    /// minification and magnification filters, the last mip level read
    /// (GL_TEXTURE_MAX_LOD), and, when `anisotropy` is above 1,
    /// GL_TEXTURE_MAX_ANISOTROPY (an extension in GL 3.3: pass
    /// 1 where the driver lacks it).
    pub fn new(
        gl: &Gl,
        wrap: [u32; 2],
        (min_filter, mag_filter): (u32, u32),
        anisotropy: f32,
        max_lod: f32,
    ) -> Result<Sampler> {
        unsafe {
            let id = gl
                .create_sampler()
                .map_err(|e| anyhow!("glGenSamplers: {e}"))?;
            super::live::made(super::live::Kind::Sampler);
            gl.sampler_parameter_i32(id, glow::TEXTURE_WRAP_S, wrap[0] as i32);
            gl.sampler_parameter_i32(id, glow::TEXTURE_WRAP_T, wrap[1] as i32);
            gl.sampler_parameter_i32(id, glow::TEXTURE_MIN_FILTER, min_filter as i32);
            gl.sampler_parameter_i32(id, glow::TEXTURE_MAG_FILTER, mag_filter as i32);
            gl.sampler_parameter_f32(id, glow::TEXTURE_MAX_LOD, max_lod);
            if anisotropy > 1.0 {
                gl.sampler_parameter_f32(id, glow::TEXTURE_MAX_ANISOTROPY, anisotropy);
            }
            Ok(Sampler { gl: gl.clone(), id })
        }
    }
}

impl Drop for Sampler {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_sampler(self.id);
            super::live::freed(super::live::Kind::Sampler);
        }
    }
}

/// The largest GL_TEXTURE_MAX_ANISOTROPY the driver takes: 1 without
/// GL_EXT_texture_filter_anisotropic or GL_ARB_texture_filter_anisotropic.
pub fn max_anisotropy(gl: &glow::Context) -> f32 {
    let ext = gl.supported_extensions();
    if ext.contains("GL_EXT_texture_filter_anisotropic")
        || ext.contains("GL_ARB_texture_filter_anisotropic")
    {
        unsafe { gl.get_parameter_f32(glow::MAX_TEXTURE_MAX_ANISOTROPY) }
    } else {
        1.0
    }
}
