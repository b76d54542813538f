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

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest angle the 12-bit grid can be off: half a step on each
    /// coordinate, stretched by at most sqrt(2) x 2 where the octahedron's
    /// faces meet the sphere at their steepest (bound checked below).
    const BOUND: f32 = 6e-4;

    fn sphere(n: usize) -> Vec<Vec3> {
        // A Fibonacci sphere: points spread evenly over every direction.
        let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
        (0..n)
            .map(|i| {
                let z = 1.0 - 2.0 * (i as f32 + 0.5) / n as f32;
                let r = (1.0 - z * z).sqrt();
                let a = golden * i as f32;
                Vec3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect()
    }

    #[test]
    fn unquantised_round_trip_is_exact_to_float() {
        for n in sphere(20_000).into_iter().chain(hard_cases()) {
            let back = decode(encode(n));
            assert!(
                angle(n, back) < 1e-3 && (n - back).length() < 2e-6,
                "{n} -> {back}"
            );
        }
    }

    #[test]
    fn twelve_bits_keep_every_direction_within_the_bound() {
        let worst = (sphere(200_000).into_iter().chain(hard_cases()))
            .map(|n| angle(n, unpack(pack(n))))
            .fold(0.0f32, f32::max);
        assert!(worst < BOUND, "worst {worst} rad");
        // Not a loose bound: some direction comes within 2x of it.
        assert!(worst > BOUND / 4.0, "worst {worst} rad");
    }

    #[test]
    fn the_poles_and_seams_come_back() {
        assert_eq!(encode(Vec3::NEG_Z), Vec2::new(1.0, 1.0));
        assert_eq!(unpack(pack(Vec3::NEG_Z)), Vec3::NEG_Z);
        assert_eq!(unpack(pack(Vec3::Z)).z, 1.0);
        for n in hard_cases() {
            // Each side of a seam stays on its side.
            let back = unpack(pack(n));
            assert!(angle(n, back) < BOUND, "{n} -> {back}");
            assert!(back.z * n.z >= -1e-3, "{n} -> {back}");
        }
    }
}
