//! The pixel probe's shadow lookups: for each light with a shadow map this
//! frame, what glsl/common/shadow.glsl's `shadow_visibility` does at the
//! probed point, step by step on the CPU (notes 01 §8.5: "compare the z
//! component of the fragment to the value from the shadow buffer. If z <=
//! light depth the fragment is lit"): the point moved towards the light by
//! the bias and along its normal by the normal offset, taken into the map
//! (the shadow matrix and the divide, or for a point light the cube face
//! its direction points into and its distance / far), the depth stored in
//! that texel read back with glReadPixels from the map's framebuffer, and
//! the comparison: the centre texel's verdict. Then the light's PCF kernel
//! over the same point, tap by tap with the shader's weights
//! (probe_pcf.rs): the visibility the lighting shader multiplied the light
//! by, part lit in a penumbra.

use super::Renderer;
use super::probe_pcf::{Filtered, cube_face, filter_2d, filter_cube};
use crate::frame::shadows::{CUBE, ORTHOGRAPHIC};
use crate::gl::texture::bytemuck_f32;
use crate::math::shadow as matrices;
use glam::{Vec2, Vec3};
use glow::HasContext;
use std::collections::HashMap;

/// Face names in GL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i).
pub const FACES: [&str; 6] = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"];

/// One casting light's lookup at the probed point.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadowProbe {
    pub light: usize,
    /// The cube face looked up (a point light's map), 0..6 in GL's order.
    pub face: Option<usize>,
    /// Where in the map (0..1 each way; None: outside a 2D map, or behind
    /// a spot light) and the texel.
    pub uv: Option<Vec2>,
    pub texel: Option<(u32, u32)>,
    pub resolution: u32,
    /// The depth the map stores there (the border's 1.0 outside it).
    pub stored: f32,
    /// The point's own depth in the map's terms, compared with `stored`.
    pub compared: f32,
    /// compared <= stored (GL_LEQUAL), at the centre texel.
    pub lit: bool,
    /// The PCF kernel the frame averages with.
    pub pcf: String,
    /// That kernel's average of its comparisons (1 lit, 0 in shadow), as
    /// the shader filters: what the light is multiplied by here.
    pub filtered: Filtered,
}

/// The lookup of every light with a map this frame, at world point `p`
/// with normal `n` (zero: no normal offset).
pub(super) fn probe_shadows(r: &Renderer, p: Vec3, n: Vec3) -> Vec<ShadowProbe> {
    let shadows = r.shadows();
    let mut out = Vec::new();
    for ((caster, map), view) in shadows.maps.iter().zip(&shadows.views) {
        let Some(view) = view else { continue };
        let light = &r.scene.lights[caster.light];
        let s = caster.shadow;
        let dir = light.direction.normalize_or_zero();
        let from_light = p - light.position;
        let l = if view.kind == ORTHOGRAPHIC {
            -dir
        } else {
            -from_light.normalize_or_zero()
        };
        // A texel's size in world units at p.
        let world_texel = match view.kind {
            ORTHOGRAPHIC => view.texel,
            CUBE => view.texel * from_light.abs().max_element(),
            _ => view.texel * from_light.dot(dir),
        };
        let q = p + n * (s.normal_offset * world_texel) + l * s.bias;
        let res = s.resolution;
        let mut probe = ShadowProbe {
            light: caster.light,
            face: None,
            uv: None,
            texel: None,
            resolution: res,
            stored: 1.0,
            compared: 0.0,
            lit: true,
            pcf: s.pcf.name().to_string(),
            filtered: Filtered {
                visibility: 1.0,
                taps: 0,
                near_face_edge: false,
            },
        };
        // Each texel read once, however many taps share it.
        let mut read: HashMap<(usize, i64, i64), f32> = HashMap::new();
        let mut stored = |face: usize, x: i64, y: i64| {
            *read
                .entry((face, x, y))
                .or_insert_with(|| read_texel(r, map.framebuffers[face], (x as u32, y as u32)))
        };
        if view.kind == CUBE {
            let d = q - light.position;
            let (face, uv) = cube_face(d);
            let texel = texel_of(uv, res);
            probe.face = Some(face);
            probe.uv = Some(uv);
            probe.texel = Some(texel);
            probe.compared = (d.length() / view.far).min(1.0);
            probe.stored = stored(face, texel.0 as i64, texel.1 as i64);
            probe.filtered = filter_cube(s.pcf, d, probe.compared, res, view.texel, &mut stored);
        } else {
            let c = matrices::bias() * view.view_projections[0] * q.extend(1.0);
            if c.w <= 0.0 {
                // Behind a spot light: the shader calls it lit (its cone is dark there).
                out.push(probe);
                continue;
            }
            let c = c.truncate() / c.w;
            probe.compared = c.z.min(1.0);
            let uv = Vec2::new(c.x, c.y);
            if (0.0..=1.0).contains(&uv.x) && (0.0..=1.0).contains(&uv.y) {
                let texel = texel_of(uv, res);
                probe.uv = Some(uv);
                probe.texel = Some(texel);
                probe.stored = stored(0, texel.0 as i64, texel.1 as i64);
            }
            let c = Vec3::new(uv.x, uv.y, probe.compared);
            probe.filtered = filter_2d(s.pcf, c, res, &mut |x, y| stored(0, x, y));
        }
        probe.lit = probe.compared <= probe.stored;
        out.push(probe);
    }
    out
}

/// The texel (column, row from the bottom) that `uv` falls in.
fn texel_of(uv: Vec2, res: u32) -> (u32, u32) {
    let t = |v: f32| ((v * res as f32).floor().max(0.0) as u32).min(res.saturating_sub(1));
    (t(uv.x), t(uv.y))
}

/// One depth of a map, through the framebuffer it is attached to.
fn read_texel(r: &Renderer, fb: glow::Framebuffer, (x, y): (u32, u32)) -> f32 {
    let gl = &r.gl;
    let mut v = [0f32; 1];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb));
        gl.read_pixels(
            x as i32,
            y as i32,
            1,
            1,
            glow::DEPTH_COMPONENT,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(bytemuck_f32(&mut v))),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    v[0]
}

impl std::fmt::Display for ShadowProbe {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let verdict = if self.lit { "lit" } else { "in shadow" };
        let map = match self.face {
            Some(face) => format!("cube face {}", FACES[face]),
            None => "2D map".to_string(),
        };
        let at = match (self.uv, self.texel) {
            (Some(uv), Some((x, y))) => {
                format!("uv ({:.4}, {:.4}), texel ({x}, {y})", uv.x, uv.y)
            }
            _ => "outside the map".to_string(),
        };
        let edge = if self.filtered.near_face_edge {
            " (within half a texel of a face edge: a GPU filtering across faces may differ)"
        } else {
            ""
        };
        write!(
            f,
            "shadow of light {} ({map}, {}x{}): {at}, stored {:.6}, compared {:.6}: {verdict} at the centre texel; PCF {} over {} comparisons: visibility {:.4}{edge}",
            self.light,
            self.resolution,
            self.resolution,
            self.stored,
            self.compared,
            self.pcf,
            self.filtered.taps,
            self.filtered.visibility
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_axis_picks_its_face() {
        for (i, d) in [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z]
            .into_iter()
            .enumerate()
        {
            let (face, uv) = cube_face(d);
            assert_eq!(face, i);
            assert!((uv - Vec2::splat(0.5)).length() < 1e-6);
        }
        // +X: s runs along -z, t along -y.
        let (_, uv) = cube_face(Vec3::new(1.0, -0.5, -0.5));
        assert!((uv - Vec2::new(0.75, 0.75)).length() < 1e-6);
    }
}
