//! A directional light's cascades this frame (Engel 2006, "Cascaded Shadow
//! Maps"; docs/shadows/cascaded_shadow_maps.md): the camera's frustum, cut
//! at the scene's far side as the visible fit cuts it, split and fitted by
//! src/math/cascades.rs, and the std140 `Cascades` block that
//! glsl/shadows/cascaded_shadow_maps.glsl reads.

use super::{CASCADED, LightView};
use crate::frame::shadows::Caster;
use crate::frame::unit_check::{self, UnitsNeeded};
use crate::gl::Gl;
use crate::gl::buffer::Buffer;
use crate::gl::depth_map::DepthMap;
use crate::gl::texture_units;
use crate::math::cascades;
use crate::math::shadow as matrices;
use crate::scene::shadows::MAX_CASCADES;
use crate::scene::{Camera, Shadow};
use anyhow::Result;
use glam::{Vec3, Vec4};
use glow::HasContext;

/// The uniform-block binding point of the `Cascades` block.
pub const CASCADES_BINDING: u32 = 3;
/// The cascades' GL_TEXTURE_2D_ARRAY: past the 16 units every GL 3.3 has
/// (src/frame/units.rs).
pub const UNIT_CASCADES: u32 = crate::frame::units::SHADOW_CASCADES;
/// std140: MAX_CASCADES mat4, MAX_CASCADES vec4 (near, far, texel, 0), then
/// the camera's eye (w: count) and forward (w: blend band), and the flags
/// (x: cascade colours).
const BLOCK_SIZE: usize = MAX_CASCADES as usize * (64 + 16) + 3 * 16;

/// The cascades' view of the world: `visible` are the camera's frustum
/// corners (near plane first, far plane cut at the scene's far side, as
/// `visible_corners` makes them), `scene_points` every caster's corners.
pub(super) fn light_view(
    direction: Vec3,
    s: &Shadow,
    scene_points: &[Vec3],
    visible: &[Vec3],
    camera: &Camera,
) -> Option<LightView> {
    if visible.len() != 8 {
        return None;
    }
    // View depths of the near and far planes: along the camera's axis (the
    // depth the lookup measures, `view_depth` in the shader).
    let forward = (camera.target - camera.eye).try_normalize()?;
    let depth = |p: Vec3| (p - camera.eye).dot(forward);
    let (near, far) = (depth(visible[0]), depth(visible[4]));
    let all = cascades::cascades(
        direction,
        visible,
        (near, far),
        scene_points,
        (s.cascades, s.split_lambda(), s.blend),
        s.resolution,
        s.stable,
    )?;
    Some(LightView {
        kind: CASCADED,
        view_projections: all.iter().map(|c| c.view_projection).collect(),
        near,
        far,
        texel: all[0].texel,
        cascades: all,
    })
}

/// The texture unit a cascaded map needs, and what `check_units` says
/// on a GL without it.
pub(super) const UNITS: UnitsNeeded = UnitsNeeded {
    key: "shadow.cascades > 1",
    reads: "a directional light's cascades",
    units: &[UNIT_CASCADES],
    instead: "set shadow.cascades = 1",
};

/// Whether `scene`'s lighting programs read the cascades: a light
/// cascades, or the general shader (render.specialize off) has the lookup.
pub(super) fn read_by(scene: &crate::scene::Scene) -> bool {
    let cascaded = |l: &crate::scene::Light| l.shadow.is_some_and(|s| s.cascades > 1);
    !scene.render.specialize || scene.lights.iter().any(cascaded)
}

/// Whether `scene` shows the cascade colours (`shadow.cascade_colors` on a
/// directional light with cascades): the deferred paths' last passes
/// (composite, the light pre-pass's combine) then tint by the cascade of
/// each pixel's point, as the forward pass tints by the point it lights.
pub fn cascade_tints(scene: &crate::scene::Scene) -> bool {
    scene.lights.iter().any(|l| {
        l.kind == crate::scene::LightKind::Directional
            && l.shadow.is_some_and(|s| s.cascades > 1 && s.cascade_colors)
    })
}

/// The `Cascades` block and a 1 x 1 x 1 array for the unit when no light
/// cascades (a program that reads the sampler wants a complete texture).
/// Bound only when `needed` (`read_by`): other frames' lighting passes
/// make no call for the cascades.
pub(super) struct CascadeBlock {
    ubo: Buffer,
    pub(super) empty: Option<DepthMap>,
    pub(super) needed: bool,
}

impl CascadeBlock {
    pub(super) fn new(gl: &Gl) -> Result<CascadeBlock> {
        let ubo = Buffer::new(gl, glow::UNIFORM_BUFFER, BLOCK_SIZE, glow::DYNAMIC_DRAW)?;
        let have = unit_check::fragment_units(gl);
        let empty = match unit_check::units_fit(have, &UNITS) {
            Ok(()) => Some(DepthMap::new_array(gl, 1, 1)?),
            Err(_) => None,
        };
        let b = CascadeBlock {
            ubo,
            empty,
            needed: true,
        };
        b.ubo.write(&vec![0u8; BLOCK_SIZE]);
        Ok(b)
    }

    /// Write this frame's cascades (none: a count of 0).
    pub(super) fn write(&self, camera: &Camera, cascaded: Option<(&Caster, &LightView)>) {
        if !self.needed {
            return;
        }
        let mut out = vec![0u8; BLOCK_SIZE];
        let mut put = |at: usize, v: &[f32]| {
            for (k, x) in v.iter().enumerate() {
                out[at + 4 * k..at + 4 * k + 4].copy_from_slice(&x.to_ne_bytes());
            }
        };
        let m = MAX_CASCADES as usize;
        let forward = (camera.target - camera.eye).normalize_or_zero();
        let (mut count, mut blend, mut colors) = (0.0, 0.0, 0.0);
        if let Some((c, v)) = cascaded {
            for (k, cascade) in v.cascades.iter().enumerate().take(m) {
                let shadow = matrices::bias() * cascade.view_projection;
                put(64 * k, &shadow.to_cols_array());
                let range = Vec4::new(cascade.near, cascade.far, cascade.texel, 0.0);
                put(64 * m + 16 * k, &range.to_array());
            }
            count = v.cascades.len().min(m) as f32;
            blend = c.shadow.blend;
            colors = if c.shadow.cascade_colors { 1.0 } else { 0.0 };
        }
        let base = 80 * m;
        put(base, &camera.eye.extend(count).to_array());
        put(base + 16, &forward.extend(blend).to_array());
        put(base + 32, &[colors, 0.0, 0.0, 0.0]);
        self.ubo.write(&out);
    }

    /// Bind the block and, on the cascades' unit, the empty array (the
    /// cascaded light's map, bound after, replaces it).
    pub(super) fn bind(&self, gl: &glow::Context) {
        if !self.needed {
            return;
        }
        if let Some(e) = &self.empty {
            let array = glow::TEXTURE_2D_ARRAY;
            texture_units::bind_one(gl, UNIT_CASCADES, array, Some(e.texture));
        }
        unsafe { gl.bind_buffer_base(glow::UNIFORM_BUFFER, CASCADES_BINDING, Some(self.ubo.id)) };
    }

    /// The block alone, for a pass that reads the cascades' ranges and no
    /// map (the deferred paths' cascade colours).
    pub(super) fn bind_block(&self, gl: &glow::Context, on: bool) {
        let id = on.then_some(self.ubo.id);
        unsafe { gl.bind_buffer_base(glow::UNIFORM_BUFFER, CASCADES_BINDING, id) };
    }

    pub(super) fn unbind(&self, gl: &glow::Context) {
        if !self.needed {
            return;
        }
        if self.empty.is_some() {
            texture_units::bind_one(gl, UNIT_CASCADES, glow::TEXTURE_2D_ARRAY, None);
        }
        unsafe { gl.bind_buffer_base(glow::UNIFORM_BUFFER, CASCADES_BINDING, None) };
    }
}
