//! Per-frame values every pass reads, and the texture units, named once.

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
    /// Every light as RGBA32F texels (glsl/common/light_buffer.glsl).
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
}

/// Texture units. A pass binds a texture with
/// `glActiveTexture(GL_TEXTURE0 + unit)` and tells its sampler with
/// `glUniform1i(sampler, unit)`; GLSL 3.30 has no `layout(binding = n)`, so
/// these numbers appear nowhere else.
pub mod unit {
    /// Geometry passes: the material's diffuse texture (`u_diffuse_texture`).
    pub const DIFFUSE_TEXTURE: u32 = 0;
    /// Geometry passes: the material's normal map (`u_normal_map`, notes 01 §8.4).
    pub const NORMAL_MAP: u32 = 1;
    /// The forward pass: an object's baked light map (`u_light_map`, notes 01 §8.2).
    pub const LIGHT_MAP: u32 = 2;
    /// Geometry passes: the material's specular map (`u_specular_map`):
    /// FAR_SPECULAR's unit, which only tiled shading's lighting pass reads,
    /// and no geometry pass is a lighting pass of tiled shading.
    pub const SPECULAR_MAP: u32 = 15;
    /// Geometry passes: glTF's metallic-roughness, occlusion and emissive
    /// maps (`u_metal_rough_map`, `u_occlusion_map`, `u_emissive_map`;
    /// src/scene/gltf_material.rs): past the 16 units GL 3.3 promises, as
    /// GBUFFER_ALPHA is, so they clash with no pass's own units.
    pub const METAL_ROUGH_MAP: u32 = 18;
    pub const OCCLUSION_MAP: u32 = 19;
    pub const EMISSIVE_MAP: u32 = 20;
    /// The parallax pass: the material's height map (`u_height_map`,
    /// techniques/lighting/parallax_mapping.rs).
    pub const HEIGHT_MAP: u32 = 3;
    /// Lighting passes read the G-buffer (`glsl/common/gbuffer_read.glsl`).
    pub const GBUFFER_NORMAL: u32 = 0;
    pub const GBUFFER_ALBEDO: u32 = 1;
    pub const GBUFFER_SPECULAR: u32 = 2;
    pub const GBUFFER_DEPTH: u32 = 3;
    /// The microfacet triple, gAlpha and gConvert (notes 03, src/frame/gbuffer.rs):
    /// past the 16 units GL 3.3 promises, which tiled shading fills.
    pub const GBUFFER_ALPHA: u32 = 16;
    pub const GBUFFER_CONVERT: u32 = 17;
    /// The accumulated light (`u_light`; the light pre-pass's diffuse light).
    pub const LIGHT: u32 = 4;
    /// The light pre-pass's specular light (`u_specular_light`).
    pub const SPECULAR_LIGHT: u32 = 5;
    /// Tiled shading's buffer textures (glsl/deferred/tiled_shading.frag):
    /// the lights, and each cluster's (offset, count) followed by the light
    /// numbers. Units 6-13 hold the shadow maps (src/frame/shadows.rs).
    pub const TILED_LIGHTS: u32 = 4;
    pub const TILED_CLUSTERS: u32 = 5;
    /// The far field's diffuse and specular light (glsl/common/far_field.glsl),
    /// read by tiled shading: with the units above, all 16 that GL 3.3
    /// promises a fragment shader are taken.
    pub const FAR_DIFFUSE: u32 = 14;
    pub const FAR_SPECULAR: u32 = 15;
    /// The far field's harmonics past their first four floats
    /// (glsl/common/far_field_sh.glsl, `render.far_field_sh`), read by tiled
    /// shading: 27-31, past the units taken, and 18, glTF's
    /// metallic-roughness map, which only geometry passes read (no geometry
    /// pass is a lighting pass of tiled shading).
    pub const FAR_SH: [u32; 6] = [27, 28, 29, 30, 31, 18];
    /// The environment cube map (`u_environment`, glsl/common/environment.glsl):
    /// FAR_DIFFUSE's unit, which only tiled shading's lighting pass reads, and
    /// no pass reads both.
    pub const ENVIRONMENT: u32 = 14;
    /// The ambient occlusion (techniques/deferred/ambient_light.rs): its
    /// passes' own input (the rotation tile, the AO being blurred), and the
    /// AO the ambient term reads in the composite and the light pre-pass's
    /// combine. Those two bind no shadow map, so one of their units serves.
    pub const AMBIENT_OCCLUSION: u32 = 13;
    /// Order-independent transparency (techniques/blending/weighted_blended.rs,
    /// depth_peeling.rs): the opaque world's depth, and the two textures a
    /// pass reads (accumulated colour and weights; a layer and its depth).
    pub const OIT_OPAQUE_DEPTH: u32 = 3;
    pub const OIT_FIRST: u32 = 4;
    pub const OIT_SECOND: u32 = 5;
    /// A post-chain step reads the previous image (`u_image`).
    pub const POST_INPUT: u32 = 0;
    /// Image-based lighting's irradiance and prefiltered cube maps and its
    /// split-sum table (glsl/common/image_based_lighting.glsl), read by the
    /// forward pass and the composite: past the 16 units GL 3.3 promises
    /// (src/frame/image_based_lighting.rs checks the GL has them).
    pub const IBL_IRRADIANCE: u32 = 21;
    pub const IBL_PREFILTERED: u32 = 22;
    pub const IBL_BRDF: u32 = 23;
    // 24: the cascaded shadow maps' array (src/frame/shadows/cascades.rs).
    /// The LTC fit tables of the area lights (glsl/lighting/ltc_area_lights.glsl,
    /// src/frame/ltc_area_lights.rs), read by the forward pass: past IBL's and
    /// the cascades' units (`ltc_area_lights::check_units`).
    pub const LTC_1: u32 = 25;
    pub const LTC_2: u32 = 26;
}

/// The uniform-block binding point of the `Lights` block (glsl/common/lighting.glsl).
pub const LIGHTS_BINDING: u32 = 0;
