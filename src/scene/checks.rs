//! What every section of the scene file is checked with: finite numbers,
//! numbers not below 0, paths relative to the file; and the ranges the
//! render settings take (the knobs' sliders use the same). A leaf: the
//! feature files (lights.rs, mirrors.rs, views.rs, ...) and resolve.rs,
//! which calls them, import it, and it imports none of them.

use crate::assets;
use anyhow::{Result, bail};
use std::path::Path;

pub(super) fn finite(key: &str, v: &[f32]) -> Result<()> {
    if v.iter().any(|x| !x.is_finite()) {
        bail!("{key}: expected finite numbers, found {v:?}");
    }
    Ok(())
}

pub(super) fn non_negative(key: &str, v: &[f32]) -> Result<()> {
    finite(key, v)?;
    if v.iter().any(|x| *x < 0.0) {
        bail!("{key}: expected values >= 0, found {v:?}");
    }
    Ok(())
}

/// A path written in a scene file: relative to the file, unless it names a
/// shipped file (`embedded:scenes/...`, as "save as" writes for a shipped
/// scene's assets).
pub(super) fn relative_to(base: &Path, written: &str) -> std::path::PathBuf {
    if written.starts_with(assets::EMBEDDED) {
        std::path::PathBuf::from(written)
    } else {
        base.join(written)
    }
}

/// The deepest mirror recursion a scene may ask for: each level is another
/// pass over the world, and the stencil buffer's 8 bits count the levels.
pub const MAX_MIRROR_DEPTH: u32 = 8;

/// The tile edges `render.tile_size` takes, in pixels.
pub const TILE_SIZES: std::ops::RangeInclusive<u32> = 4..=256;
/// The far-field scales `render.far_field` takes besides 0 (off): one
/// sample per k x k pixels.
pub const FAR_FIELD_SCALES: std::ops::RangeInclusive<u32> = 1..=32;
/// The far lists' radii `render.far_radius` takes besides 0 (off), in
/// whole cutoff radii (src/techniques/deferred/far_lists.rs).
pub const FAR_RADII: std::ops::RangeInclusive<u32> = 1..=64;

/// `render.far_radius`: 0 (off) or in FAR_RADII.
pub(super) fn far_radius(a: u32) -> Result<u32> {
    if a != 0 && !FAR_RADII.contains(&a) {
        bail!(
            "render.far_radius: expected 0 (off) or the far lists' radius in whole cutoff radii, 1 to 64, found {a}"
        );
    }
    Ok(a)
}

/// The depth slices `render.depth_slices` takes (1: tiled, no slicing).
pub const DEPTH_SLICES: std::ops::RangeInclusive<u32> = 1..=64;

/// The layers `render.peel_layers` takes (depth peeling: one pass over the
/// transparent objects per layer).
pub const PEEL_LAYERS: std::ops::RangeInclusive<u32> = 1..=64;

/// The layers `render.parallax_layers` takes (steep and occlusion parallax).
pub const PARALLAX_LAYERS: std::ops::RangeInclusive<u32> = 1..=256;

/// The sample counts `render.msaa` takes.
pub const MSAA_SAMPLES: [u32; 4] = [1, 2, 4, 8];

/// The camera's defaults in the scene file (file.rs's `[camera]`).
pub(super) fn default_fov() -> f32 {
    50.0
}
pub(super) fn default_near() -> f32 {
    0.1
}
pub(super) fn default_far() -> f32 {
    100.0
}
