//! Planar mirrors in a scene file (notes 05, "Planar Reflections"): any
//! object with a `mirror = { ... }` table is a mirror. Its mesh must be flat
//! (the built-in `plane`, or an OBJ whose faces are coplanar: checked here);
//! its plane is the mesh's plane carried by the object's model matrix.
//!
//! ```toml
//! [[objects]]
//! name = "mirror"
//! mesh = "plane"
//! position = [0.0, 1.5, -3.0]
//! rotation = [90.0, 0.0, 0.0]            # the plane's +y now faces +z
//! mirror = { tint = [0.9, 0.95, 1.0], reflectance = 0.9 }
//! ```

use super::checks::{finite, non_negative};
use super::{MeshSource, Object};
use crate::assets;
use crate::geometry::{self, MeshData};
use crate::math;
use anyhow::{Result, bail};
use glam::{Mat3, Vec3, Vec4};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The `mirror` table of an object.
#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub(super) struct MirrorFile {
    /// Multiplies the reflection (linear RGB).
    #[serde(default = "white")]
    tint: [f32; 3],
    /// The fraction of light the mirror reflects.
    #[serde(default = "one")]
    reflectance: f32,
    /// A greyscale PNG that roughens (darkens, smudges) the reflection.
    roughness: Option<String>,
    /// An unbounded mirror (a lake): no stencil pass is needed.
    #[serde(default)]
    infinite: bool,
    /// The mirror fills an opening in a wall drawn around it: no stencil
    /// or colour clear is needed.
    #[serde(default)]
    covered: bool,
    /// A convex spherical mirror (mesh "sphere" or "icosphere", scaled
    /// alike on every axis): each vertex is reflected on its own.
    #[serde(default)]
    curved: bool,
}

fn white() -> [f32; 3] {
    [1.0, 1.0, 1.0]
}
fn one() -> f32 {
    1.0
}

/// A mirror, as the renderer uses it.
#[derive(Clone, Debug, PartialEq)]
pub struct Mirror {
    pub tint: Vec3,
    pub reflectance: f32,
    pub roughness: Option<PathBuf>,
    pub infinite: bool,
    pub covered: bool,
    /// A convex spherical mirror (`Object::curved_mirror`).
    pub curved: bool,
    /// The mesh's plane in object space: a point on it and the unit normal
    /// its front faces look along.
    pub local_point: Vec3,
    pub local_normal: Vec3,
    /// The mesh's box in object space (lowest, highest corner): what can
    /// be seen of the mirror (src/scene/mirror_views.rs).
    pub local_bounds: (Vec3, Vec3),
}

impl Object {
    /// The mirror's plane in world space, `(n, -n . p)` with unit n on the
    /// side its front faces look at (notes 05: "a plane derived from its
    /// transform"). None when the object is not a mirror, or its model
    /// matrix flattens the plane's normal away.
    pub fn mirror_plane(&self) -> Option<Vec4> {
        let m = self.mirror.as_ref()?;
        let point = self.model.transform_point3(m.local_point);
        // Normals go through the normal matrix (its cofactor form also
        // copes with a scale of 0 along the plane).
        let cofactor = math::cofactor(&self.model);
        if m.curved {
            return None;
        }
        math::reflection::plane(point, cofactor * m.local_normal)
    }

    /// A curved mirror's sphere in world space, (centre, radius); None when
    /// the object is not a curved mirror or is not scaled alike on every
    /// axis (then it is no sphere).
    pub fn curved_mirror(&self) -> Option<Vec4> {
        if !self.mirror.as_ref()?.curved {
            return None;
        }
        let l = Mat3::from_mat4(self.model);
        let (a, b, c) = (l.x_axis.length(), l.y_axis.length(), l.z_axis.length());
        let r = a.max(b).max(c);
        let alike = r > 0.0 && (a.min(b).min(c) / r) > 1.0 - 1e-4;
        alike.then(|| self.model.transform_point3(Vec3::ZERO).extend(r))
    }
}

/// Check one object's `mirror` table (`key` names it in messages).
pub(super) fn mirror(
    key: &str,
    file: &MirrorFile,
    mesh: &MeshSource,
    base: &Path,
) -> Result<Mirror> {
    finite(&format!("{key}.tint"), &file.tint)?;
    non_negative(&format!("{key}.tint"), &file.tint)?;
    if !(0.0..=1.0).contains(&file.reflectance) {
        bail!(
            "{key}.reflectance: expected a fraction in [0, 1], found {}",
            file.reflectance
        );
    }
    let roughness = match &file.roughness {
        None => None,
        Some(t) => {
            let p = super::checks::relative_to(base, t);
            if let Some(why) = assets::not_a_file(&p) {
                bail!("{key}.roughness: file {} {why}", p.display());
            }
            Some(p)
        }
    };
    if file.infinite && file.covered {
        bail!("{key}: a mirror is either infinite or covered, not both");
    }
    let (local_point, local_normal, local_bounds) = match mesh {
        // geometry::uv_sphere and icosphere: radius 1 about the origin.
        MeshSource::Sphere | MeshSource::Icosphere if file.curved => {
            (Vec3::ZERO, Vec3::Y, (Vec3::splat(-1.0), Vec3::ONE))
        }
        _ if file.curved => bail!(
            "{key}.curved: a curved mirror is a sphere: mesh \"sphere\" or \"icosphere\", not {mesh:?}"
        ),
        // geometry::plane(2, 2): the xz plane from -1 to 1, facing +y.
        MeshSource::Plane => (
            Vec3::ZERO,
            Vec3::Y,
            (Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0)),
        ),
        MeshSource::Obj(path) => {
            let data = geometry::load_obj(path)?;
            let (p, n) =
                flat(&data).map_err(|e| anyhow::anyhow!("{key}: {} {e}", path.display()))?;
            (p, n, bounds(&data))
        }
        other => bail!(
            "{key}: a mirror must be flat: mesh \"plane\" or an .obj whose faces are coplanar, not {other:?}"
        ),
    };
    Ok(Mirror {
        tint: Vec3::from(file.tint),
        reflectance: file.reflectance,
        roughness,
        infinite: file.infinite,
        covered: file.covered,
        curved: file.curved,
        local_point,
        local_normal,
        local_bounds,
    })
}

/// A mesh's box in its own space (lowest, highest corner).
fn bounds(mesh: &MeshData) -> (Vec3, Vec3) {
    let points = mesh.vertices.iter().map(|v| Vec3::from(v.position));
    let lo = points.clone().fold(Vec3::INFINITY, Vec3::min);
    let hi = points.fold(Vec3::NEG_INFINITY, Vec3::max);
    (lo, hi)
}

/// The plane of a flat mesh (a point on it and the normal its faces look
/// along), or why the mesh is not flat.
pub fn flat(mesh: &MeshData) -> Result<(Vec3, Vec3)> {
    let p = |i: u32| Vec3::from(mesh.vertices[i as usize].position);
    // The area-weighted normal: the sum of the triangles' cross products.
    let mut sum = Vec3::ZERO;
    for t in mesh.indices.chunks_exact(3) {
        sum += (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
    }
    let Some(normal) = sum.try_normalize() else {
        bail!("has no area (or faces that cancel out): it defines no plane");
    };
    let n = mesh.vertices.len() as f32;
    let centre = mesh
        .vertices
        .iter()
        .map(|v| Vec3::from(v.position))
        .sum::<Vec3>()
        / n;
    let extent = mesh
        .vertices
        .iter()
        .map(|v| Vec3::from(v.position).distance(centre))
        .fold(0.0f32, f32::max);
    let worst = mesh
        .vertices
        .iter()
        .map(|v| (Vec3::from(v.position) - centre).dot(normal).abs())
        .fold(0.0f32, f32::max);
    if worst > 1e-4 * extent.max(1e-6) {
        bail!(
            "is not flat: a vertex lies {worst} off the faces' mean plane (mesh size {extent}); a mirror must be planar"
        );
    }
    Ok((centre, normal))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_is_flat_and_a_cube_is_not() {
        let (p, n) = flat(&geometry::plane(2.0, 3.0, 4)).unwrap();
        assert!(p.length() < 1e-6 && (n - Vec3::Y).length() < 1e-6);
        let e = flat(&geometry::cube()).unwrap_err().to_string();
        // A closed cube's faces cancel out.
        assert!(e.contains("no area"), "{e}");
        let mut bent = geometry::plane(2.0, 2.0, 2);
        bent.vertices[4].position[1] = 0.3;
        let e = flat(&bent).unwrap_err().to_string();
        assert!(e.contains("not flat"), "{e}");
    }
}
