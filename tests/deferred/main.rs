//! Invariants between the render paths on the shipped scenes:
//!
//! * deferred shading == forward: at most 0.5% of pixels differ by more than
//!   1/255 and none by more than 6/255 (sRGB 8-bit output). The residue is the
//!   G-buffer's precision: RGBA16F normals (relative error 2^-11) raised to a
//!   shininess of up to 96 in a highlight, and 8-bit sRGB albedo.
//! * light pre-pass == forward: the same 0.5% / 1/255 bound; and at most 0.02%
//!   of pixels off by more than 8/255: its second geometry pass tests depth
//!   with GL_LEQUAL, so where two surfaces fall within one 24-bit depth step
//!   the later one wins (docs/deferred/deferred_lighting.md).
//! * light volumes == full-screen deferred within the cutoff bound: per
//!   channel, (number of bounded lights) x cutoff x (kd + ks) in linear light;
//!   with a tiny cutoff, within 1/255.
//! * camera inside a light volume; spot cones cover their lit region; the
//!   stencil volume test gives the same image; `gloss plan` lists the passes.
//! * tiled shading == light volumes at the same cutoff, for every tile size
//!   and slice count (both summed in RGBA32F: within 1/255); with a tiny
//!   cutoff, == forward within the deferred bound; 10,000 lights == the sum
//!   of their parts.
//! * with the windowed falloff, light volumes and tiled shading == forward
//!   within the deferred bound (the cutoff drops nothing).
//! * tiled shading with the far field: one sample per pixel == forward within
//!   the deferred bound; one per 4x4 or 8x8 pixels within FAR_BOUND.
//!
//! * the slim G-buffer (no specular attachment when every material shares
//!   one specular colour) draws every path's image byte for byte as the
//!   full one (slim_gbuffer.rs).
//! * area lights (LTC) on every G-buffer path == forward within 2/255 and
//!   0.05 % of pixels over 1/255 (ltc_area_lights_deferred.rs).
//!
//! Every render runs with GL debug output on and fails on any GL error.

#[path = "../common/mod.rs"]
mod common;

mod ambient_light;
mod composite_programs;
mod deferred_lighting;
mod deferred_shading;
mod far_field;
mod far_field_sh;
mod far_lists;
mod gbuffer_material_variant;
mod hardware_srgb;
mod light_halves;
mod light_volumes;
mod ltc_area_lights_deferred;
mod numeric_edges;
mod numeric_sweep;
mod packed_gbuffer;
mod shader_variants;
mod shader_variants_paths;
mod slim_gbuffer;
mod stencil_light_volumes;
mod tiled_shading;
mod windowed_falloff;

use gloss::image_compare::Tolerance;
use gloss::scene::{RenderPath, Scene};

pub fn with_path(scene: &Scene, path: RenderPath) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    s
}

pub const DEFERRED_BOUND: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.005,
    max_abs: Some(6.0 / 255.0),
};
