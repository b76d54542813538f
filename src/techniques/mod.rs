//! Every technique of the course, one file each in its chapter's folder,
//! named as the notes name it. `ALL` is the registry: one line per
//! technique, in the order their passes run within a frame. The frame plan,
//! `gloss plan`, the bench and the demo all read this list; a technique
//! whose scene does not need it adds no pass (docs/adding-a-technique.md).
//!
//! A technique imports only what lies below it (src/frame, src/gl,
//! src/scene, src/geometry, src/lighting, src/math) and, at most, a technique
//! of its own chapter; never the renderer or another chapter's technique
//! (tests/architecture.rs checks it).

pub mod animation;
pub mod billboards;
pub mod blending;
pub mod deferred;
pub mod fragment_tests;
pub mod lighting;
pub mod post;
pub mod shadows;
pub mod sky;
pub mod stencil;
pub mod vertex_geometry;

use crate::frame::Technique;
use crate::frame::lights::FrameLights;
use crate::frame::plan::FramePlan;
use crate::scene::Scene;

/// The registry, in frame order.
pub static ALL: &[&Technique] = &[
    // First: every later pass draws the skinned meshes it poses.
    &animation::skinned_meshes::SKINNED_MESHES,
    &shadows::shadow_map::SHADOW_MAP,
    // A directional light's map split into cascades (shadow.cascades > 1).
    &shadows::cascaded_shadow_maps::CASCADED_SHADOW_MAPS,
    // Before the views too: the [sky] into the environment cube map.
    &sky::sky_cube_map::SKY_CUBE_MAP,
    &sky::image_based_lighting::IMAGE_BASED_LIGHTING,
    // The skybox before the opaque world (render.sky_first, for comparison).
    &sky::sky_first::SKY_FIRST,
    &lighting::forward::FORWARD,
    // Into forward's target, the opaque world exploded that forward skips
    // (render.explode).
    &vertex_geometry::exploding_objects::EXPLODING_OBJECTS,
    // Into forward's target, the objects with a height map that forward skips.
    &lighting::parallax_mapping::PARALLAX_MAPPING,
    &vertex_geometry::tessellation::TESSELLATION,
    &deferred::gbuffer::GBUFFER,
    &deferred::deferred_shading::DEFERRED_SHADING,
    &deferred::light_volumes::LIGHT_VOLUMES,
    &deferred::stencil_light_volumes::STENCIL_LIGHT_VOLUMES,
    &deferred::far_field::FAR_FIELD,
    &deferred::tiled_shading::TILED_SHADING,
    // The area lights' light, added to what the lighting pass accumulated
    // (the light pre-pass runs it as a step of its own).
    &deferred::ltc_area_lights_deferred::LTC_AREA_LIGHTS_DEFERRED,
    // After the lights, as notes 03 orders them; before the passes that
    // add the ambient term (the combine, the composite).
    &deferred::ambient_light::AMBIENT_LIGHT,
    &deferred::deferred_lighting::DEFERRED_LIGHTING,
    // Added to the accumulated light, before the composite reads it.
    &sky::skybox_reflection::SKYBOX_REFLECTION,
    &deferred::composite::COMPOSITE,
    // The area lights' rectangles, over the world every path shaded with
    // them, tested against its depth.
    &lighting::ltc_area_lights::LTC_AREA_LIGHTS,
    // Opaque rocks after every path's opaque world (its depth is in the
    // world target by now), before the mirrors and the sky.
    &vertex_geometry::instancing::INSTANCING,
    &stencil::mirror::MIRROR,
    &fragment_tests::viewports::VIEWPORTS,
    // The sky behind the opaque world, before what blends over it.
    &sky::sun_sky::SUN_SKY,
    &sky::skybox::SKYBOX,
    // Over the finished opaque world and the sky (the outline is drawn with
    // the depth test off, over the background too); under the glass.
    &stencil::object_outlines::OBJECT_OUTLINES,
    // A debug view over the finished opaque world and sky.
    &vertex_geometry::visualizing_normals::VISUALIZING_NORMALS,
    &billboards::billboards::BILLBOARDS,
    &vertex_geometry::particles::PARTICLES,
    &blending::transparency::TRANSPARENCY,
    // Or, as render.transparency chooses, one of these in its place.
    &blending::weighted_blended::WEIGHTED_BLENDED,
    &blending::depth_peeling::DEPTH_PEELING,
    // After every view: first the MSAA resolve (registered before the chain,
    // item 0: the plan's sort by entry is stable), then the post chain, in
    // the scene's [[post]] order.
    &fragment_tests::msaa::MSAA_RESOLVE,
    &post::blur::BLUR,
    &post::kernel::KERNEL,
    &post::color_filters::COLOR_FILTERS,
    &post::tone_mapping::TONE_MAPPING,
    &post::fxaa::FXAA,
    &post::gamma_correction::GAMMA_CORRECTION,
    &post::bloom::BLOOM,
];

/// The frame plan of `scene`: the registered techniques' passes and targets.
pub fn plan(scene: &Scene) -> FramePlan {
    FramePlan::new(scene, &FrameLights::new(scene), ALL)
}
