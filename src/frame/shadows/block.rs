//! The std140 `Shadows` block that every lighting shader reads
//! (glsl/common/shadow.glsl), written from the frame's shadow maps.

use super::{SHADOW_STRIDE, SLOTS, ShadowMaps};
use crate::math::shadow as matrices;
use glam::Vec4;

/// The std140 `Shadows` block: per slot, the shadow matrix (bias x
/// light projection x light view), (kind, texel, near, far) and (bias,
/// normal offset, PCF kernel, resolution); then each light's slot, four
/// to an ivec4, -1 for none; then the casting lights' numbers, -1 after
/// the last (two ivec4).
pub(super) fn pack(maps: &ShadowMaps) -> Vec<u8> {
    let mut out = vec![0u8; block_size(maps.max_lights)];
    let mut put = |at: usize, v: &[f32]| {
        for (k, x) in v.iter().enumerate() {
            out[at + 4 * k..at + 4 * k + 4].copy_from_slice(&x.to_ne_bytes());
        }
    };
    let mut slot_of = vec![-1i32; maps.max_lights];
    for ((c, _), view) in maps.maps.iter().zip(&maps.views) {
        let Some(v) = view else { continue };
        let at = c.slot * SHADOW_STRIDE;
        let s = c.shadow;
        put(
            at,
            &(matrices::bias() * v.view_projections[0]).to_cols_array(),
        );
        put(
            at + 64,
            &Vec4::new(v.kind as f32, v.texel, v.near, v.far).to_array(),
        );
        let b = [
            s.bias,
            s.normal_offset,
            s.pcf.code() as f32,
            s.resolution as f32,
        ];
        put(at + 80, &b);
        if c.light < slot_of.len() {
            slot_of[c.light] = c.slot as i32;
        }
    }
    let base = SLOTS * SHADOW_STRIDE;
    for (i, s) in slot_of.iter().enumerate() {
        out[base + 4 * i..base + 4 * i + 4].copy_from_slice(&s.to_ne_bytes());
    }
    let base = SLOTS * SHADOW_STRIDE + (maps.max_lights / 4 + 1) * 16;
    let casting = maps.casting_lights();
    for k in 0..SLOTS {
        let light = casting.get(k).map_or(-1, |&l| l as i32);
        out[base + 4 * k..base + 4 * k + 4].copy_from_slice(&light.to_ne_bytes());
    }
    out
}

pub(super) fn block_size(max_lights: usize) -> usize {
    SLOTS * SHADOW_STRIDE + (max_lights / 4 + 1) * 16 + SLOTS / 4 * 16
}
