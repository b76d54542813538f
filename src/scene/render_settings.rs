//! The `[render]` table, checked: each setting's range, and the error that
//! names the key and what it takes.

use super::RenderSettings;
use super::file::SceneFile;
use super::resolve::non_negative;
use anyhow::{Result, bail};
use glam::Vec3;

/// The deepest mirror recursion a scene may ask for: each level is another
/// pass over the world, and the stencil buffer's 8 bits count the levels.
pub const MAX_MIRROR_DEPTH: u32 = 8;

/// The tile edges `render.tile_size` takes, in pixels.
pub const TILE_SIZES: std::ops::RangeInclusive<u32> = 4..=256;
/// The far-field scales `render.far_field` takes besides 0 (off): one
/// sample per k x k pixels.
pub const FAR_FIELD_SCALES: std::ops::RangeInclusive<u32> = 1..=32;
/// The depth slices `render.depth_slices` takes (1: tiled, no slicing).
pub const DEPTH_SLICES: std::ops::RangeInclusive<u32> = 1..=64;

/// The sample counts `render.msaa` takes.
pub const MSAA_SAMPLES: [u32; 4] = [1, 2, 4, 8];

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
        sort_opaque: r.sort_opaque,
        post_chain: r.post_chain,
        msaa: {
            if !MSAA_SAMPLES.contains(&r.msaa) {
                bail!(
                    "render.msaa: expected 1, 2, 4 or 8 samples per pixel (1: no MSAA), found {}",
                    r.msaa
                );
            }
            r.msaa
        },
        frustum_culling: r.frustum_culling,
        wireframe: r.wireframe,
        skinning_on: r.skinning_on,
        joint_storage: r.joint_storage,
    })
}
