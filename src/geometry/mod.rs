//! CPU-side meshes: the interleaved vertex layout, procedural shapes, OBJ loading
//! and tangent generation. `gl::mesh` uploads a `MeshData` into a VAO.
//!
//! The files of this folder, one job each:
//!
//! * `shapes`: procedural meshes (spheres, cube, plane, cylinder, cone, torus,
//!   the full-screen triangle);
//! * `volumes`: meshes that must ENCLOSE a shape, for the light volumes of
//!   notes 04, and the bounding radius;
//! * `normals`: smooth normals (notes 01 §8.1) and tangents for bump mapping
//!   (notes 01 §8.4);
//! * `obj`: Wavefront OBJ files, loaded through tobj, whole or one part
//!   per `usemtl`;
//! * `mtl`: the MTL files an OBJ names, mapped onto gloss's material terms;
//! * `polygons`: faces of more than three corners, ear-clipped;
//! * `skin`: skinned meshes (notes 01 §7.1): skin, skeleton, clips, posing;
//! * `gltf`, `gltf_write`: skinned meshes read from and written to glTF 2.0;
//! * `gltf_scene`, `gltf_material`, `gltf_buffers`: a whole glTF 2.0 scene
//!   (nodes, triangle primitives, materials, animations), and its bytes
//!   and counts checked before anything is read;
//! * `gltf_images`: the images inside a glTF file (.glb buffer views,
//!   data: URIs), read when their texture loads.
//!
//! Every public function is re-exported here: use `crate::geometry::cube`,
//! not the file it lives in.
//!
//! Conventions for every mesh made here:
//!
//! * right-handed model space, y up; front faces wind counter-clockwise seen
//!   from outside (GL's default `glFrontFace(GL_CCW)`), normals point outward
//!   and have unit length;
//! * uv (0, 0) is the bottom-left of a texture: v grows upward, as GL samples
//!   textures that `gl::texture` flipped on load;
//! * `tangent.xyz` is the unit direction of increasing u, perpendicular to the
//!   normal; `tangent.w` (+1 or -1) is the handedness, so the bitangent of
//!   notes 01 §8.4 is `B = cross(N, T) * tangent.w` (direction of increasing v).
//!   Every procedural mesh has w = +1.

mod gltf;
mod gltf_buffers;
mod gltf_build;
mod gltf_images;
mod gltf_material;
mod gltf_nodes;
mod gltf_scene;
mod gltf_write;
mod mtl;
mod normals;
mod obj;
mod polygons;
mod rock;
mod shapes;
pub mod skin;
mod tangents;
mod volumes;

pub use gltf::{MAX_GLTF_BYTES, MAX_GLTF_VERTICES, load_gltf};
pub use gltf_buffers::{MAX_ACCESSOR_BYTES, SUPPORTED_EXTENSIONS};
pub use gltf_build::GltfBuilder;
pub use gltf_images::{gltf_image_bytes, gltf_image_path};
pub use gltf_material::{AlphaMode, GltfMaterial, GltfTexture};
pub use gltf_scene::{
    GltfNode, GltfPrimitive, GltfScene, MAX_GLTF_NODES, MAX_GLTF_VALUE, load_gltf_scene,
    read_scene, triangles,
};
pub use gltf_write::write_glb;
pub use mtl::{MAX_MTL_BYTES, MAX_MTL_MATERIALS, MtlMaterial, load_mtl, parse_mtl};
pub use normals::compute_normals;
pub use obj::{MAX_OBJ_BYTES, MAX_OBJ_VERTICES, ObjFile, ObjPart, load_obj, load_obj_file};
pub use polygons::{newell_normal, triangulate};
pub use rock::rock;
pub use shapes::{cone, cube, cylinder, fullscreen_triangle, icosphere, plane, torus, uv_sphere};
pub use tangents::compute_tangents;
pub use volumes::{bounding_radius, light_volume_sphere};

use glam::{Vec2, Vec3};

/// One interleaved vertex: position, normal, uv, tangent (xyz + handedness w).
/// 48 bytes; attribute locations 0..3 in every shader.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
    pub tangent: [f32; 4],
}

/// An indexed triangle list.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
    /// Linear RGB per vertex (notes 01 §4.1), from an OBJ's `v x y z r g b`
    /// lines: empty when the mesh has none (the GPU then reads white).
    pub colors: Vec<[f32; 3]>,
}

impl MeshData {
    /// Number of triangles (`indices.len() / 3`).
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    fn push(&mut self, position: Vec3, normal: Vec3, uv: Vec2) -> u32 {
        self.vertices.push(Vertex {
            position: position.to_array(),
            normal: normal.to_array(),
            uv: uv.to_array(),
            tangent: [1.0, 0.0, 0.0, 1.0],
        });
        (self.vertices.len() - 1) as u32
    }

    /// Two triangles for the quad a, b, c, d given counter-clockwise.
    fn quad(&mut self, a: u32, b: u32, c: u32, d: u32) {
        self.indices.extend_from_slice(&[a, b, c, a, c, d]);
    }

    /// A `(columns + 1) x (rows + 1)` grid of vertices from `f(u, v)` ->
    /// (position, normal), u and v in 0..1, stitched into counter-clockwise
    /// quads (u to the right, v up as seen from the front). The seam column
    /// is duplicated so it can carry u = 1.
    fn grid(&mut self, columns: u32, rows: u32, f: impl Fn(f32, f32) -> (Vec3, Vec3)) {
        let base = self.vertices.len() as u32;
        for i in 0..=rows {
            for j in 0..=columns {
                let uv = Vec2::new(j as f32 / columns as f32, i as f32 / rows as f32);
                let (p, n) = f(uv.x, uv.y);
                self.push(p, n, uv);
            }
        }
        let at = |j: u32, i: u32| base + i * (columns + 1) + j;
        for i in 0..rows {
            for j in 0..columns {
                self.quad(at(j, i), at(j + 1, i), at(j + 1, i + 1), at(j, i + 1));
            }
        }
    }
}

/// What every mesh must satisfy, checked on every procedural mesh.
/// `check_mesh` and `procedural` also serve the tests of the other files here.
#[cfg(test)]
mod tests {
    use super::*;

    /// Everything every mesh must satisfy: indices in range and whole
    /// triangles, finite data, unit normals, unit tangents perpendicular to the
    /// normal with w = ±1, and counter-clockwise winding seen from outside:
    /// each triangle's edge cross product points the same way as the average
    /// of its vertex normals.
    pub(super) fn check_mesh(name: &str, m: &MeshData) {
        assert_eq!(m.indices.len() % 3, 0, "{name}: partial triangle");
        assert!(!m.indices.is_empty(), "{name}: no triangles");
        for (i, v) in m.vertices.iter().enumerate() {
            let all = v
                .position
                .iter()
                .chain(&v.normal)
                .chain(&v.uv)
                .chain(&v.tangent);
            assert!(
                all.clone().all(|x| x.is_finite()),
                "{name}: vertex {i} not finite: {v:?}"
            );
            let n = Vec3::from(v.normal);
            assert!(
                (n.length() - 1.0).abs() < 1e-4,
                "{name}: vertex {i} normal {n}"
            );
            let t = Vec3::new(v.tangent[0], v.tangent[1], v.tangent[2]);
            assert!(
                (t.length() - 1.0).abs() < 1e-4,
                "{name}: vertex {i} tangent {t}"
            );
            assert!(
                t.dot(n).abs() < 1e-4,
                "{name}: vertex {i} tangent not perpendicular"
            );
            assert!(v.tangent[3].abs() == 1.0, "{name}: vertex {i} handedness");
        }
        for (k, t) in m.indices.chunks_exact(3).enumerate() {
            assert!(
                t.iter().all(|&i| (i as usize) < m.vertices.len()),
                "{name}: index range"
            );
            let v = [t[0], t[1], t[2]].map(|i| m.vertices[i as usize]);
            let p = v.map(|v| Vec3::from(v.position));
            let face = (p[1] - p[0]).cross(p[2] - p[0]);
            let avg: Vec3 = v.iter().map(|v| Vec3::from(v.normal)).sum();
            assert!(face.length() > 0.0, "{name}: triangle {k} degenerate");
            assert!(
                face.dot(avg) > 0.0,
                "{name}: triangle {k} winds clockwise seen from outside"
            );
        }
    }

    pub(super) fn procedural() -> Vec<(&'static str, MeshData)> {
        vec![
            ("uv_sphere", uv_sphere(12, 24)),
            ("uv_sphere_min", uv_sphere(0, 0)),
            ("icosphere0", icosphere(0)),
            ("icosphere3", icosphere(3)),
            ("light_volume_sphere", light_volume_sphere()),
            ("cube", cube()),
            ("plane", plane(4.0, 2.0, 3)),
            ("cylinder", cylinder(16)),
            ("cone", cone(16)),
            ("cone3", cone(3)),
            ("torus", torus(1.0, 0.25, 32, 12)),
            ("fullscreen_triangle", fullscreen_triangle()),
        ]
    }

    #[test]
    fn procedural_meshes_are_well_formed() {
        for (name, m) in procedural() {
            check_mesh(name, &m);
        }
    }
}
