//! The tangent frame bump mapping needs (notes 01 §8.4), by MikkTSpace
//! (Mikkelsen 2008): the `bevy_mikktspace` crate, a byte-for-byte port of
//! the reference C implementation that Blender, xNormal, Unity, Unreal and
//! glTF use. A normal map baked by any of those tools therefore decodes
//! with exactly the frame it was baked in; a home-made tangent (the
//! per-triangle dP/du summed per vertex) would disagree with them along
//! seams and on curved surfaces.
//!
//! `tangent.xyz` is the unit direction of increasing u, perpendicular to
//! the normal; `tangent.w` is +1 or -1, the handedness, so that the
//! notes' bitangent is B = cross(N, T) * w (the direction of increasing v)
//! and mirrored uvs work.

use super::MeshData;
use super::normals::any_perpendicular;
use bevy_mikktspace::{Geometry, TangentSpace, generate_tangents};
use glam::Vec3;

/// Computes `tangent` for every vertex by MikkTSpace. MikkTSpace gives a
/// tangent per triangle corner. Corners of one vertex agree wherever the
/// triangles around it share edges; where they do not (fans that meet only
/// at the vertex, as the cone's sides do), the corners' tangents are
/// averaged, and where their handedness differs (a vertex on a mirror seam
/// of the uvs) the vertex is split, so the vertex count may grow. A corner MikkTSpace gives no frame (a triangle
/// with zero uv area and no neighbour to borrow from, a mesh without uvs)
/// gets some unit vector perpendicular to its normal, w = +1: never NaN.
/// Normals should be set first.
///
/// Returns, for each vertex it added (at the end, in order), the vertex it
/// copies: a caller with data of its own per vertex (a skin's joints and
/// weights) copies that data likewise.
pub fn compute_tangents(mesh: &mut MeshData) -> Vec<usize> {
    let mut added = Vec::new();
    let mut corners = Corners {
        mesh,
        tangents: Vec::new(),
    };
    corners.tangents = vec![None; corners.mesh.indices.len()];
    // Err only for a mesh with no triangles: every corner then keeps None.
    let _ = generate_tangents(&mut corners);
    let Corners { mesh, tangents } = corners;
    let fallback = |n: [f32; 3]| {
        let n = Vec3::from(n).try_normalize().unwrap_or(Vec3::Y);
        let t = any_perpendicular(n);
        [t.x, t.y, t.z, 1.0]
    };
    // Per vertex: the sum of its corners' tangents, and their handedness.
    let count = mesh.vertices.len();
    let mut given: Vec<Option<(Vec3, f32)>> = vec![None; count];
    for (corner, t) in tangents.into_iter().enumerate() {
        let Some(&index) = mesh.indices.get(corner) else {
            continue;
        };
        let i = index as usize;
        if i >= count {
            continue;
        }
        let t = t
            .filter(|t| t.iter().all(|x| x.is_finite()))
            .unwrap_or_else(|| fallback(mesh.vertices[i].normal));
        let (dir, w) = (Vec3::new(t[0], t[1], t[2]), t[3]);
        match &mut given[i] {
            None => given[i] = Some((dir, w)),
            Some((sum, hand)) if *hand == w => *sum += dir,
            // This corner's uvs are mirrored against the vertex's first
            // corner (a mirror seam): it needs its own vertex.
            Some(_) => {
                let v = mesh.vertices[i];
                mesh.vertices.push(v);
                if let Some(&c) = mesh.colors.get(i) {
                    mesh.colors.push(c);
                }
                added.push(i);
                given.push(Some((dir, w)));
                mesh.indices[corner] = (mesh.vertices.len() - 1) as u32;
            }
        }
    }
    for (v, t) in mesh.vertices.iter_mut().zip(given) {
        let n = Vec3::from(v.normal).try_normalize().unwrap_or(Vec3::Y);
        v.tangent = match t {
            Some((sum, w)) => match (sum - n * n.dot(sum)).try_normalize() {
                Some(t) => [t.x, t.y, t.z, w],
                None => fallback(v.normal),
            },
            None => fallback(v.normal),
        };
    }
    added
}

/// The mesh as MikkTSpace sees it: triangles of corners, and a frame per corner.
struct Corners<'a> {
    mesh: &'a mut MeshData,
    tangents: Vec<Option<[f32; 4]>>,
}

impl Corners<'_> {
    fn vertex(&self, face: usize, vert: usize) -> &super::Vertex {
        let i = self.mesh.indices[face * 3 + vert] as usize;
        // An out-of-range index reads the first vertex (MeshData::check
        // refuses such meshes before they are drawn).
        self.mesh.vertices.get(i).unwrap_or(&self.mesh.vertices[0])
    }
}

impl Geometry for Corners<'_> {
    fn num_faces(&self) -> usize {
        if self.mesh.vertices.is_empty() {
            0
        } else {
            self.mesh.indices.len() / 3
        }
    }
    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }
    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.vertex(face, vert).position
    }
    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.vertex(face, vert).normal
    }
    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        self.vertex(face, vert).uv
    }
    fn set_tangent(&mut self, t: Option<TangentSpace>, face: usize, vert: usize) {
        self.tangents[face * 3 + vert] = t.map(|t| t.tangent_encoded());
    }
}
