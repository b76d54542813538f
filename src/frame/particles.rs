//! A particle system on the CPU (notes 01 §3.2: "a basic graphical particle
//! system in which points are sent to the GPU pipeline and are converted
//! into quads by the geometry shader"). The simulation has a closed form,
//! so any instant is computed directly and exactly, with no stepping:
//!
//! - particle `i` is born at `i / rate` seconds and lives `lifetime`
//!   seconds; at time t the living ones are those born in (t - lifetime, t];
//! - its start velocity is `speed` along a direction inside a cone of
//!   half-angle `spread` about `direction`, from a hash of (seed, i);
//! - at age `a` it is at `emitter + v a + g a^2 / 2` (gravity `g`).
//!
//! What goes to the GPU, per frame, in one of two forms
//! (src/techniques/vertex_geometry/particles.rs):
//! - points: 16 bytes a particle (position, age / lifetime), which the
//!   geometry shader turns into a camera-facing quad;
//! - quads expanded here: two triangles a particle, 6 vertices of 24 bytes
//!   (position, corner, age / lifetime), 144 bytes a particle.

use crate::scene::particles::Particles;
use glam::{Mat4, Vec3};

/// One living particle at an instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Particle {
    pub position: Vec3,
    /// Age over lifetime, 0 at birth, below 1.
    pub life: f32,
}

/// A hash of (seed, i, k) to 0..1 (a small integer mixer, the same on
/// every machine).
fn unit(seed: u32, i: u64, k: u32) -> f32 {
    let mut x = (i ^ (u64::from(seed) << 32)).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ u64::from(k);
    x ^= x >> 33;
    x = x.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
    x ^= x >> 33;
    (x >> 40) as f32 / (1u64 << 24) as f32
}

/// Particle `i`'s start velocity: a direction uniform over the cone's cap.
pub fn velocity(p: &Particles, i: u64) -> Vec3 {
    let axis = p.direction.normalize();
    let (u, w) = (unit(p.seed, i, 1), unit(p.seed, i, 2));
    let cos_max = p.spread.to_radians().cos();
    let cos = 1.0 - u * (1.0 - cos_max);
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = w * std::f32::consts::TAU;
    let side = axis.any_orthonormal_pair();
    (axis * cos + (side.0 * phi.cos() + side.1 * phi.sin()) * sin) * p.speed
}

/// The numbers of the particles living at time `t`: born at i / rate in
/// (t - lifetime, t], the newest `p.count` of them.
pub fn alive_range(p: &Particles, t: f32) -> std::ops::Range<u64> {
    if t.is_nan() || t < 0.0 || p.rate <= 0.0 {
        return 0..0;
    }
    let first = (((t - p.lifetime) * p.rate).floor() + 1.0).max(0.0) as u64;
    let last = (t * p.rate).floor() as u64;
    let first = first.max((last + 1).saturating_sub(p.count as u64));
    first..last + 1
}

/// The particles living at time `t`, oldest first (at most `p.count`).
pub fn alive(p: &Particles, t: f32) -> Vec<Particle> {
    alive_range(p, t)
        .map(|i| {
            let age = t - i as f32 / p.rate;
            let v = velocity(p, i);
            Particle {
                position: p.emitter + v * age + p.gravity * (0.5 * age * age),
                life: (age / p.lifetime).clamp(0.0, 0.999_999),
            }
        })
        .collect()
}

/// Bytes a particle takes as a point, and as a quad expanded on the CPU.
pub const POINT_BYTES: usize = 16;
pub const QUAD_BYTES: usize = 6 * 24;

/// The points, packed: x, y, z, life (f32 each).
pub fn pack_points(ps: &[Particle], out: &mut Vec<u8>) {
    out.clear();
    out.reserve(ps.len() * POINT_BYTES);
    for q in ps {
        for f in [q.position.x, q.position.y, q.position.z, q.life] {
            out.extend_from_slice(&f.to_ne_bytes());
        }
    }
}

/// The quads the geometry shader would make, made here instead: for each
/// particle two triangles facing the camera (`view`'s right and up), side
/// `size`, each vertex x, y, z, corner u, v, life.
pub fn pack_quads(ps: &[Particle], view: &Mat4, size: f32, out: &mut Vec<u8>) {
    let right = Vec3::new(view.x_axis.x, view.y_axis.x, view.z_axis.x) * (0.5 * size);
    let up = Vec3::new(view.x_axis.y, view.y_axis.y, view.z_axis.y) * (0.5 * size);
    out.clear();
    out.reserve(ps.len() * QUAD_BYTES);
    const CORNERS: [(f32, f32); 6] = [
        (-1.0, -1.0),
        (1.0, -1.0),
        (1.0, 1.0),
        (-1.0, -1.0),
        (1.0, 1.0),
        (-1.0, 1.0),
    ];
    for q in ps {
        for (cu, cv) in CORNERS {
            let p = q.position + right * cu + up * cv;
            for f in [p.x, p.y, p.z, cu, cv, q.life] {
                out.extend_from_slice(&f.to_ne_bytes());
            }
        }
    }
}

#[cfg(test)]
mod tests;
