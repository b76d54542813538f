//! Per-vertex normals computed from the triangles: smooth, area-weighted
//! normals (notes 01 §8.1). The tangents bump mapping needs are in
//! `tangents.rs`; this file's tests check both.

use super::MeshData;
use glam::Vec3;
use std::collections::HashMap;

/// Replaces every normal by the area-weighted average of the normals of the
/// triangles around it (notes 01 §8.1: the cross product of two edges, whose
/// length is twice the triangle's area, so big triangles count more).
///
/// Vertices at exactly the same position share their normal even when they
/// are separate vertices (split for a uv seam), so seams do not show as
/// creases; give the file normals if you want hard edges. A vertex touched by
/// no usable triangle keeps its normal if it is a usable one, otherwise gets
/// +y. Out-of-range indices are ignored.
pub fn compute_normals(mesh: &mut MeshData) {
    let key = |p: [f32; 3]| p.map(|c| if c == 0.0 { 0 } else { c.to_bits() });
    let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
    for t in mesh.indices.chunks_exact(3) {
        let Some(v) = t
            .iter()
            .map(|&i| mesh.vertices.get(i as usize))
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let p = v.iter().map(|v| Vec3::from(v.position)).collect::<Vec<_>>();
        let n = (p[1] - p[0]).cross(p[2] - p[0]);
        if !n.is_finite() {
            continue;
        }
        for corner in v {
            *sums.entry(key(corner.position)).or_insert(Vec3::ZERO) += n;
        }
    }
    for v in &mut mesh.vertices {
        let sum = sums.get(&key(v.position)).copied().unwrap_or(Vec3::ZERO);
        let n = sum
            .try_normalize()
            .or_else(|| Vec3::from(v.normal).try_normalize())
            .unwrap_or(Vec3::Y);
        v.normal = n.to_array();
    }
}

/// A unit vector perpendicular to the unit vector `n`: +x made perpendicular
/// to n (or +y when n is close to ±x). For a +y normal this is +x.
pub(super) fn any_perpendicular(n: Vec3) -> Vec3 {
    let a = if n.x.abs() < 0.9 { Vec3::X } else { Vec3::Y };
    (a - n * n.dot(a)).try_normalize().unwrap_or(Vec3::X)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::compute_tangents;
    use crate::geometry::tests::{check_mesh, procedural};
    use crate::geometry::{Vertex, icosphere, plane, uv_sphere};

    #[test]
    fn tangents_follow_u_and_handedness() {
        // Procedural meshes are right-handed: cross(N, T) runs along +v.
        for (name, m) in procedural() {
            assert!(
                m.vertices.iter().all(|v| v.tangent[3] == 1.0),
                "{name}: w != +1"
            );
        }
        // Mirroring u flips the handedness.
        let mut p = plane(1.0, 1.0, 1);
        for v in &mut p.vertices {
            v.uv[0] = 1.0 - v.uv[0];
        }
        compute_tangents(&mut p);
        for v in &p.vertices {
            assert!((v.tangent[0] + 1.0).abs() < 1e-6 && v.tangent[3] == -1.0);
        }
    }

    fn triangle(uvs: [[f32; 2]; 3]) -> MeshData {
        let p = [[0.0, 0.0, 0.0], [1.0, 0.0, -0.2], [0.3, 0.1, -1.0]];
        let mut m = MeshData {
            vertices: (0..3)
                .map(|i| Vertex {
                    position: p[i],
                    uv: uvs[i],
                    ..Default::default()
                })
                .collect(),
            indices: vec![0, 1, 2],
            ..Default::default()
        };
        compute_normals(&mut m);
        compute_tangents(&mut m);
        m
    }

    fn assert_tangent_ok(m: &MeshData) {
        for v in &m.vertices {
            assert!(v.tangent.iter().all(|x| x.is_finite()), "NaN tangent {v:?}");
            let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
            assert!((t.length() - 1.0).abs() < 1e-5);
            assert!(t.dot(Vec3::from(v.normal)).abs() < 1e-5);
            assert!(v.tangent[3] == 1.0 || v.tangent[3] == -1.0);
        }
    }

    #[test]
    fn degenerate_uvs_give_finite_tangents() {
        // Missing uvs (all zero), all uvs equal, zero uv area (collinear uvs).
        assert_tangent_ok(&triangle([[0.0; 2]; 3]));
        assert_tangent_ok(&triangle([[0.3, 0.7]; 3]));
        assert_tangent_ok(&triangle([[0.0, 0.0], [0.5, 0.5], [1.0, 1.0]]));
        assert_tangent_ok(&triangle([[f32::NAN, 0.0], [0.5, 0.5], [1.0, 0.0]]));
        // A degenerate triangle (zero area) and a vertex no triangle uses.
        let mut m = triangle([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        m.vertices.push(Vertex::default());
        m.vertices[1].position = m.vertices[0].position;
        m.vertices[2].position = m.vertices[0].position;
        compute_normals(&mut m);
        compute_tangents(&mut m);
        assert_tangent_ok(&m);
        // Out-of-range indices are ignored, not a panic.
        m.indices.extend_from_slice(&[0, 1, 99]);
        compute_normals(&mut m);
        compute_tangents(&mut m);
        assert_tangent_ok(&m);
    }

    #[test]
    fn compute_normals_area_weighted_and_welded() {
        // Recomputing the sphere's normals gives back (almost) the radius.
        let mut s = icosphere(3);
        compute_normals(&mut s);
        for v in &s.vertices {
            assert!(Vec3::from(v.normal).dot(Vec3::from(v.position)) > 0.999);
        }
        // uv-seam duplicates share the same normal.
        let mut u = uv_sphere(8, 8);
        compute_normals(&mut u);
        let (first, last) = (&u.vertices[9 * 4], &u.vertices[9 * 4 + 8]);
        assert_eq!(first.position, last.position);
        assert_eq!(first.normal, last.normal);
        // Area weighting: a big triangle on the xz plane outweighs a small one
        // on the xy plane sharing vertex 0.
        let mut m = MeshData {
            vertices: [
                [0.0, 0.0, 0.0],
                [10.0, 0.0, 0.0],
                [0.0, 0.0, -10.0],
                [0.0, 0.1, 0.0],
                [-0.1, 0.0, 0.0],
            ]
            .iter()
            .map(|&p| Vertex {
                position: p,
                ..Default::default()
            })
            .collect(),
            indices: vec![0, 1, 2, 0, 3, 4],
            ..Default::default()
        };
        compute_normals(&mut m);
        compute_tangents(&mut m);
        let n0 = Vec3::from(m.vertices[0].normal);
        assert!(n0.y > 0.99 && n0.z > 0.0, "{n0}");
        check_mesh("weighted", &m);
    }
}
