//! Per-frame values every pass reads (the texture units are in units.rs).

use glam::{Mat4, Vec3};

/// Per-frame values every pass needs.
pub struct FrameUniforms {
    pub view: Mat4,
    pub projection: Mat4,
    pub view_projection: Mat4,
    pub inverse_view_projection: Mat4,
    pub eye: Vec3,
    /// The camera's near and far planes (eye-space distances).
    pub near: f32,
    pub far: f32,
    pub light_count: i32,
    pub lights_ubo: glow::Buffer,
    /// Every light as RGBA32F texels, or as packed halves in RGBA32UI ones
    /// when the lighting variant reads those (glsl/common/light_buffer.glsl).
    pub lights_texture: glow::Texture,
    /// The world's target holds sRGB-encoded values (the 8-bit output, with
    /// no post chain) rather than linear light (a post chain's HDR target,
    /// or the RGBA32F output of error measurements).
    pub output_srgb: bool,
    /// The output holds encoded values (8-bit) rather than linear ones
    /// (RGBA32F): whether a post chain's gamma pass encodes.
    pub output_encoded: bool,
    /// The background as written to the world's target (sRGB-encoded when it is).
    pub clear_color: Vec3,
    /// The view's rectangle in the targets: x, y, width, height in pixels
    /// (the whole target but for a split view).
    pub viewport: [i32; 4],
    /// The packed G-buffer's shininess values, four a vec4
    /// (src/frame/gbuffer.rs `shininess_uniform`).
    pub shininess_table: [glam::Vec4; 16],
    /// The slim G-buffer's specular colour, as the full one would store it
    /// (src/frame/gbuffer_slim.rs `constant_specular`; 0 with the full one).
    pub gbuffer_specular: Vec3,
}

/// Texture units, named once in src/frame/units.rs.
pub use super::units as unit;

/// The uniform-block binding point of the `Lights` block (glsl/common/lighting.glsl).
pub const LIGHTS_BINDING: u32 = 0;
