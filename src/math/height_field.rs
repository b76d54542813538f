//! The reference parallax mapping is measured against: the view ray traced
//! through the height field on the CPU, in f64, with fine steps and then
//! bisection, and the ray from that hit toward a light marched the same way
//! (techniques/lighting/parallax_mapping.rs approximates both with a few
//! layers; docs/lighting/parallax_mapping.md).
//!
//! The height field is the one the shader reads: the map's texels sampled
//! bilinearly as GL_LINEAR does (texel centres at (i + 0.5) / width,
//! GL_REPEAT), depth = 1 - height, `scale` deep in texture uv units; a
//! tangent-space direction (x along u, y along v, z out of the surface)
//! moves xy / z * scale in uv per unit of depth.

use glam::{DVec2, DVec3};

/// A height map as GL holds it: row 0 is v = 0 (the bottom of the image).
pub struct HeightMap {
    pub width: usize,
    pub height: usize,
    /// Heights in 0..=1 (1: the top of the relief), row by row from v = 0.
    pub texels: Vec<f64>,
}

/// Where a view ray meets the height field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The texture coordinates of the hit (not wrapped).
    pub uv: DVec2,
    /// How deep, 0 (the top) to 1.
    pub depth: f64,
}

impl HeightMap {
    /// From an image's rows, top row first (as a PNG stores them): the
    /// loader flips it for GL, and so does this.
    pub fn from_image_rows(width: usize, height: usize, top_first: &[f64]) -> HeightMap {
        assert_eq!(top_first.len(), width * height, "one height per texel");
        let mut texels = Vec::with_capacity(width * height);
        for row in (0..height).rev() {
            texels.extend_from_slice(&top_first[row * width..(row + 1) * width]);
        }
        HeightMap {
            width,
            height,
            texels,
        }
    }

    fn texel(&self, i: i64, j: i64) -> f64 {
        let (w, h) = (self.width as i64, self.height as i64);
        self.texels[(j.rem_euclid(h) * w + i.rem_euclid(w)) as usize]
    }

    /// The depth below the top at `uv`: 1 - the bilinear height (GL_LINEAR, GL_REPEAT).
    pub fn depth(&self, uv: DVec2) -> f64 {
        let x = uv.x * self.width as f64 - 0.5;
        let y = uv.y * self.height as f64 - 0.5;
        let (i, j) = (x.floor(), y.floor());
        let (fx, fy) = (x - i, y - j);
        let (i, j) = (i as i64, j as i64);
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        let bottom = lerp(self.texel(i, j), self.texel(i + 1, j), fx);
        let top = lerp(self.texel(i, j + 1), self.texel(i + 1, j + 1), fx);
        1.0 - lerp(bottom, top, fy)
    }

    /// Steps fine enough that a ray crossing `shift` uv moves at most a
    /// sixteenth of a texel per step.
    fn steps(&self, shift: DVec2) -> usize {
        let texels = (shift.x.abs() * self.width as f64).max(shift.y.abs() * self.height as f64);
        ((texels * 16.0).ceil() as usize).clamp(256, 1 << 20)
    }

    /// The first point where the view ray entering the top at `uv` along
    /// -`view` (`view` toward the eye, tangent space, z > 0) is at or below
    /// the surface: marched in fine steps, then bisected to 1e-12 in depth.
    pub fn trace(&self, uv: DVec2, view: DVec3, scale: f64) -> Hit {
        let shift = view.truncate() / view.z * scale; // uv per unit of depth
        let at = |t: f64| uv - shift * t;
        // f(t) < 0: the ray is above the surface.
        let f = |t: f64| t - self.depth(at(t));
        if f(0.0) >= 0.0 {
            return Hit { uv, depth: 0.0 };
        }
        let n = self.steps(shift);
        let (mut lo, mut hi) = (0.0, 1.0);
        for k in 1..=n {
            let t = k as f64 / n as f64;
            if f(t) >= 0.0 {
                hi = t;
                break;
            }
            lo = t;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if f(mid) >= 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
            if hi - lo < 1e-12 {
                break;
            }
        }
        Hit {
            uv: at(hi),
            depth: hi,
        }
    }

    /// Whether light from `light` (toward the light, tangent space) reaches
    /// `hit`: false below the horizon (z <= 0) or where the relief rises
    /// above the ray between the hit and the top. The first 1e-3 of depth
    /// is skipped: the ray leaves the surface there.
    pub fn lit(&self, hit: Hit, light: DVec3, scale: f64) -> bool {
        if light.z <= 0.0 {
            return false;
        }
        let shift = light.truncate() / light.z * scale;
        let start = hit.depth - 1e-3;
        if start <= 0.0 {
            return true;
        }
        let n = self.steps(shift * start);
        (0..=n).all(|k| {
            let s = start * (1.0 - k as f64 / n as f64); // the ray's depth
            let uv = hit.uv + shift * (hit.depth - s);
            self.depth(uv) >= s - 1e-9
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Heights 0 and 1 in a 2 x 1 map: bilinear between the texel centres
    /// 0.25 and 0.75, a ramp of height 2u - 0.5.
    fn ramp() -> HeightMap {
        HeightMap::from_image_rows(2, 1, &[0.0, 1.0])
    }

    #[test]
    fn a_straight_down_ray_hits_at_the_depth_under_it() {
        let m = ramp();
        let hit = m.trace(DVec2::new(0.5, 0.5), DVec3::Z, 0.1);
        // Height at u = 0.5: 0.5, depth 0.5; straight down the uv stays put.
        assert!((hit.depth - 0.5).abs() < 1e-9, "{hit:?}");
        assert!((hit.uv - DVec2::new(0.5, 0.5)).length() < 1e-12);
    }

    #[test]
    fn a_slanted_ray_meets_the_ramp_where_the_line_does() {
        let m = ramp();
        // depth(u) = 1 - (2u - 0.5) = 1.5 - 2u on [0.25, 0.75]. The ray from
        // u0 = 0.7 moves u = 0.7 - 0.1 t (view x/z = 1, scale 0.1):
        // t = 1.5 - 2 (0.7 - 0.1 t) = 0.1 + 0.2 t, so t = 0.125.
        let hit = m.trace(
            DVec2::new(0.7, 0.5),
            DVec3::new(1.0, 0.0, 1.0).normalize(),
            0.1,
        );
        assert!((hit.depth - 0.125).abs() < 1e-9, "{hit:?}");
        assert!((hit.uv.x - 0.6875).abs() < 1e-9, "{hit:?}");
    }

    #[test]
    fn a_low_light_is_blocked_by_the_rising_side_only() {
        let m = ramp();
        let hit = m.trace(DVec2::new(0.5, 0.5), DVec3::Z, 0.1);
        // A light low over the horizon (x / z = 10): its ray moves 10 x 0.1
        // = 1 uv per unit of depth, so it rises 1 in depth per uv. Toward +u
        // the relief rises 2 per uv, faster: blocked. Toward -u it falls
        // away: lit.
        assert!(!m.lit(hit, DVec3::new(1.0, 0.0, 0.1).normalize(), 0.1));
        assert!(m.lit(hit, DVec3::new(-1.0, 0.0, 0.1).normalize(), 0.1));
        // A high light toward +u (x / z = 1: 10 in depth per uv) rises faster
        // than the relief: lit. Straight up: lit; below the horizon: not.
        assert!(m.lit(hit, DVec3::new(1.0, 0.0, 1.0).normalize(), 0.1));
        assert!(m.lit(hit, DVec3::Z, 0.1));
        assert!(!m.lit(hit, DVec3::new(1.0, 0.0, -0.1), 0.1));
    }
}
