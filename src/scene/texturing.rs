//! How a material samples its texture (notes 01 §5): the wrap rule per axis
//! (clamp, repeat, mirror), the filter (nearest, bilinear, a mip level,
//! trilinear, anisotropic), and a transform of the mesh's texture
//! coordinates (uv x scale + offset), which is how a scene reaches
//! coordinates outside [0, 1]. Also the render settings that override them
//! frame-wide for the demo and the bench.
//!
//! ```toml
//! [materials.floor]
//! diffuse_texture = "assets/checker.png"
//! wrap = ["repeat", "mirror"]   # s, t; or one word for both
//! filter = "anisotropic"
//! anisotropy = 16
//! max_lod = 3                  # the last mip level read (an atlas's gutter)
//! uv_scale = [8.0, 8.0]
//! uv_offset = [0.0, 0.0]
//! ```

use super::settings::setting;
use crate::math::texture_mapping::WrapRule;

setting! {
    /// What a texture coordinate outside [0, 1] reads (notes 01 §5).
    pub enum Wrap {
        /// GL_CLAMP_TO_EDGE: above 1 reads 1, below 0 reads 0.
        Clamp = "clamp",
        /// GL_REPEAT: 1.1 reads 0.1, -0.1 reads 0.9.
        Repeat = "repeat",
        /// GL_MIRRORED_REPEAT: 1.1 reads 0.9, -0.1 reads 0.1.
        Mirror = "mirror",
    }
}

impl Wrap {
    /// The glSamplerParameteri value.
    pub fn gl(self) -> u32 {
        match self {
            Wrap::Clamp => glow::CLAMP_TO_EDGE,
            Wrap::Repeat => glow::REPEAT,
            Wrap::Mirror => glow::MIRRORED_REPEAT,
        }
    }
    /// The CPU twin's rule (src/math/texture_mapping.rs).
    pub fn rule(self) -> WrapRule {
        match self {
            Wrap::Clamp => WrapRule::Clamp,
            Wrap::Repeat => WrapRule::Repeat,
            Wrap::Mirror => WrapRule::Mirror,
        }
    }
}

setting! {
    /// How a texture is filtered (notes 01 §5.2-5.3.1).
    pub enum TextureFilter {
        /// The nearest texel, level 0 only (GL_NEAREST).
        Nearest = "nearest",
        /// Four texels blended, level 0 only (GL_LINEAR; §5.2).
        Bilinear = "bilinear",
        /// The nearest texel of the level lambda picks
        /// (GL_NEAREST_MIPMAP_NEAREST; §5.3): shows the levels' edges.
        NearestMip = "nearest_mip",
        /// Bilinear within the level lambda picks (GL_LINEAR_MIPMAP_NEAREST; §5.3).
        BilinearMip = "bilinear_mip",
        /// Bilinear in the two levels around lambda, blended (GL_LINEAR_MIPMAP_LINEAR; §5.3.1).
        Trilinear = "trilinear",
        /// Trilinear, with up to `anisotropy` samples along the footprint's
        /// long axis (GL_TEXTURE_MAX_ANISOTROPY, where the driver has it).
        Anisotropic = "anisotropic",
    }
}

impl TextureFilter {
    /// GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER.
    pub fn gl(self) -> (u32, u32) {
        match self {
            TextureFilter::Nearest => (glow::NEAREST, glow::NEAREST),
            TextureFilter::Bilinear => (glow::LINEAR, glow::LINEAR),
            TextureFilter::NearestMip => (glow::NEAREST_MIPMAP_NEAREST, glow::NEAREST),
            TextureFilter::BilinearMip => (glow::LINEAR_MIPMAP_NEAREST, glow::LINEAR),
            TextureFilter::Trilinear | TextureFilter::Anisotropic => {
                (glow::LINEAR_MIPMAP_LINEAR, glow::LINEAR)
            }
        }
    }
}

setting! {
    /// `render.texture_filter`: every material's own filter, or one for all.
    pub enum FilterOverride {
        Material = "material",
        Nearest = "nearest",
        Bilinear = "bilinear",
        NearestMip = "nearest_mip",
        BilinearMip = "bilinear_mip",
        Trilinear = "trilinear",
        Anisotropic = "anisotropic",
    }
}

impl FilterOverride {
    /// The filter a material with `own` samples with.
    pub fn apply(self, own: TextureFilter) -> TextureFilter {
        match self {
            FilterOverride::Material => own,
            FilterOverride::Nearest => TextureFilter::Nearest,
            FilterOverride::Bilinear => TextureFilter::Bilinear,
            FilterOverride::NearestMip => TextureFilter::NearestMip,
            FilterOverride::BilinearMip => TextureFilter::BilinearMip,
            FilterOverride::Trilinear => TextureFilter::Trilinear,
            FilterOverride::Anisotropic => TextureFilter::Anisotropic,
        }
    }
}

setting! {
    /// How texture coordinates and vertex colours cross a triangle (notes 01 §4.1, §5.1).
    pub enum Interpolation {
        /// Divided by w, interpolated, multiplied back: right under perspective.
        Perspective = "perspective",
        /// Linear in screen space (GLSL `noperspective`): the tilted-plane artefact.
        Affine = "affine",
    }
}

/// One material's sampling, resolved and checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texturing {
    /// The wrap rule along s (u) and along t (v).
    pub wrap: [Wrap; 2],
    pub filter: TextureFilter,
    /// The most samples the anisotropic filter takes (1..=16; the driver may allow fewer).
    pub anisotropy: f32,
    /// The last mip level sampling may read (GL_TEXTURE_MAX_LOD): an
    /// atlas whose tiles have an n-texel gutter stays clean up to log2 n.
    pub max_lod: f32,
    /// uv' = uv x scale + offset, applied in the vertex shader.
    pub uv_scale: [f32; 2],
    pub uv_offset: [f32; 2],
}

impl Default for Texturing {
    fn default() -> Self {
        Texturing {
            wrap: [Wrap::Repeat; 2],
            filter: TextureFilter::Trilinear,
            anisotropy: 16.0,
            max_lod: 1000.0,
            uv_scale: [1.0, 1.0],
            uv_offset: [0.0, 0.0],
        }
    }
}
