//! Wavefront OBJ loading through tobj, with size limits and errors that name
//! the file and say what is wrong with it.

use super::mtl::MtlMaterial;
use super::normals::compute_normals;
use super::polygons::triangulate;
use super::tangents::compute_tangents;
use super::{MeshData, Vertex};
use crate::assets;
use anyhow::{Context, Result, anyhow, bail};
use glam::Vec3;
use std::io::Read;
use std::path::Path;

/// Largest OBJ file `load_obj` reads.
pub const MAX_OBJ_BYTES: u64 = 256 * 1024 * 1024;
/// Most vertices `load_obj` accepts (after splitting by position/uv/normal).
pub const MAX_OBJ_VERTICES: usize = 16_000_000;

/// Loads a Wavefront OBJ through tobj (polygons triangulated by ear
/// clipping, src/geometry/polygons.rs; one index per vertex), merging all
/// its objects, groups and `usemtl` parts into one mesh. Materials are
/// ignored (`load_obj_file` reads them). Objects without normals in the
/// file get smooth normals ([`compute_normals`]); tangents are always
/// computed. A file without uvs loads with uv (0, 0) everywhere (and
/// arbitrary tangents).
///
/// Refuses, with an error naming the file: a missing or unreadable file, one
/// over 256 MiB (checked before reading) or with more than 16 million
/// vertices, malformed content, no triangles, NaN or infinite numbers, and
/// face indices out of range.
pub fn load_obj(path: &Path) -> Result<MeshData> {
    let file = load_obj_limited(path, MAX_OBJ_BYTES, MAX_OBJ_VERTICES, false)?;
    Ok(merge(file.parts))
}

/// One `usemtl` part of an OBJ file: the faces drawn with one material.
#[derive(Clone, Debug)]
pub struct ObjPart {
    /// Index into `ObjFile::materials`; None for faces before any `usemtl`
    /// or naming a material no MTL file defines.
    pub material: Option<usize>,
    pub mesh: MeshData,
}

/// An OBJ file with its materials: one part per material its faces use,
/// in the order the file first uses them.
#[derive(Clone, Debug)]
pub struct ObjFile {
    pub parts: Vec<ObjPart>,
    /// Every material of every `mtllib`, in file order.
    pub materials: Vec<MtlMaterial>,
    /// What was left out (a missing MTL file or texture, an unknown
    /// `usemtl`, an MTL key gloss does not use), one line each.
    pub warnings: Vec<String>,
}

/// `load_obj`, keeping the file's `usemtl` parts apart and reading the MTL
/// files its `mtllib` lines name (src/geometry/mtl.rs). A missing MTL file
/// is a warning (its faces take the default material); a malformed one an
/// error naming it and its line.
pub fn load_obj_file(path: &Path) -> Result<ObjFile> {
    load_obj_limited(path, MAX_OBJ_BYTES, MAX_OBJ_VERTICES, true)
}

/// All parts in one mesh, as `load_obj` gives it.
fn merge(parts: Vec<ObjPart>) -> MeshData {
    let mut mesh = MeshData::default();
    let coloured = parts.iter().any(|p| !p.mesh.colors.is_empty());
    for p in parts {
        let offset = mesh.vertices.len() as u32;
        if coloured {
            let mut c = p.mesh.colors;
            c.resize(p.mesh.vertices.len(), [1.0; 3]);
            mesh.colors.extend(c);
        }
        mesh.vertices.extend(p.mesh.vertices);
        mesh.indices
            .extend(p.mesh.indices.iter().map(|i| i + offset));
    }
    mesh
}

fn load_obj_limited(
    path: &Path,
    max_bytes: u64,
    max_vertices: usize,
    with_materials: bool,
) -> Result<ObjFile> {
    let name = path.display();
    let bytes: Vec<u8> = match assets::embedded(path) {
        Some(f) => f.contents().to_vec(),
        None => {
            // What is there, from its metadata alone: a FIFO is never opened.
            if let Some(why) = assets::not_a_file(path) {
                bail!("OBJ file {name} {why}");
            }
            let meta =
                std::fs::metadata(path).with_context(|| format!("cannot open OBJ file {name}"))?;
            if meta.len() > max_bytes {
                bail!(
                    "OBJ file {name} is too large: {} bytes, the limit is {max_bytes} bytes",
                    meta.len()
                );
            }
            let mut bytes = Vec::with_capacity(meta.len() as usize);
            std::fs::File::open(path)
                .and_then(|f| f.take(max_bytes + 1).read_to_end(&mut bytes))
                .with_context(|| format!("cannot read OBJ file {name}"))?;
            if bytes.len() as u64 > max_bytes {
                bail!(
                    "OBJ file {name} is too large: it grew past {max_bytes} bytes while being read"
                );
            }
            bytes
        }
    };
    // Cheap count before tobj allocates anything per vertex.
    let positions = bytes
        .split(|&b| b == b'\n')
        .filter(|l| {
            l.trim_ascii_start().starts_with(b"v ") || l.trim_ascii_start().starts_with(b"v\t")
        })
        .count();
    if positions > max_vertices {
        bail!(
            "OBJ file {name} is too large: {positions} vertex positions, the limit is {max_vertices}"
        );
    }

    let options = tobj::LoadOptions {
        // Ear clipping here (polygons.rs), not tobj's fan.
        triangulate: false,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let base = path.parent().unwrap_or(Path::new("."));
    let materials = std::cell::RefCell::new(Vec::<MtlMaterial>::new());
    let warnings = std::cell::RefCell::new(Vec::<String>::new());
    let failed = std::cell::RefCell::new(None::<anyhow::Error>);
    let loader = |lib: &Path| -> tobj::MTLLoadResult {
        if !with_materials {
            return Ok((Vec::new(), Default::default()));
        }
        let written = lib.to_string_lossy();
        let Some(mtl) = super::mtl::find_file(base, &written) else {
            warnings.borrow_mut().push(format!(
                "OBJ file {name}: mtllib {written}: {} not found: its faces take gloss's default material",
                base.join(written.replace('\\', "/")).display()
            ));
            return Ok((Vec::new(), Default::default()));
        };
        match super::mtl::load_both(&mtl) {
            Ok((ours, w, theirs)) => {
                let total = materials.borrow().len() + ours.len();
                if total > super::mtl::MAX_MTL_MATERIALS {
                    failed.borrow_mut().get_or_insert(anyhow!(
                        "OBJ file {name}: its MTL files define {total} materials, the limit is {}",
                        super::mtl::MAX_MTL_MATERIALS
                    ));
                    return Err(tobj::LoadError::MaterialParseError);
                }
                materials.borrow_mut().extend(ours);
                warnings.borrow_mut().extend(w);
                theirs
            }
            Err(e) => {
                failed.borrow_mut().get_or_insert(e);
                Err(tobj::LoadError::MaterialParseError)
            }
        }
    };
    let (models, _materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, loader)
        .map_err(|e| anyhow!("malformed OBJ file {name}: {}", describe_tobj_error(&e)))?;
    if let Some(e) = failed.into_inner() {
        return Err(e.context(format!("OBJ file {name}: its mtllib")));
    }
    let materials = materials.into_inner();
    let mut warnings = warnings.into_inner();
    if with_materials {
        unknown_materials(&bytes, &materials, &name.to_string(), &mut warnings);
    }

    // One part per material, in the order the file first uses it.
    let mut parts: Vec<ObjPart> = Vec::new();
    let mut total = 0;
    for model in &models {
        let mut part = model_mesh(model, &name.to_string())?;
        total += part.vertices.len();
        if total > max_vertices {
            bail!(
                "OBJ file {name} is too large: more than {max_vertices} vertices after splitting by uv and normal"
            );
        }
        let material = model.mesh.material_id.filter(|&m| m < materials.len());
        if part.indices.is_empty() {
            continue;
        }
        compute_tangents(&mut part);
        match parts.iter_mut().find(|p| p.material == material) {
            Some(p) => {
                let old = std::mem::take(&mut p.mesh);
                p.mesh = merge(vec![
                    ObjPart {
                        material,
                        mesh: old,
                    },
                    ObjPart {
                        material,
                        mesh: part,
                    },
                ]);
            }
            None => parts.push(ObjPart {
                material,
                mesh: part,
            }),
        }
    }
    if parts.iter().all(|p| p.mesh.indices.len() < 3) {
        bail!("OBJ file {name} contains no triangles");
    }
    Ok(ObjFile {
        parts,
        materials,
        warnings,
    })
}

/// One tobj model as a checked, triangulated mesh with unit normals.
fn model_mesh(model: &tobj::Model, name: &str) -> Result<MeshData> {
    let m = &model.mesh;
    let object = &model.name;
    if !m.positions.len().is_multiple_of(3) {
        bail!("malformed OBJ file {name}: object '{object}' has a partial position");
    }
    let n = m.positions.len() / 3;
    let finite = |values: &[f32], what: &str| -> Result<()> {
        match values.iter().position(|x| !x.is_finite()) {
            Some(_) => bail!("OBJ file {name}: object '{object}' has a NaN or infinite {what}"),
            None => Ok(()),
        }
    };
    finite(&m.positions, "vertex position")?;
    finite(&m.normals, "normal")?;
    finite(&m.texcoords, "texture coordinate")?;
    if let Some(&bad) = m.indices.iter().find(|&&i| i as usize >= n) {
        bail!(
            "OBJ file {name}: object '{object}' has face index {bad} out of range ({n} vertices)"
        );
    }
    let indices = triangles(m, name, object)?;
    finite(&m.vertex_color, "vertex colour")?;
    let has_normals = m.normals.len() == m.positions.len();
    let has_colors = m.vertex_color.len() == m.positions.len();
    let has_uvs = m.texcoords.len() == 2 * n;
    let mut part = MeshData {
        vertices: (0..n)
            .map(|i| Vertex {
                position: [
                    m.positions[3 * i],
                    m.positions[3 * i + 1],
                    m.positions[3 * i + 2],
                ],
                normal: if has_normals {
                    [m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]]
                } else {
                    [0.0; 3]
                },
                uv: if has_uvs {
                    [m.texcoords[2 * i], m.texcoords[2 * i + 1]]
                } else {
                    [0.0; 2]
                },
                tangent: [1.0, 0.0, 0.0, 1.0],
            })
            .collect(),
        indices,
        colors: if has_colors {
            m.vertex_color
                .chunks_exact(3)
                .map(|c| [c[0], c[1], c[2]])
                .collect()
        } else {
            Vec::new()
        },
    };
    if !has_normals {
        compute_normals(&mut part);
    }
    for v in &mut part.vertices {
        // File normals of zero length fall back to +y rather than NaN.
        v.normal = Vec3::from(v.normal)
            .try_normalize()
            .unwrap_or(Vec3::Y)
            .to_array();
    }
    Ok(part)
}

/// The model's faces as triangles: each face of n corners (tobj's
/// `face_arities`; none when every face is a triangle) ear-clipped.
fn triangles(m: &tobj::Mesh, name: &str, object: &str) -> Result<Vec<u32>> {
    if m.face_arities.is_empty() {
        if !m.indices.len().is_multiple_of(3) {
            bail!("malformed OBJ file {name}: object '{object}' has a partial triangle");
        }
        return Ok(m.indices.clone());
    }
    let total: usize = m.face_arities.iter().map(|&a| a as usize).sum();
    if total != m.indices.len() {
        bail!("malformed OBJ file {name}: object '{object}' has a partial face");
    }
    let mut out = Vec::with_capacity(3 * total);
    let mut at = 0;
    for &arity in &m.face_arities {
        let face = &m.indices[at..at + arity as usize];
        at += arity as usize;
        let corners: Vec<Vec3> = face
            .iter()
            .map(|&i| Vec3::from_slice(&m.positions[3 * i as usize..3 * i as usize + 3]))
            .collect();
        out.extend(triangulate(&corners).iter().map(|&k| face[k as usize]));
    }
    Ok(out)
}

/// A warning for each `usemtl` name no MTL file defines (tobj drops the name).
fn unknown_materials(bytes: &[u8], materials: &[MtlMaterial], name: &str, w: &mut Vec<String>) {
    let mut seen: Vec<String> = Vec::new();
    for line in bytes.split(|&b| b == b'\n') {
        let line = String::from_utf8_lossy(line);
        let Some(m) = line.trim().strip_prefix("usemtl") else {
            continue;
        };
        let m = m.trim();
        if m.is_empty() || materials.iter().any(|x| x.name == m) || seen.iter().any(|s| s == m) {
            continue;
        }
        if seen.len() == 16 {
            w.push(format!(
                "OBJ file {name}: more usemtl names no MTL file defines"
            ));
            break;
        }
        seen.push(m.to_string());
        w.push(format!(
            "OBJ file {name}: usemtl {m}: no MTL file defines it: its faces take gloss's default material"
        ));
    }
}

fn describe_tobj_error(e: &tobj::LoadError) -> String {
    use tobj::LoadError as E;
    match e {
        E::FaceVertexOutOfBounds | E::FaceTexCoordOutOfBounds | E::FaceNormalOutOfBounds => {
            format!("{e} (face index out of range)")
        }
        E::ReadError => "read error (not UTF-8 text?)".to_string(),
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests;
