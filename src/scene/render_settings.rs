//! The `[render]` table, checked: each setting's range, and the error that
//! names the key and what it takes.

use super::checks::non_negative;
use super::file::SceneFile;
use super::settings::{
    Accumulation, BillboardMode, DeferredLights, DepthFunc, Falloff, JointStorage, MirrorOrder,
    RenderPath, Shading, SkinningOn,
};
use super::texturing::{FilterOverride, Interpolation};
use anyhow::{Result, bail};
use glam::Vec3;

pub use super::checks::{
    DEPTH_SLICES, FAR_FIELD_SCALES, MAX_MIRROR_DEPTH, MSAA_SAMPLES, PARALLAX_LAYERS, PEEL_LAYERS,
    TILE_SIZES,
};

/// Render settings (the `[render]` table).
pub(super) fn render_settings(f: &SceneFile) -> Result<RenderSettings> {
    let r = &f.render;
    Ok(RenderSettings {
        path: r.path,
        shading: r.shading,
        size: {
            let [w, h] = r.size;
            if !(1..=8192).contains(&w) || !(1..=8192).contains(&h) {
                bail!("render.size: expected [width, height] in 1..=8192, found [{w}, {h}]");
            }
            (w, h)
        },
        background: {
            non_negative("render.background", &r.background)?;
            Vec3::from(r.background)
        },
        ambient: {
            non_negative("render.ambient", &r.ambient)?;
            Vec3::from(r.ambient)
        },
        depth_func: r.depth_func,
        cutoff: {
            if !(r.cutoff.is_finite() && r.cutoff > 0.0 && r.cutoff < 1.0) {
                bail!(
                    "render.cutoff: expected a fraction in (0, 1), found {}",
                    r.cutoff
                );
            }
            r.cutoff
        },
        stencil_volumes: r.stencil_volumes,
        accumulation: r.accumulation,
        falloff: r.falloff,
        deferred_lights: r.deferred_lights,
        tile_size: {
            if !(TILE_SIZES).contains(&r.tile_size) {
                bail!(
                    "render.tile_size: expected a tile edge of {}..={} pixels, found {}",
                    TILE_SIZES.start(),
                    TILE_SIZES.end(),
                    r.tile_size
                );
            }
            r.tile_size
        },
        far_field: {
            if r.far_field != 0 && !FAR_FIELD_SCALES.contains(&r.far_field) {
                bail!(
                    "render.far_field: expected 0 (off) or one sample per k x k pixels, k in {}..={}, found {}",
                    FAR_FIELD_SCALES.start(),
                    FAR_FIELD_SCALES.end(),
                    r.far_field
                );
            }
            r.far_field
        },
        far_field_bound: false,
        far_coarse_tolerance: 0.5 / 255.0,
        far_field_sh: r.far_field_sh,
        near_radius: {
            if !(r.near_radius.is_finite() && r.near_radius > 0.0 && r.near_radius <= 1.0) {
                bail!(
                    "render.near_radius: expected the near part's end as a fraction of each light's cutoff radius, in (0, 1], found {}",
                    r.near_radius
                );
            }
            r.near_radius
        },
        far_radius: super::checks::far_radius(r.far_radius)?,
        depth_slices: {
            if !(DEPTH_SLICES).contains(&r.depth_slices) {
                bail!(
                    "render.depth_slices: expected {}..={} depth slices (1: tiles only), found {}",
                    DEPTH_SLICES.start(),
                    DEPTH_SLICES.end(),
                    r.depth_slices
                );
            }
            r.depth_slices
        },
        mirror_order: r.mirror_order,
        mirror_depth: {
            if !(1..=MAX_MIRROR_DEPTH).contains(&r.mirror_depth) {
                bail!(
                    "render.mirror_depth: expected 1..={MAX_MIRROR_DEPTH} mirrors deep, found {}",
                    r.mirror_depth
                );
            }
            r.mirror_depth
        },
        mirror_clip: r.mirror_clip,
        mirror_winding: r.mirror_winding,
        billboards: r.billboards,
        billboard_alpha_ref: {
            let a = r.billboard_alpha_ref;
            if !(a.is_finite() && (0.0..=1.0).contains(&a)) {
                bail!("render.billboard_alpha_ref: expected a number in 0..=1, found {a}");
            }
            a
        },
        sort_transparent: r.sort_transparent,
        transparency: r.transparency,
        peel_layers: {
            if !(PEEL_LAYERS).contains(&r.peel_layers) {
                bail!(
                    "render.peel_layers: expected {}..={} layers, found {}",
                    PEEL_LAYERS.start(),
                    PEEL_LAYERS.end(),
                    r.peel_layers
                );
            }
            r.peel_layers
        },
        sort_opaque: r.sort_opaque,
        specialize: r.specialize,
        light_block: r.light_block,
        light_data: {
            use super::light_data::LightData;
            if r.light_block && !matches!(r.light_data, LightData::Texture | LightData::Block) {
                bail!(
                    "render.light_block = true asks for the uniform block, render.light_data = \"{}\" for another form: give one (light_block is the older name of light_data = \"block\")",
                    r.light_data
                );
            }
            r.light_data
        },
        post_chain: r.post_chain,
        msaa: {
            if !MSAA_SAMPLES.contains(&r.msaa) {
                bail!(
                    "render.msaa: expected 1, 2, 4 or 8 samples per pixel (1: no MSAA), found {}",
                    r.msaa
                );
            }
            if r.msaa > 1
                && r.path == RenderPath::Forward
                && r.transparency != super::settings::Transparency::Sorted
            {
                bail!(
                    "render.transparency = \"{}\" draws into single-sampled targets: set render.msaa = 1, or render.transparency = \"sorted\"",
                    r.transparency
                );
            }
            r.msaa
        },
        frustum_culling: r.frustum_culling,
        wireframe: r.wireframe,
        outlines: r.outlines,
        instancing: r.instancing,
        show_normals: r.show_normals,
        normal_length: {
            if !(r.normal_length.is_finite() && r.normal_length > 0.0 && r.normal_length <= 100.0) {
                bail!(
                    "render.normal_length: expected a length in world units, > 0 and <= 100, found {}",
                    r.normal_length
                );
            }
            r.normal_length
        },
        explode: r.explode,
        explode_magnitude: {
            let m = r.explode_magnitude;
            if !(m.is_finite() && (0.0..=100.0).contains(&m)) {
                bail!(
                    "render.explode_magnitude: expected a distance in world units, >= 0 and <= 100, found {m}"
                );
            }
            m
        },
        outline_width: {
            let widths = super::outlines::OUTLINE_WIDTHS;
            if !widths.contains(&r.outline_width) {
                bail!(
                    "render.outline_width: expected {}..={} pixels, found {}",
                    widths.start(),
                    widths.end(),
                    r.outline_width
                );
            }
            r.outline_width
        },
        skinning_on: r.skinning_on,
        joint_storage: r.joint_storage,
        texture_filter: r.texture_filter,
        interpolation: r.interpolation,
        mip_colors: r.mip_colors,
        normal_mapping: r.normal_mapping,
        parallax: r.parallax,
        parallax_layers: {
            if !PARALLAX_LAYERS.contains(&r.parallax_layers) {
                bail!(
                    "render.parallax_layers: expected {}..={} layers, found {}",
                    PARALLAX_LAYERS.start(),
                    PARALLAX_LAYERS.end(),
                    r.parallax_layers
                );
            }
            r.parallax_layers
        },
        parallax_shadows: r.parallax_shadows,
        parallax_uv: r.parallax_uv,
        light_maps: r.light_maps,
        sky_first: r.sky_first,
        ibl: r.ibl,
        area_lights: r.area_lights,
        area_light_reference: r.area_light_reference,
        area_light_points: super::area_lights::reference_points(r.area_light_points)?,
        ambient_occlusion: super::ambient_occlusion::resolve(f.ambient_occlusion.as_ref())?,
        gbuffer_encoding: r.gbuffer_encoding,
        gbuffer: r.gbuffer,
        hardware_srgb: r.hardware_srgb,
        gbuffer_slim: r.gbuffer_slim,
    })
}

/// The `[render]` table, resolved and checked (src/scene/resolve.rs).
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    pub path: RenderPath,
    pub shading: Shading,
    pub size: (u32, u32),
    pub background: glam::Vec3,
    pub ambient: glam::Vec3,
    /// GL_LESS (notes 02: "fails when d >= D") or GL_LEQUAL (notes 01: "passes when z <= D").
    pub depth_func: DepthFunc,
    /// Light-volume cutoff, a fraction of the light's brightest channel (notes 04: 5/256).
    pub cutoff: f32,
    /// Light volumes: use the two-sided stencil test to mark lit pixels first.
    pub stencil_volumes: bool,
    /// Internal format of the light accumulation target (RGBA16F or RGBA32F).
    pub accumulation: Accumulation,
    /// How point and spot lights' attenuation ends: the notes' model, or a
    /// windowed one that reaches 0 at the cutoff radius.
    pub falloff: Falloff,
    /// The deferred path: a pass per light, or one pass over all of them.
    pub deferred_lights: DeferredLights,
    /// Tiled shading: the screen tile's edge in pixels, and how many depth
    /// slices cut the view (1: tiles only; more: clustered shading).
    pub tile_size: u32,
    pub depth_slices: u32,
    /// Tiled shading: 0, every light stops at its cutoff radius; k, the light
    /// beyond half that radius comes from a far field evaluated once per k x k
    /// pixels (src/techniques/deferred/far_field.rs).
    pub far_field: u32,
    /// Not in the scene file: `gloss bench` sets it to render, instead of
    /// the light, the far field's per-pixel error bound (far_field.rs).
    pub far_field_bound: bool,
    /// Tiled shading's far field stores the diffuse far light as order-2
    /// spherical harmonics, which every pixel evaluates for its own normal
    /// (glsl/common/far_field_sh.glsl).
    pub far_field_sh: bool,
    /// With the far field: where each light's near part ends, as a fraction
    /// of its cutoff radius (1: at the radius); tiled shading bins at it.
    pub near_radius: f32,
    /// With the far field: 0, or the far lists' radius a (0 or 1..=64;
    /// src/techniques/deferred/far_lists.rs).
    pub far_radius: u32,
    /// Not in the scene file: how far off a coarse part a far-list pixel takes.
    pub far_coarse_tolerance: f32,
    /// Planar mirrors (notes 05): the order of their passes, how deep
    /// reflections recurse, the clip plane and the winding fix (toggles that
    /// show what goes wrong without them).
    pub mirror_order: MirrorOrder,
    pub mirror_depth: u32,
    pub mirror_clip: bool,
    pub mirror_winding: bool,
    /// How billboards are drawn: alpha test, blending, or sorted blending (notes 05).
    pub billboards: BillboardMode,
    /// The billboards' alpha test passes alpha >= this (notes 05: 0.5).
    pub billboard_alpha_ref: f32,
    /// Draw transparent objects back to front (notes 01 §6.1); false shows
    /// what goes wrong unsorted.
    pub sort_transparent: bool,
    /// How transparent objects are drawn: sorted per object (the notes),
    /// weighted blended OIT, or depth peeling of `peel_layers` layers.
    pub transparency: super::settings::Transparency,
    pub peel_layers: u32,
    /// Draw opaque objects nearest first (notes 01 §6.2), so that the depth
    /// test rejects hidden fragments before they are shaded.
    pub sort_opaque: bool,
    /// Compile the lighting passes' shaders for what the scene holds (its
    /// light types, falloff, shadows, materials: src/frame/variant.rs);
    /// false: the general shader, every part evaluated for every light.
    pub specialize: bool,
    /// With `specialize`: tiled shading and the far field read the lights
    /// from the `Lights` uniform block when every light fits in it on every
    /// GL (256), instead of the buffer texture (src/frame/variant.rs). Off
    /// by default: on llvmpipe the two measured the same.
    pub light_block: bool,
    /// Where tiled shading and the far field read the lights: a buffer
    /// texture of floats, the uniform block (as `light_block`), or packed
    /// halves (src/frame/light_halves.rs). With `specialize` only.
    pub light_data: super::light_data::LightData,
    /// How the post chain passes its image along (src/scene/post.rs).
    pub post_chain: super::post::ChainForm,
    /// Samples per pixel (MSAA) of the world on the forward path: 1, 2, 4
    /// or 8 (src/techniques/fragment_tests/msaa.rs); 1 is no MSAA.
    pub msaa: u32,
    /// Draw only the opaque objects inside the view's frustum (notes 01 §6.3).
    pub frustum_culling: bool,
    /// The forward and G-buffer passes draw triangles' edges only
    /// (glPolygonMode(GL_FRONT_AND_BACK, GL_LINE)): where the clipper cut them.
    pub wireframe: bool,
    /// Draw the scene's `[outlines]` (src/techniques/stencil/object_outlines.rs),
    /// `outline_width` pixels wide.
    pub outlines: bool,
    pub outline_width: u32,
    /// The `[instancing]` rocks in one glDrawElementsInstanced (true) or
    /// one glDrawElements per rock (src/techniques/vertex_geometry/instancing.rs).
    pub instancing: bool,
    /// Draw every opaque object's vertex normals, `normal_length` long, as
    /// lines a geometry shader makes (src/techniques/vertex_geometry/visualizing_normals.rs).
    pub show_normals: bool,
    pub normal_length: f32,
    /// Draw the opaque objects exploded (forward path, Phong shading): a
    /// geometry shader moves each triangle along its face normal by
    /// `explode_magnitude` x (sin(t) + 1) / 2 at the scene's time t
    /// (src/techniques/vertex_geometry/exploding_objects.rs).
    pub explode: bool,
    pub explode_magnitude: f32,
    /// Where skinned meshes are skinned: the GPU pass, or the CPU reference.
    pub skinning_on: SkinningOn,
    /// Where the skinning pass reads the joint matrices from.
    pub joint_storage: JointStorage,
    /// Every material's texture filter, or one for all (notes 01 §5.2-5.3.1).
    pub texture_filter: FilterOverride,
    /// Texture coordinates perspective-correct, or affine (notes 01 §5.1).
    pub interpolation: Interpolation,
    /// Textures read a twin whose mip levels are flat colours: which level
    /// lambda picks, pixel by pixel (notes 01 §5.3).
    pub mip_colors: bool,
    /// Materials with a normal map perturb their normals with it (notes 01 §8.4).
    pub normal_mapping: bool,
    /// Parallax mapping of materials with a height map (lighting/parallax_mapping.rs):
    /// the method, the layers a ray is marched through, self-shadowing, and
    /// the debug view that colours each pixel by the uv its ray hits.
    pub parallax: super::settings::Parallax,
    pub parallax_layers: u32,
    pub parallax_shadows: bool,
    pub parallax_uv: bool,
    /// Objects with a light map draw it instead of their light loop (notes 01 §8.2).
    pub light_maps: bool,
    /// Draw the skybox first, before the opaque world, with the depth test
    /// off, instead of last at z = w (notes 03, Implementation; forward only).
    pub sky_first: bool,
    /// The ambient term from the environment cube map (Karis 2013's
    /// image-based lighting: irradiance, prefiltered specular, split-sum
    /// table) instead of the constant `ambient` (src/frame/image_based_lighting.rs).
    pub ibl: bool,
    /// Shade and draw the `[[area_lights]]` (LTC, lighting/ltc_area_lights.rs).
    pub area_lights: bool,
    /// LTC, or the quadrature reference it is measured against
    /// (glsl/lighting/area_light_reference.glsl), with N x N points per
    /// triangle of each light (`area_light_points`).
    pub area_light_reference: super::area_lights::AreaLightReference,
    pub area_light_points: u32,
    /// `[ambient_occlusion]`: SSAO on the G-buffer paths (notes 03, Ambient
    /// Light; src/scene/ambient_occlusion.rs). None: the ambient term unoccluded.
    pub ambient_occlusion: Option<super::ambient_occlusion::AmbientOcclusion>,
    /// How the G-buffer holds the microfacet triple (notes 03, Geometry Pass).
    pub gbuffer_encoding: super::settings::GBufferEncoding,
    /// How the G-buffer holds the normal and shininess (src/frame/gbuffer.rs).
    pub gbuffer: super::settings::GBufferNormals,
    /// The composite writes linear light into an SRGB8_ALPHA8 output with
    /// GL_FRAMEBUFFER_SRGB on, where the frame allows (src/frame/plan.rs
    /// `hardware_srgb`); false: pow() in the shader, as every other pass.
    pub hardware_srgb: bool,
    /// Leave the specular attachment out of the G-buffer when every opaque
    /// material has the same specular colour (src/frame/gbuffer_slim.rs);
    /// false: always the full G-buffer.
    pub gbuffer_slim: bool,
}

impl RenderSettings {
    /// Whether the exploding-objects pass draws the opaque world (the
    /// forward pass then skips it): `explode` on the forward path with
    /// Phong shading (src/techniques/vertex_geometry/exploding_objects.rs).
    pub fn explodes(&self) -> bool {
        self.explode && self.path == RenderPath::Forward && self.shading == Shading::Phong
    }
}
