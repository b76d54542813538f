//! The alpha test in the shadow reference (notes 05 "Alpha Test", applied to
//! notes 01 §8.5): a caster whose material alpha-tests (an MTL's map_d or
//! alpha in map_Kd, glTF's alphaMode MASK) stops a ray only where the
//! texel at the hit passes the material's test, as the shadow pass's
//! `shadow_alpha_test` decides (glsl/shadows/shadow_alpha.glsl). The alpha
//! is the diffuse texture's (with an alpha map's first channel put in it),
//! read at level 0 with the nearest texel and the material's wrap rule and
//! uv transform; the uv at the hit is the barycentric mix of the corners'.

use crate::gl::image_file::{load_rgba8, load_rgba8_with_alpha};
use crate::lighting::triangle::Triangle;
use crate::math::texture_mapping::nearest_texel;
use crate::scene::{AlphaTest, Material};
use anyhow::Result;
use glam::{Vec2, Vec3};
use std::collections::HashMap;

/// A material's alpha as the shadow pass reads it.
pub(super) struct AlphaTexture {
    alpha: Vec<u8>,
    width: usize,
    height: usize,
    wrap: [crate::math::texture_mapping::WrapRule; 2],
    test: AlphaTest,
    reference: f32,
}

impl AlphaTexture {
    /// `m`'s alpha texture, or None when its casters are plain (no test,
    /// or nothing to sample: the test then sees alpha 1 everywhere and
    /// decides for the whole triangle, which `always` gives).
    pub(super) fn of(m: &Material) -> Result<Option<AlphaTexture>> {
        if m.alpha_test == AlphaTest::Always {
            return Ok(None);
        }
        let img = match (&m.alpha_map, &m.diffuse_texture) {
            (Some(a), colour) => load_rgba8_with_alpha(colour.as_deref(), a)?,
            (None, Some(d)) => load_rgba8(d)?,
            (None, None) => return Ok(None),
        };
        Ok(Some(AlphaTexture {
            width: img.width() as usize,
            height: img.height() as usize,
            alpha: img.pixels().map(|p| p.0[3]).collect(),
            wrap: m.texturing.wrap.map(|w| w.rule()),
            test: m.alpha_test,
            reference: m.alpha_ref,
        }))
    }

    /// Whether the texel at `uv` (gloss's: v up; rows already flipped so
    /// that row 0 is v = 0) passes the test: the fragment is kept.
    fn passes(&self, uv: Vec2) -> bool {
        let x = nearest_texel(uv.x as f64, self.width, self.wrap[0]);
        let y = nearest_texel(uv.y as f64, self.height, self.wrap[1]);
        let a = self.alpha[y * self.width + x] as f32 / 255.0;
        self.test.passes(a, self.reference)
    }
}

/// The material of a whole-triangle decision: does the test pass at all
/// without a texture (alpha 1)?
pub(super) fn passes_untextured(m: &Material) -> bool {
    m.alpha_test.passes(1.0, m.alpha_ref)
}

/// The alpha-tested casters, found by their corners.
#[derive(Default)]
pub(super) struct Cutouts {
    textures: Vec<AlphaTexture>,
    /// Corners (bit patterns) -> (texture, the corners' transformed uvs).
    triangles: HashMap<[u32; 9], (usize, [Vec2; 3])>,
}

fn key(t: &Triangle) -> [u32; 9] {
    let [a, b, c] = [t.a, t.b, t.c].map(|p| p.to_array().map(f32::to_bits));
    [a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]]
}

impl Cutouts {
    /// Add texture `t`; its index for `add_triangle`.
    pub(super) fn add_texture(&mut self, t: AlphaTexture) -> usize {
        self.textures.push(t);
        self.textures.len() - 1
    }

    /// Triangle `t` samples texture `texture` at `uv` (after the
    /// material's uv x scale + offset).
    pub(super) fn add_triangle(&mut self, t: &Triangle, texture: usize, uv: [Vec2; 3]) {
        self.triangles.insert(key(t), (texture, uv));
    }

    /// Whether `t`, met by the ray `origin + s dir`, blocks it: always for
    /// a plain caster; for a cut-out, where the texel at the hit passes.
    pub(super) fn blocks(&self, t: &Triangle, origin: Vec3, dir: Vec3) -> bool {
        let Some(&(texture, uv)) = self.triangles.get(&key(t)) else {
            return true;
        };
        let Some(s) = t.intersect(origin, dir) else {
            return true;
        };
        let p = origin + s * dir;
        // Barycentrics of p by sub-triangle areas (p lies in the plane).
        let n = (t.b - t.a).cross(t.c - t.a);
        let area = n.length_squared();
        if area <= 0.0 {
            return true;
        }
        let l1 = (p - t.a).cross(t.c - t.a).dot(n) / area;
        let l2 = (t.b - t.a).cross(p - t.a).dot(n) / area;
        let l0 = 1.0 - l1 - l2;
        let at = uv[0] * l0 + uv[1] * l1 + uv[2] * l2;
        self.textures[texture].passes(at)
    }
}
