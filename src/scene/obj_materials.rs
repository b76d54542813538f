//! An OBJ file's own materials (`mesh = "model.obj"` with no `material`):
//! the file is split into one part per `usemtl`, each drawn with the
//! material its MTL file defines (src/geometry/mtl.rs maps the keys). The
//! object draws the first part; each other part becomes a child object of
//! it (named `OBJECT.MATERIAL`), at the identity, so culling, sorting,
//! shadows, mirrors and every render path see each part as an object.
//! A scene's `material = ...` overrides the file's materials: the object
//! is then one mesh with that material.

use super::{AlphaTest, Cull, Material, MeshSource, Object};
use crate::geometry::MtlMaterial;
use crate::scene::meshes;
use anyhow::Result;
use glam::{Mat4, Vec3};
use std::path::Path;

/// The reference of the alpha test an MTL's alpha gets (notes 05: "Do not
/// let alpha < 0.5 pass through").
pub const MTL_ALPHA_REF: f32 = 0.5;

/// gloss's material for MTL material `m` of OBJ file `obj`, named
/// `FILE/MATERIAL`. Alpha (map_d, or an alpha channel in map_Kd) is an
/// alpha test, alpha >= 0.5, drawn from both sides (a leaf is one quad);
/// d < 1 sends the material to the transparency pass (notes 05 "Blending").
pub fn material(m: &MtlMaterial, obj: &Path) -> Material {
    let file = obj.file_name().map(|f| f.to_string_lossy().into_owned());
    let alpha_in_map = (m.diffuse_map.as_deref())
        .is_some_and(|p| crate::gl::image_file::has_alpha(p).unwrap_or(false));
    let cut_out = m.alpha_map.is_some() || alpha_in_map;
    Material {
        name: format!("{}/{}", file.unwrap_or_default(), m.name),
        diffuse: Vec3::from(m.diffuse),
        diffuse_texture: m.diffuse_map.clone(),
        normal_map: m.normal_map.clone(),
        specular: Vec3::from(m.specular),
        shininess: m.shininess,
        alpha_test: if cut_out {
            AlphaTest::Gequal
        } else {
            AlphaTest::Always
        },
        alpha_ref: MTL_ALPHA_REF,
        opacity: m.opacity,
        cull: if cut_out { Cull::None } else { Cull::Back },
        specular_map: m.specular_map.clone(),
        normal_scale: m.normal_scale,
        alpha_map: m.alpha_map.clone(),
        ..Material::default()
    }
}

/// Object `o` (index `index`, mesh the OBJ file `path`) drawn with its
/// file's materials: `o` takes part 0 and `extra` gets a child for each
/// other part; the materials are appended to `materials` (once per file:
/// `first` holds where each file's start). Returns the file's warnings
/// (empty when the file has no materials: `o` stays one mesh, material 0).
pub(super) fn expand(
    o: &mut Object,
    index: usize,
    path: &Path,
    materials: &mut Vec<Material>,
    first: &mut Vec<(std::path::PathBuf, usize)>,
    extra: &mut Vec<Object>,
    taken: &dyn Fn(&str) -> bool,
) -> Result<Vec<String>> {
    let file = meshes::obj_file(path)?;
    if file.materials.is_empty() {
        return Ok(file.warnings.clone());
    }
    let start = match first.iter().find(|(p, _)| p == path) {
        Some(&(_, s)) => s,
        None => {
            let s = materials.len();
            materials.extend(file.materials.iter().map(|m| material(m, path)));
            first.push((path.to_path_buf(), s));
            s
        }
    };
    // Faces with no (known) material take gloss's default, material 0.
    let of = |k: usize| file.parts[k].material.map_or(0, |m| start + m);
    o.mesh = MeshSource::ObjPart(path.to_path_buf(), 0);
    o.material = of(0);
    for k in 1..file.parts.len() {
        let what = file.parts[k]
            .material
            .map_or("default", |m| file.materials[m].name.as_str());
        let mut name = format!("{}.{what}", o.name);
        if taken(&name) || extra.iter().any(|e| e.name == name) {
            name = format!("{}.{what}#{k}", o.name);
        }
        extra.push(Object {
            name,
            mesh: MeshSource::ObjPart(path.to_path_buf(), k),
            material: of(k),
            position: Vec3::ZERO,
            rotation: Vec3::ZERO,
            scale: Vec3::ONE,
            parent: Some(index),
            model: Mat4::IDENTITY,
            mirror: None,
            orientation: None,
            skin: None,
            light_map: None,
        });
    }
    Ok(file.warnings.clone())
}
