//! Deferred rendering (notes 01 §8.6, notes 02, notes 04): the G-buffer,
//! lighting with a full-screen pass per light or with light volumes (plain
//! or stencil-tested) or with lights binned per screen tile (tiled shading),
//! the composite pass, and deferred lighting (the light
//! pre-pass).
//!
//! | path     | 1. fill G-buffer | 2. lighting                            | 3. final image       |
//! |----------|------------------|----------------------------------------|----------------------|
//! | deferred | gbuffer.rs       | deferred_shading.rs (full screen)      | composite.rs         |
//! | volumes  | gbuffer.rs       | light_volumes.rs / stencil_light_volumes.rs | composite.rs    |
//! | prepass  | gbuffer.rs, thin | deferred_lighting.rs (volumes)         | deferred_lighting.rs |
//! | tiled    | gbuffer.rs       | tiled_shading.rs (lights binned per tile), far_field.rs (the tails, at low resolution) | composite.rs |
//!
//! On every path the `[[area_lights]]` add their light after step 2
//! (ltc_area_lights_deferred.rs).

pub mod ambient_light;
pub mod composite;
pub mod deferred_lighting;
pub mod deferred_lighting_combine;
pub mod deferred_shading;
pub mod far_field;
pub mod far_lists;
pub mod gbuffer;
pub mod light_volumes;
pub mod ltc_area_lights_deferred;
pub mod stencil_light_volumes;
pub mod tiled_shading;
