//! The triangles behind each `MeshSource`: the built-in shapes at the
//! tessellation every part of gloss uses, or an OBJ file. The draw list
//! uploads them to the GPU; the CPU shadow reference (`lighting`) ray-traces
//! the same triangles, so both see exactly the same surfaces.

use super::MeshSource;
use crate::geometry::{self, MeshData, ObjFile};
use anyhow::{Result, anyhow};
use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;

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
        MeshSource::ObjPart(path, k) => {
            let file = obj_file(path)?;
            let part = file.parts.get(*k).ok_or_else(|| {
                anyhow!(
                    "OBJ file {} has {} material parts, not {}",
                    path.display(),
                    file.parts.len(),
                    k + 1
                )
            })?;
            part.mesh.clone()
        }
        // The skin in its bind pose: the draw list poses it (each object
        // its own way), from `Object::skin`.
        MeshSource::Gltf(path) => geometry::load_gltf(path)?.0.mesh,
        // Read with its file when the scene loaded.
        MeshSource::GltfPart(part) => (*part.data).clone(),
    })
}

thread_local! {
    /// The last OBJ file read with its materials: the scene reads it to
    /// make its parts' objects and the draw list reads each part, so a
    /// model of n materials is parsed once, not n + 1 times. One file is
    /// kept, per thread.
    static LAST_OBJ: RefCell<Option<(PathBuf, Rc<ObjFile>)>> = const { RefCell::new(None) };
}

/// Forget the OBJ file `obj_file` keeps: a scene being loaded reads its
/// files again (an edited MTL shows).
pub fn forget_obj_files() {
    LAST_OBJ.set(None);
}

/// The OBJ file at `path` with its materials and `usemtl` parts
/// (`geometry::load_obj_file`), read once while it is the last one asked for.
pub fn obj_file(path: &Path) -> Result<Rc<ObjFile>> {
    if let Some(f) = LAST_OBJ.with_borrow(|l| {
        l.as_ref()
            .filter(|(p, _)| p == path)
            .map(|(_, f)| f.clone())
    }) {
        return Ok(f);
    }
    let f = Rc::new(geometry::load_obj_file(path)?);
    LAST_OBJ.set(Some((path.to_path_buf(), f.clone())));
    Ok(f)
}
