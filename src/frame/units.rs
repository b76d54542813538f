//! Every fixed texture unit gloss binds, named once. A pass binds a texture
//! with `glActiveTexture(GL_TEXTURE0 + unit)` and tells its sampler with
//! `glUniform1i(sampler, unit)`; GLSL 3.30 has no `layout(binding = n)`, so
//! these numbers appear nowhere else.
//!
//! Units are few (GL 3.3 promises 16 to a fragment shader), so passes that
//! never run one program together share them. A constant on the same unit
//! as another says so with `shares` and says why no draw reads both;
//! tests/trace/units.rs fails on two constants on one unit that do not,
//! and replays every shipped scene's traced frame on every path to check
//! that no draw has two samplers of different types on one unit and that
//! no unit is rebound by other code between its bind and its draw.

/// One constant of this module, for the tests: its name, first unit, how
/// many units from there it holds, what it holds (its doc comment) and the
/// constants it is documented to share a unit with.
#[derive(Clone, Copy, Debug)]
pub struct Unit {
    pub name: &'static str,
    pub first: u32,
    pub count: u32,
    pub holds: &'static str,
    pub shares: &'static [&'static str],
}

impl Unit {
    /// The units it holds.
    pub fn range(&self) -> std::ops::Range<u32> {
        self.first..self.first + self.count
    }
}

/// A constant's `count`, 1 when it names none.
const fn count_or_one(count: &[u32]) -> u32 {
    match count {
        [n] => *n,
        _ => 1,
    }
}

macro_rules! units {
    ($(
        $(#[doc = $doc:literal])*
        $name:ident = $first:literal $(, count $count:literal)? $(, shares $($other:ident),+)? ;
    )*) => {
        $(
            $(#[doc = $doc])*
            pub const $name: u32 = $first;
        )*
        /// Every constant above, in order.
        pub const ALL: &[Unit] = &[$(Unit {
            name: stringify!($name),
            first: $first,
            count: count_or_one(&[$($count)?]),
            holds: concat!($($doc, "\n"),*),
            shares: &[$($(stringify!($other)),+)?],
        }),*];
    };
}

units! {
    /// Geometry passes: the material's diffuse texture (`u_diffuse_texture`;
    /// src/frame/draw_textures.rs, forward.rs, deferred/gbuffer.rs).
    DIFFUSE_TEXTURE = 0;
    /// Geometry passes: the material's normal map (`u_normal_map`, notes 01 §8.4).
    NORMAL_MAP = 1;
    /// The forward pass: an object's baked light map (`u_light_map`, notes 01 §8.2).
    LIGHT_MAP = 2;
    /// The parallax pass: the material's height map (`u_height_map`,
    /// techniques/lighting/parallax_mapping.rs).
    HEIGHT_MAP = 3;
    /// Geometry passes: the material's specular map (`u_specular_map`):
    /// FAR_SPECULAR's unit, which only tiled shading's lighting pass reads,
    /// and no geometry pass is a lighting pass of tiled shading.
    SPECULAR_MAP = 15, shares FAR_SPECULAR;
    /// Geometry passes: glTF's metallic-roughness, occlusion and emissive
    /// maps (`u_metal_rough_map`, `u_occlusion_map`, `u_emissive_map`;
    /// src/scene/gltf_material.rs): past the 16 units GL 3.3 promises, as
    /// GBUFFER_ALPHA is, so they clash with no pass's own units.
    METAL_ROUGH_MAP = 18;
    /// glTF's occlusion map (`u_occlusion_map`).
    OCCLUSION_MAP = 19;
    /// glTF's emissive map (`u_emissive_map`).
    EMISSIVE_MAP = 20;
    /// Lighting passes read the G-buffer (`glsl/common/gbuffer_read.glsl`):
    /// normal and shininess. Lighting passes draw no material, so they share
    /// the geometry passes' units.
    GBUFFER_NORMAL = 0, shares DIFFUSE_TEXTURE;
    /// The G-buffer's albedo.
    GBUFFER_ALBEDO = 1, shares NORMAL_MAP;
    /// The G-buffer's specular colour.
    GBUFFER_SPECULAR = 2, shares LIGHT_MAP;
    /// The G-buffer's depth.
    GBUFFER_DEPTH = 3, shares HEIGHT_MAP;
    /// The microfacet triple, gAlpha (notes 03, src/frame/gbuffer.rs): past
    /// the 16 units GL 3.3 promises, which tiled shading fills.
    GBUFFER_ALPHA = 16;
    /// The microfacet triple's gConvert.
    GBUFFER_CONVERT = 17;
    /// The accumulated light (`u_light`; the light pre-pass's diffuse
    /// light), read by the composite and the pre-pass's combine, which draw
    /// no material.
    LIGHT = 4;
    /// The light pre-pass's specular light (`u_specular_light`).
    SPECULAR_LIGHT = 5;
    /// Tiled shading's buffer textures (glsl/deferred/tiled_shading.frag):
    /// the lights. Tiled shading's lighting pass reads no accumulated light.
    TILED_LIGHTS = 4, shares LIGHT;
    /// Tiled shading's clusters: each cluster's (offset, count) followed by
    /// the light numbers.
    TILED_CLUSTERS = 5, shares SPECULAR_LIGHT;
    /// The 2D shadow maps, one a caster slot (`u_shadow_map[i]`;
    /// src/frame/shadows.rs; as many as scene::shadows::MAX_SHADOW_MAPS_2D).
    SHADOW_MAPS_2D = 6, count 4;
    /// The cube shadow maps (`u_shadow_cube[i]`; as many as
    /// scene::shadows::MAX_SHADOW_CUBES).
    SHADOW_CUBES = 10, count 4;
    /// The ambient occlusion (techniques/deferred/ambient_light.rs): its
    /// passes' own input (the rotation tile, the AO being blurred), and the
    /// AO the ambient term reads in the composite and the light pre-pass's
    /// combine. Those two bind no shadow map, so the last cube's unit serves.
    AMBIENT_OCCLUSION = 13, shares SHADOW_CUBES;
    /// The far field's diffuse light (glsl/common/far_field.glsl), read by
    /// tiled shading: with the units above, all 16 that GL 3.3 promises a
    /// fragment shader are taken.
    FAR_DIFFUSE = 14;
    /// The far field's specular light.
    FAR_SPECULAR = 15;
    /// The environment cube map (`u_environment`, glsl/common/environment.glsl):
    /// FAR_DIFFUSE's unit, which only tiled shading's lighting pass reads, and
    /// no pass reads both.
    ENVIRONMENT = 14, shares FAR_DIFFUSE;
    /// Order-independent transparency (techniques/blending/weighted_blended.rs,
    /// depth_peeling.rs): the opaque world's depth. Its transparent draws
    /// and composites read no G-buffer and no height map.
    OIT_OPAQUE_DEPTH = 3, shares HEIGHT_MAP, GBUFFER_DEPTH;
    /// The first texture an OIT composite reads (the accumulated colour; a
    /// peeled layer): its passes read no accumulated light nor tiled data.
    OIT_FIRST = 4, shares LIGHT, TILED_LIGHTS;
    /// The second (the weights; the previous layer's depth).
    OIT_SECOND = 5, shares SPECULAR_LIGHT, TILED_CLUSTERS;
    /// A post-chain step reads the previous image (`u_image`): post passes
    /// draw no material and read no G-buffer.
    POST_INPUT = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL;
    /// Bloom's merge reads its four blurred levels (`u_blur0..3`,
    /// techniques/post/bloom.rs) beside POST_INPUT: a post pass, reading no
    /// geometry or lighting units.
    BLOOM_BLURS = 1, count 4, shares NORMAL_MAP, LIGHT_MAP, HEIGHT_MAP, GBUFFER_ALBEDO,
        GBUFFER_SPECULAR, GBUFFER_DEPTH, LIGHT, TILED_LIGHTS, OIT_OPAQUE_DEPTH, OIT_FIRST;
    /// Image-based lighting's irradiance cube (glsl/common/image_based_lighting.glsl),
    /// read by the forward pass and the composite: past the 16 units GL 3.3
    /// promises (src/frame/image_based_lighting.rs checks the GL has them).
    IBL_IRRADIANCE = 21;
    /// Image-based lighting's prefiltered cube.
    IBL_PREFILTERED = 22;
    /// Image-based lighting's split-sum table.
    IBL_BRDF = 23;
    /// Without image-based lighting its table sampler (`u_ibl_brdf`) names
    /// unit 0, where every program that includes it reads a sampler2D
    /// (a material's diffuse texture or the G-buffer's normal), so no draw
    /// mixes two sampler types on one unit; it reads nothing.
    IBL_BRDF_OFF = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT;
    /// Image-based lighting's precompute (techniques/sky/image_based_lighting.rs)
    /// reads the sky's cube (`u_environment`) in programs of its own.
    IBL_SOURCE = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT, IBL_BRDF_OFF;
    /// Skinning's joint matrices as a buffer texture (`u_joint_texture`,
    /// techniques/animation/skinned_meshes.rs), read by its vertex shader in
    /// a transform-feedback program that samples nothing else.
    JOINT_TEXTURE = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT, IBL_BRDF_OFF, IBL_SOURCE;
    /// The tessellated terrain's displacement map (`u_height`,
    /// techniques/vertex_geometry/tessellation.rs), in a program of its own.
    TERRAIN_HEIGHT = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT, IBL_BRDF_OFF,
        IBL_SOURCE, JOINT_TEXTURE;
    /// A mirror's roughness map (`u_roughness`, techniques/stencil/mirror.rs),
    /// in the mirror surface's program of its own.
    MIRROR_ROUGHNESS = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT, IBL_BRDF_OFF,
        IBL_SOURCE, JOINT_TEXTURE, TERRAIN_HEIGHT;
    /// The cascaded shadow maps' GL_TEXTURE_2D_ARRAY (`u_shadow_cascades`,
    /// src/frame/shadows/cascades.rs): past the units above.
    SHADOW_CASCADES = 24;
    /// The LTC area lights' inverse-matrix table (glsl/lighting/ltc_area_lights.glsl,
    /// src/frame/ltc_area_lights.rs), read by the forward pass beside
    /// everything it reads: past IBL's and the cascades' units
    /// (`ltc_area_lights::check_units`).
    LTC_1 = 25;
    /// The LTC area lights' magnitude and Fresnel table.
    LTC_2 = 26;
    /// The far field's harmonics past their first four floats
    /// (glsl/common/far_field_sh.glsl, `render.far_field_sh`), read by tiled
    /// shading's lighting pass: 27-31, past the units taken ...
    FAR_SH_FIRST = 27, count 5;
    /// ... and the sixth on glTF's metallic-roughness unit, which only
    /// geometry passes read (no geometry pass is a lighting pass of tiled
    /// shading); GL 3.3 on llvmpipe has 32 units, so 32 and up are not there.
    FAR_SH_LAST = 18, shares METAL_ROUGH_MAP;
    /// The demo's views (src/demo: the inspector's `u_texture`, the shadow
    /// views' `u_map` and `u_layout`, the panel layer's `u_layer`), drawn in programs of
    /// their own after the frame.
    DEMO_VIEW = 0, shares DIFFUSE_TEXTURE, GBUFFER_NORMAL, POST_INPUT, IBL_BRDF_OFF,
        IBL_SOURCE, JOINT_TEXTURE, TERRAIN_HEIGHT, MIRROR_ROUGHNESS;
    /// The shadow views' cube map (`u_cube_map`), beside DEMO_VIEW.
    DEMO_VIEW_CUBE = 1, shares NORMAL_MAP, GBUFFER_ALBEDO, BLOOM_BLURS;
}

/// The far field's six harmonics units in the order the shader reads them.
pub const FAR_SH: [u32; 6] = [
    FAR_SH_FIRST,
    FAR_SH_FIRST + 1,
    FAR_SH_FIRST + 2,
    FAR_SH_FIRST + 3,
    FAR_SH_FIRST + 4,
    FAR_SH_LAST,
];
