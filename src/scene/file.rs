//! The scene file format, exactly as written in TOML (scenes/*.toml), with
//! serde's defaults for every key that may be left out. `resolve` checks these
//! values and turns them into a `Scene`.

use super::billboards::{BillboardFieldFile, BillboardFile};
use super::light_grid::LightGrid;
use super::mirrors::MirrorFile;
use super::settings::{
    Accumulation, AlphaTest, BillboardMode, Cull, DeferredLights, DepthFunc, Falloff, MirrorOrder,
    RenderPath, Shading,
};
use serde::Deserialize;
use std::collections::HashMap;

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    pub(super) name: Option<String>,
    pub(super) camera: CameraFile,
    /// Split views (src/scene/views.rs).
    #[serde(default)]
    pub(super) views: Vec<ViewFile>,
    #[serde(default)]
    pub(super) render: RenderFile,
    #[serde(default)]
    pub(super) lights: Vec<LightFile>,
    #[serde(default)]
    pub(super) area_lights: Vec<super::area_lights::AreaLightFile>,
    pub(super) light_grid: Option<LightGrid>,
    #[serde(default)]
    pub(super) materials: HashMap<String, MaterialFile>,
    #[serde(default)]
    pub(super) objects: Vec<ObjectFile>,
    /// Planes that cut the world open (src/scene/clip_planes.rs).
    #[serde(default)]
    pub(super) clip_planes: Vec<super::clip_planes::ClipPlaneFile>,
    pub(super) sky: Option<super::sky::SkyFile>,
    /// The cube map behind the world (src/scene/skybox.rs).
    pub(super) skybox: Option<super::skybox::SkyboxFile>,
    /// Screen-space ambient occlusion (src/scene/ambient_occlusion.rs).
    pub(super) ambient_occlusion: Option<super::ambient_occlusion::AmbientOcclusionFile>,
    /// Seeded groups of objects (src/scene/object_fields.rs).
    #[serde(default)]
    pub(super) object_fields: Vec<super::object_field_file::ObjectFieldFile>,
    #[serde(default)]
    pub(super) billboards: Vec<BillboardFile>,
    #[serde(default)]
    pub(super) billboard_fields: Vec<BillboardFieldFile>,
    /// The post chain's entries, each checked by src/scene/post.rs.
    #[serde(default)]
    pub(super) post: Vec<toml::Table>,
    /// Keyframe tracks and the instant shown (src/scene/animation.rs).
    #[serde(default)]
    pub(super) animation: super::animation::AnimationFile,
    /// A tessellated terrain (src/scene/tessellation.rs).
    pub(super) tessellation: Option<super::tessellation::TessellationFile>,
    /// A particle fountain (src/scene/particles.rs).
    pub(super) particles: Option<super::particles::ParticlesFile>,
    /// Outlined objects (src/scene/outlines.rs).
    pub(super) outlines: Option<super::outlines::OutlinesFile>,
    /// A field of instanced rocks (src/scene/instancing.rs).
    pub(super) instancing: Option<super::instancing::InstancingFile>,
}

/// One `[[views]]` entry.
#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct ViewFile {
    pub(super) name: Option<String>,
    pub(super) viewport: [f32; 4],
    pub(super) camera: Option<CameraFile>,
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraFile {
    #[serde(default = "perspective_str")]
    pub(super) projection: String,
    pub(super) eye: [f32; 3],
    pub(super) target: [f32; 3],
    #[serde(default = "up_y")]
    pub(super) up: [f32; 3],
    #[serde(default = "super::checks::default_fov")]
    pub(super) fov_y: f32,
    /// Orthographic: half the height of the view box (width follows the aspect).
    pub(super) half_height: Option<f32>,
    #[serde(default = "super::checks::default_near")]
    pub(super) near: f32,
    #[serde(default = "super::checks::default_far")]
    pub(super) far: f32,
}

fn perspective_str() -> String {
    "perspective".into()
}
fn up_y() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields, default)]
pub(super) struct RenderFile {
    pub(super) path: RenderPath,
    pub(super) shading: Shading,
    pub(super) size: [u32; 2],
    pub(super) background: [f32; 3],
    pub(super) ambient: [f32; 3],
    pub(super) depth_func: DepthFunc,
    pub(super) cutoff: f32,
    pub(super) stencil_volumes: bool,
    pub(super) accumulation: Accumulation,
    pub(super) falloff: Falloff,
    pub(super) deferred_lights: DeferredLights,
    pub(super) tile_size: u32,
    pub(super) depth_slices: u32,
    pub(super) far_field: u32,
    pub(super) far_field_sh: bool,
    pub(super) near_radius: f32,
    pub(super) far_radius: u32,
    pub(super) mirror_order: MirrorOrder,
    /// How many mirrors deep reflections go (1: mirrors seen in a mirror are blank).
    pub(super) mirror_depth: u32,
    /// Cut away what lies behind a mirror in its reflection (GL_CLIP_DISTANCE0).
    pub(super) mirror_clip: bool,
    /// glFrontFace(GL_CW) while drawing a reflection (it reverses the winding).
    pub(super) mirror_winding: bool,
    pub(super) billboards: BillboardMode,
    pub(super) billboard_alpha_ref: f32,
    pub(super) sort_transparent: bool,
    pub(super) transparency: super::settings::Transparency,
    pub(super) peel_layers: u32,
    pub(super) sort_opaque: bool,
    /// Lighting shaders specialised to what the scene holds (src/frame/variant.rs).
    pub(super) specialize: bool,
    /// The older `light_data = "block"` (src/frame/variant.rs).
    pub(super) light_block: bool,
    /// Texture, block or packed halves (src/frame/light_halves.rs).
    pub(super) light_data: super::light_data::LightData,
    pub(super) post_chain: super::settings::ChainForm,
    /// Samples per pixel on the forward path (1: no MSAA).
    pub(super) msaa: u32,
    pub(super) frustum_culling: bool,
    pub(super) wireframe: bool,
    /// Draw the `[outlines]` (src/scene/outlines.rs), this many pixels wide.
    pub(super) outlines: bool,
    pub(super) outline_width: u32,
    /// Draw the `[instancing]` field with one instanced draw (false: one draw per rock).
    pub(super) instancing: bool,
    /// Geometry shaders: vertex normals drawn as lines; exploding objects.
    pub(super) show_normals: bool,
    pub(super) normal_length: f32,
    pub(super) explode: bool,
    pub(super) explode_magnitude: f32,
    pub(super) skinning_on: super::settings::SkinningOn,
    pub(super) joint_storage: super::settings::JointStorage,
    pub(super) texture_filter: super::texturing::FilterOverride,
    pub(super) interpolation: super::texturing::Interpolation,
    pub(super) mip_colors: bool,
    pub(super) normal_mapping: bool,
    /// Parallax mapping of materials with a height_map (lighting/parallax_mapping.rs).
    pub(super) parallax: super::settings::Parallax,
    pub(super) parallax_layers: u32,
    pub(super) parallax_shadows: bool,
    pub(super) parallax_uv: bool,
    pub(super) light_maps: bool,
    /// Draw the skybox before the opaque world, depth test off (forward only).
    pub(super) sky_first: bool,
    /// Image-based lighting as the ambient term (src/frame/image_based_lighting.rs).
    pub(super) ibl: bool,
    pub(super) area_lights: bool,
    pub(super) area_light_reference: super::area_lights::AreaLightReference,
    pub(super) area_light_points: u32,
    pub(super) gbuffer_encoding: super::settings::GBufferEncoding,
    pub(super) gbuffer: super::settings::GBufferNormals,
    pub(super) hardware_srgb: bool,
    pub(super) gbuffer_slim: bool,
}

impl Default for RenderFile {
    fn default() -> Self {
        RenderFile {
            path: RenderPath::Forward,
            shading: Shading::Phong,
            size: [1280, 720],
            background: [0.0, 0.0, 0.0],
            ambient: [0.03, 0.03, 0.03],
            depth_func: DepthFunc::Less,
            cutoff: 5.0 / 256.0,
            stencil_volumes: false,
            accumulation: Accumulation::Rgba16f,
            falloff: Falloff::Notes,
            deferred_lights: DeferredLights::PerLight,
            tile_size: 16,
            depth_slices: 16,
            far_field: 0,
            far_field_sh: false,
            near_radius: 1.0,
            far_radius: 0,
            mirror_order: MirrorOrder::NormalFirst,
            mirror_depth: 1,
            mirror_clip: true,
            mirror_winding: true,
            billboards: BillboardMode::AlphaTest,
            billboard_alpha_ref: 0.5,
            sort_transparent: true,
            transparency: super::settings::Transparency::Sorted,
            peel_layers: 8,
            sort_opaque: true,
            specialize: true,
            light_block: false,
            light_data: super::light_data::LightData::Texture,
            post_chain: super::settings::ChainForm::PingPong,
            msaa: 1,
            frustum_culling: true,
            wireframe: false,
            outlines: true,
            outline_width: 4,
            instancing: true,
            show_normals: false,
            normal_length: 0.2,
            explode: false,
            explode_magnitude: 0.5,
            skinning_on: super::settings::SkinningOn::Gpu,
            joint_storage: super::settings::JointStorage::Auto,
            texture_filter: super::texturing::FilterOverride::Material,
            interpolation: super::texturing::Interpolation::Perspective,
            mip_colors: false,
            normal_mapping: true,
            parallax: super::settings::Parallax::Occlusion,
            parallax_layers: 32,
            parallax_shadows: true,
            parallax_uv: false,
            light_maps: true,
            sky_first: false,
            ibl: false,
            area_lights: true,
            area_light_reference: super::area_lights::AreaLightReference::Off,
            area_light_points: 32,
            gbuffer_encoding: super::settings::GBufferEncoding::PlainRgba16f,
            gbuffer: super::settings::GBufferNormals::Rgba16f,
            hardware_srgb: true,
            gbuffer_slim: true,
        }
    }
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct LightFile {
    #[serde(rename = "type")]
    pub(super) kind: String,
    pub(super) position: Option<[f32; 3]>,
    pub(super) direction: Option<[f32; 3]>,
    #[serde(default = "white")]
    pub(super) color: [f32; 3],
    #[serde(default = "one")]
    pub(super) intensity: f32,
    /// [Kc, Kl, Kq]; notes 04's defaults.
    #[serde(default = "default_attenuation")]
    pub(super) attenuation: [f32; 3],
    /// Spot cone, degrees from the axis (notes 04: 20 and 30).
    #[serde(default = "spot_inner")]
    pub(super) inner_angle: f32,
    #[serde(default = "spot_outer")]
    pub(super) outer_angle: f32,
    /// `true`, or a table of shadow-map knobs (src/scene/shadows.rs).
    pub(super) shadow: Option<toml::Value>,
    /// Lmax of the linear falloff (`render.falloff = "linear"`).
    pub(super) range: Option<f32>,
}

fn white() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}
fn one() -> f32 {
    1.0
}
fn default_attenuation() -> [f32; 3] {
    [1.0, 0.09, 0.032]
}
fn spot_inner() -> f32 {
    20.0
}
fn spot_outer() -> f32 {
    30.0
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct MaterialFile {
    #[serde(default = "grey")]
    pub(super) diffuse: [f32; 3],
    pub(super) diffuse_texture: Option<String>,
    /// A tangent-space normal map (notes 01 §8.4), loaded as linear data.
    pub(super) normal_map: Option<String>,
    /// A height map (white high), for parallax mapping; its relief's depth in uv units.
    pub(super) height_map: Option<String>,
    pub(super) height_scale: Option<f32>,
    #[serde(default = "spec_default")]
    pub(super) specular: [f32; 3],
    #[serde(default = "shininess_default")]
    pub(super) shininess: f32,
    /// "phong" (the default) or "microfacet", with notes 03's triple (src/scene/material.rs).
    pub(super) model: Option<super::settings::Model>,
    pub(super) alpha: Option<f32>,
    pub(super) eta: Option<f32>,
    pub(super) k_s: Option<f32>,
    /// The alpha test on the diffuse texture's alpha (notes 05, "Alpha Test").
    #[serde(default = "always")]
    pub(super) alpha_test: AlphaTest,
    #[serde(default = "half")]
    pub(super) alpha_ref: f32,
    /// 1 = opaque; below 1 the object is transparent (notes 01 §4.5, §6.1).
    #[serde(default = "one")]
    pub(super) opacity: f32,
    /// How much of the environment it mirrors, 0..=1 (src/scene/skybox.rs).
    #[serde(default)]
    pub(super) reflectivity: f32,
    /// Overrides `render.depth_func` for this material's objects.
    pub(super) depth_func: Option<DepthFunc>,
    /// The faces its objects cull: back (the default), front, front_and_back, none.
    #[serde(default)]
    pub(super) cull: Option<Cull>,
    /// Which winding is a front face: "ccw" (the default) or "cw".
    pub(super) winding: Option<super::settings::Winding>,
    /// How it is sampled (src/scene/texturing.rs): wrap, filter, anisotropy, uv transform.
    pub(super) wrap: Option<toml::Value>,
    pub(super) filter: Option<super::texturing::TextureFilter>,
    pub(super) anisotropy: Option<f32>,
    pub(super) max_lod: Option<f32>,
    pub(super) uv_scale: Option<[f32; 2]>,
    pub(super) uv_offset: Option<[f32; 2]>,
}

fn always() -> AlphaTest {
    AlphaTest::Always
}
fn half() -> f32 {
    0.5
}

fn grey() -> [f32; 3] {
    [0.6, 0.6, 0.6]
}
pub(super) fn spec_default() -> [f32; 3] {
    [0.3, 0.3, 0.3]
}
pub(super) fn shininess_default() -> f32 {
    32.0
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub(super) struct ObjectFile {
    pub(super) name: Option<String>,
    pub(super) mesh: String,
    pub(super) material: Option<String>,
    #[serde(default)]
    pub(super) position: [f32; 3],
    /// Degrees about x, then y, then z.
    #[serde(default)]
    pub(super) rotation: [f32; 3],
    #[serde(default = "unit_scale")]
    pub(super) scale: [f32; 3],
    pub(super) parent: Option<String>,
    /// This object is a planar mirror (src/scene/mirrors.rs).
    pub(super) mirror: Option<MirrorFile>,
    /// A skinned glTF mesh: how its vertices follow the joints.
    pub(super) skinning: Option<super::settings::SkinMethod>,
    /// A skinned glTF mesh: the animation that poses it (default: the file's first; "none": rest).
    pub(super) clip: Option<String>,
    /// Static lighting (notes 01 §8.2): bake the lights into a light map over the uvs on load.
    pub(super) light_map: Option<LightMapFile>,
}

/// `light_map = { size = 256, shadows = true }` on an object.
#[derive(Deserialize, Debug, Clone, Copy)]
#[serde(deny_unknown_fields)]
pub(super) struct LightMapFile {
    pub(super) size: u32,
    #[serde(default)]
    pub(super) shadows: bool,
}

fn unit_scale() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}
