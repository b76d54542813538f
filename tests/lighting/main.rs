//! The lighting chapter (notes 01 §8, notes 04 "Forward rendering"): one
//! module per technique file under src/techniques/lighting/.

#[path = "../common/mod.rs"]
mod common;

mod area_light_reference;
mod bump_mapping;
mod forward;
mod gouraud;
mod ltc_area_lights;
mod microfacet;
mod parallax_mapping;
mod static_lighting;
