//! A rock for the instancing field (LearnOpenGL's asteroid field loads a
//! rock model; gloss makes one): an icosphere whose vertices are pushed in
//! or out by a hash of their position (so the copies of a vertex along a
//! seam move alike), faceted: each triangle its own three vertices with the
//! face's normal. Radius about 1.

use super::{MeshData, Vertex, icosphere};
use glam::Vec3;

/// How far each vertex is from the centre: 0.75 to 1.15, by a hash of its
/// (rounded) position.
fn bump(p: Vec3) -> f32 {
    let q = (p * 1000.0).round();
    let mut h = (q.x as i64).wrapping_mul(73_856_093)
        ^ (q.y as i64).wrapping_mul(19_349_663)
        ^ (q.z as i64).wrapping_mul(83_492_791);
    h = h.wrapping_mul(0x5851_f42d_4c95_7f2d);
    let u = ((h >> 24) & 0xffff) as f32 / 65535.0;
    0.75 + 0.4 * u
}

/// The rock: 80 faceted triangles, 240 vertices.
pub fn rock() -> MeshData {
    let sphere = icosphere(1);
    let mut m = MeshData::default();
    let moved: Vec<Vec3> = (sphere.vertices.iter())
        .map(|v| {
            let p = Vec3::from(v.position).normalize();
            p * bump(p)
        })
        .collect();
    for t in sphere.indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| moved[i as usize]);
        let n = (b - a).cross(c - a).normalize_or_zero();
        for p in [a, b, c] {
            m.indices.push(m.vertices.len() as u32);
            m.vertices.push(Vertex {
                position: p.to_array(),
                normal: n.to_array(),
                uv: [0.0, 0.0],
                tangent: [1.0, 0.0, 0.0, 1.0],
            });
        }
    }
    m
}
