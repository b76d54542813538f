//! The triangles behind each `MeshSource`: the built-in shapes at the
//! tessellation every part of gloss uses, or an OBJ file. The draw list
//! uploads them to the GPU; the CPU shadow reference (`lighting`) ray-traces
//! the same triangles, so both see exactly the same surfaces.

use super::MeshSource;
use crate::geometry::{self, MeshData};
use anyhow::Result;

/// The mesh data of `source`, in the object's own (model) space.
pub fn mesh_data(source: &MeshSource) -> Result<MeshData> {
    Ok(match source {
        MeshSource::Sphere => geometry::uv_sphere(32, 64),
        MeshSource::Icosphere => geometry::icosphere(3),
        MeshSource::Cube => geometry::cube(),
        MeshSource::Plane => geometry::plane(2.0, 2.0, 1),
        MeshSource::Cylinder => geometry::cylinder(48),
        MeshSource::Cone => geometry::cone(48),
        MeshSource::Torus => geometry::torus(1.0, 0.35, 64, 24),
        MeshSource::Obj(path) => geometry::load_obj(path)?,
        // The skin in its bind pose: the draw list poses it (each object
        // its own way), from `Object::skin`.
        MeshSource::Gltf(path) => geometry::load_gltf(path)?.0.mesh,
        // Read with its file when the scene loaded.
        MeshSource::GltfPart(part) => (*part.data).clone(),
    })
}
