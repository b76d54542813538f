//! Cube maps on the CPU (notes 03, Implementation: the skybox cube map and
//! its mirror reflection): which face a direction selects and where on it
//! (GL 3.3 §3.8.10, table 3.19), the direction through a face's texel, and
//! bilinear sampling of level 0, with and without seamless filtering
//! (GL_TEXTURE_CUBE_MAP_SEAMLESS, §3.8.8). src/gl/cube_map.rs makes the GL
//! texture, glsl/sky/sky_cube_map.frag renders the sky into it with the
//! same face table, and the tests compare the GPU with `CubeImage::sample`.
//!
//! A face's texel (i, j) covers s in [i, i + 1) / n and t in [j, j + 1) / n;
//! row j = 0 is t = 0, the first row uploaded (a face image's top row: GL
//! does not flip cube map faces).

use glam::DVec3;

/// The faces in GL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i).
pub const FACES: [&str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];

/// The face a direction selects (0..6, in `FACES` order) and its (s, t) in
/// [0, 1]: the major axis picks the face, the other two components divided
/// by it give (sc, tc), s = (sc / |ma| + 1) / 2 (table 3.19).
pub fn face_st(d: DVec3) -> (usize, f64, f64) {
    let a = d.abs();
    let (face, sc, tc, ma) = if a.x >= a.y && a.x >= a.z {
        if d.x >= 0.0 {
            (0, -d.z, -d.y, a.x)
        } else {
            (1, d.z, -d.y, a.x)
        }
    } else if a.y >= a.z {
        if d.y >= 0.0 {
            (2, d.x, d.z, a.y)
        } else {
            (3, d.x, -d.z, a.y)
        }
    } else if d.z >= 0.0 {
        (4, d.x, -d.y, a.z)
    } else {
        (5, -d.x, -d.y, a.z)
    };
    (face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))
}

/// The direction (not unit: its major component is +-1) through (s, t) of
/// `face`: `face_st`'s inverse. s and t may lie outside [0, 1].
pub fn direction(face: usize, s: f64, t: f64) -> DVec3 {
    let (sc, tc) = (2.0 * s - 1.0, 2.0 * t - 1.0);
    match face {
        0 => DVec3::new(1.0, -tc, -sc),
        1 => DVec3::new(-1.0, -tc, sc),
        2 => DVec3::new(sc, 1.0, tc),
        3 => DVec3::new(sc, -1.0, -tc),
        4 => DVec3::new(sc, -tc, 1.0),
        _ => DVec3::new(-sc, -tc, -1.0),
    }
}

/// The unit vector along `face`'s major axis.
fn axis(face: usize) -> DVec3 {
    direction(face, 0.5, 0.5)
}

/// Level 0 of a cube map: six `size` x `size` faces of RGBA, row j = 0 first.
#[derive(Clone, Debug)]
pub struct CubeImage {
    pub size: usize,
    pub faces: [Vec<[f32; 4]>; 6],
}

impl CubeImage {
    pub fn texel(&self, face: usize, i: usize, j: usize) -> [f32; 4] {
        self.faces[face][j * self.size + i]
    }

    /// Bilinear filtering at `d` (GL_LINEAR on level 0). Without `seamless`
    /// each face clamps to its own edge (GL_CLAMP_TO_EDGE), so the values
    /// jump where two faces meet; with it, a tap past the edge reads the
    /// texel of the neighbouring face at the same place along the edge, and
    /// a tap past a corner the mean of the three texels that meet there.
    pub fn sample(&self, d: DVec3, seamless: bool) -> [f64; 4] {
        let n = self.size as f64;
        let (face, s, t) = face_st(d);
        let (x, y) = (s * n - 0.5, t * n - 0.5);
        let (i0, j0) = (x.floor(), y.floor());
        let (a, b) = (x - i0, y - j0);
        let mut out = [0.0; 4];
        for (di, dj, w) in [
            (0.0, 0.0, (1.0 - a) * (1.0 - b)),
            (1.0, 0.0, a * (1.0 - b)),
            (0.0, 1.0, (1.0 - a) * b),
            (1.0, 1.0, a * b),
        ] {
            let c = self.tap(face, i0 + di, j0 + dj, seamless);
            for (o, c) in out.iter_mut().zip(c) {
                *o += w * c;
            }
        }
        out
    }

    /// Texel (i, j) of `face`, where i or j may be -1 or n.
    fn tap(&self, face: usize, i: f64, j: f64, seamless: bool) -> [f64; 4] {
        let n = self.size as f64;
        let clamp = |k: f64| k.clamp(0.0, n - 1.0) as usize;
        let own = |i: f64, j: f64| self.texel(face, clamp(i), clamp(j)).map(f64::from);
        let out_i = !(0.0..n).contains(&i);
        let out_j = !(0.0..n).contains(&j);
        if !seamless || (!out_i && !out_j) {
            return own(i, j);
        }
        // The texel beyond the edge: from the point on the shared edge at
        // this texel's place along it, half a texel onto the next face.
        let across = |i: f64, j: f64| -> [f64; 4] {
            let (s, t) = ((i + 0.5) / n, (j + 0.5) / n);
            let edge = direction(face, s.clamp(0.0, 1.0), t.clamp(0.0, 1.0));
            let (f, s, t) = face_st(edge - axis(face) / n);
            self.texel(f, clamp((s * n).floor()), clamp((t * n).floor()))
                .map(f64::from)
        };
        match (out_i, out_j) {
            (true, true) => {
                let three = [own(i, j), across(i, j.clamp(0.0, n - 1.0)), {
                    across(i.clamp(0.0, n - 1.0), j)
                }];
                std::array::from_fn(|c| three.iter().map(|t| t[c]).sum::<f64>() / 3.0)
            }
            _ => across(i, j),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn face_st_inverts_direction_on_every_face() {
        for face in 0..6 {
            for (s, t) in [(0.5, 0.5), (0.1, 0.8), (0.9, 0.3)] {
                let (f, s2, t2) = face_st(direction(face, s, t) * 3.0);
                assert_eq!(f, face);
                assert!((s2 - s).abs() < 1e-12 && (t2 - t).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn a_tap_past_an_edge_lands_on_the_neighbours_edge_texel() {
        // Face i holds the value i everywhere: a tap just inside +x's left
        // edge (s = 0, towards +z) mixes +x with +z.
        let size = 4;
        let faces = std::array::from_fn(|f| vec![[f as f32; 4]; size * size]);
        let c = CubeImage { size, faces };
        let d = direction(0, 0.0, 0.5);
        assert!(
            (c.sample(d, true)[0] - 2.0).abs() < 1e-9,
            "{:?}",
            c.sample(d, true)
        );
        assert!((c.sample(d, false)[0] - 0.0).abs() < 1e-9);
    }
}
