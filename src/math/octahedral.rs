//! Octahedral normal encoding (Cigolle, Donow, Evangelakos, Mara, McGuire,
//! Meyer 2014, "A Survey of Efficient Representations for Independent Unit
//! Vectors", JCGT 3(2), listing 1): the CPU twin of glsl/common/octahedral.glsl,
//! which the packed G-buffer (`render.gbuffer = "octahedral"`,
//! src/frame/gbuffer.rs) writes and reads.
//!
//! A unit vector is projected onto the octahedron |x| + |y| + |z| = 1; the
//! upper half (z >= 0) maps to the square's diamond |u| + |v| <= 1, the
//! lower half is folded out over the diamond's edges into the corners. Each
//! coordinate is then quantised to 12 bits (0..=4095 over [-1, 1]), and the
//! two 12-bit numbers go into three bytes: R and G the high 8 bits of u and
//! v, B the low 4 bits of u (high nibble) and of v (low nibble). The fourth
//! byte of the G-buffer texel holds the shininess index.

use glam::{Vec2, Vec3};

/// Steps over [-1, 1] of each coordinate (12 bits).
pub const STEPS: f32 = 4095.0;

/// sign() that gives +1 at 0, as the paper's `signNotZero`.
fn sign_not_zero(v: Vec2) -> Vec2 {
    Vec2::new(
        if v.x >= 0.0 { 1.0 } else { -1.0 },
        if v.y >= 0.0 { 1.0 } else { -1.0 },
    )
}

/// A unit vector to the square [-1, 1]^2.
pub fn encode(n: Vec3) -> Vec2 {
    let p = n.truncate() / (n.x.abs() + n.y.abs() + n.z.abs());
    if n.z < 0.0 {
        (Vec2::ONE - Vec2::new(p.y.abs(), p.x.abs())) * sign_not_zero(p)
    } else {
        p
    }
}

/// The square back to a unit vector.
pub fn decode(e: Vec2) -> Vec3 {
    let mut v = Vec3::new(e.x, e.y, 1.0 - e.x.abs() - e.y.abs());
    if v.z < 0.0 {
        let xy = (Vec2::ONE - Vec2::new(v.y.abs(), v.x.abs())) * sign_not_zero(v.truncate());
        v.x = xy.x;
        v.y = xy.y;
    }
    v.normalize()
}

/// The 12-bit numbers of `e` (round to nearest).
pub fn quantize(e: Vec2) -> [u32; 2] {
    let q = |x: f32| ((x.clamp(-1.0, 1.0) * 0.5 + 0.5) * STEPS).round() as u32;
    [q(e.x), q(e.y)]
}

/// The three bytes the G-buffer stores for unit vector `n`.
pub fn pack(n: Vec3) -> [u8; 3] {
    let [u, v] = quantize(encode(n));
    [
        (u >> 4) as u8,
        (v >> 4) as u8,
        (((u & 15) << 4) | (v & 15)) as u8,
    ]
}

/// The unit vector three stored bytes hold.
pub fn unpack(b: [u8; 3]) -> Vec3 {
    let u = (u32::from(b[0]) << 4) | (u32::from(b[2]) >> 4);
    let v = (u32::from(b[1]) << 4) | (u32::from(b[2]) & 15);
    let c = |q: u32| q as f32 / STEPS * 2.0 - 1.0;
    decode(Vec2::new(c(u), c(v)))
}

/// Angle in radians between two unit vectors (acos of the clamped dot).
pub fn angle(a: Vec3, b: Vec3) -> f32 {
    a.dot(b).clamp(-1.0, 1.0).acos()
}

/// The hard cases: the poles, the axes, the diamond's edges (the seams
/// where the lower half folds, z = 0), the corners, and vectors a hair to
/// either side of a seam.
pub fn hard_cases() -> Vec<Vec3> {
    let mut v = vec![
        Vec3::Z,
        Vec3::NEG_Z,
        Vec3::X,
        Vec3::NEG_X,
        Vec3::Y,
        Vec3::NEG_Y,
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(-1.0, 1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(-1.0, -1.0, -1.0),
        Vec3::new(0.3, -0.7, 0.0),
        Vec3::new(0.0, 1e-7, -1.0),
        Vec3::new(-1e-7, 0.0, -1.0),
    ];
    for z in [1e-4_f32, -1e-4, 1e-6, -1e-6] {
        v.push(Vec3::new(0.6, 0.8, z));
        v.push(Vec3::new(-0.8, 0.6, z));
        v.push(Vec3::new(0.0, -1.0, z));
    }
    v.into_iter().map(Vec3::normalize).collect()
}
