//! A whole glTF 2.0 scene (.gltf with its buffers, .glb, data: URIs): the
//! node tree, every triangle primitive of every mesh, the materials as the
//! file writes them, the node animations, and the first skin
//! (`gltf::skin_of`). `scene::gltf_objects` turns it into gloss objects,
//! materials and keyframe tracks; docs/gltf.md says what is read and what
//! is dropped.
//!
//! Bounded before anything is allocated (`gltf_buffers`): the file's bytes,
//! every accessor against its view and buffer, [`MAX_GLTF_NODES`] nodes and
//! [`MAX_GLTF_VERTICES`] vertices in all. The node tree is put in order
//! once (parents first), so a chain of 200,000 nodes costs what 200,000
//! siblings cost.

use super::gltf_buffers::{self, Parsed};
use super::gltf_material::{GltfMaterial, material};
use super::skin::{Clip, SkinnedMesh};
use super::{MAX_GLTF_VERTICES, MeshData, Vertex, compute_normals, compute_tangents};
use crate::assets;
use anyhow::{Result, bail};
use glam::Vec3;
use gltf::mesh::Mode;
use std::collections::BTreeSet;
use std::path::Path;
use std::sync::Arc;

use super::gltf_nodes::read_nodes;
pub use super::gltf_nodes::{GltfNode, MAX_GLTF_NODES, MAX_GLTF_VALUE};

/// One triangle primitive: its triangles (in the node's space, gloss's
/// conventions: uv v up, unit normals, tangents) and its material.
#[derive(Clone, Debug)]
pub struct GltfPrimitive {
    pub data: Arc<MeshData>,
    /// Index into `GltfScene::materials` (None: glTF's default material).
    pub material: Option<usize>,
}

#[derive(Clone, Debug)]
pub struct GltfScene {
    pub nodes: Vec<GltfNode>,
    /// Every node once, each after its parent.
    pub order: Vec<usize>,
    /// Per mesh, its triangle primitives.
    pub meshes: Vec<Vec<GltfPrimitive>>,
    pub materials: Vec<GltfMaterial>,
    /// The animations (their channels name nodes).
    pub clips: Vec<Clip>,
    /// The first skinned node's skin (the node is `nodes[skin.mesh_node]`),
    /// and the material of its first primitive.
    pub skin: Option<(Arc<SkinnedMesh>, Option<usize>)>,
    pub warnings: Vec<String>,
}

/// Read the glTF scene at `path`.
pub fn load_gltf_scene(path: &Path) -> Result<GltfScene> {
    let name = path.display().to_string();
    let bytes = assets::read(path, gltf_buffers::MAX_GLTF_BYTES, "glTF file")?;
    read_scene(&bytes, path, &name)
}

/// `load_gltf_scene` on bytes already read, with any panic inside the
/// gltf crate turned into an error (see `gltf::read_guarded`).
pub fn read_scene(bytes: &[u8], path: &Path, name: &str) -> Result<GltfScene> {
    match super::gltf::quietly(|| read(bytes, path, name)) {
        Ok(r) => r,
        Err(_) => bail!("malformed glTF file {name}: the gltf crate could not read it"),
    }
}

fn read(bytes: &[u8], path: &Path, name: &str) -> Result<GltfScene> {
    let parsed = gltf_buffers::parse(bytes, path, name)?;
    let doc = &parsed.doc;
    let mut warnings = Vec::new();
    // What gloss leaves out, gathered into one warning for the file.
    let mut dropped: BTreeSet<String> = BTreeSet::new();
    let (nodes, order) = read_nodes(doc, name)?;
    let skinned_node = doc
        .nodes()
        .find(|n| n.mesh().is_some() && n.skin().is_some());
    let skin = match &skinned_node {
        Some(n) => {
            let (s, mut w) = super::gltf::skin_of(&parsed, n, name)?;
            warnings.append(&mut w);
            let mats: BTreeSet<Option<usize>> = n
                .mesh()
                .into_iter()
                .flat_map(|m| m.primitives().map(|p| p.material().index()))
                .collect();
            if mats.len() > 1 {
                dropped.insert(format!(
                    "the skinned mesh's other {} materials (it is drawn with its first primitive's)",
                    mats.len() - 1
                ));
            }
            Some((Arc::new(s), mats.into_iter().next().flatten()))
        }
        None => None,
    };
    let skinned_others = doc
        .nodes()
        .filter(|n| n.mesh().is_some() && n.skin().is_some())
        .count()
        .saturating_sub(1);
    if skinned_others > 0 {
        dropped.insert(format!(
            "{skinned_others} skinned nodes after the first (gloss draws one skin per file)"
        ));
    }
    let mut meshes = Vec::new();
    let mut vertices = 0usize;
    for m in doc.meshes() {
        let mut prims = Vec::new();
        // The skinned mesh is drawn through its skin only.
        let only_skinned = doc
            .nodes()
            .filter(|n| n.mesh().is_some_and(|x| x.index() == m.index()))
            .all(|n| n.skin().is_some());
        if only_skinned && skinned_node.is_some() {
            meshes.push(prims);
            continue;
        }
        for p in m.primitives() {
            if p.morph_targets().len() > 0 {
                dropped.insert("morph targets".into());
            }
            match primitive(&parsed, &p, name, &m, &mut vertices)? {
                Some(data) => prims.push(GltfPrimitive {
                    data: Arc::new(data),
                    material: p.material().index(),
                }),
                None => {
                    dropped.insert(format!("{:?} primitives (gloss draws triangles)", p.mode()));
                }
            }
        }
        meshes.push(prims);
    }
    let materials = (doc.materials())
        .map(|m| material(&m, path, name, &mut dropped))
        .collect::<Result<Vec<_>>>()?;
    let clips = super::gltf::read_clips(doc, name, &parsed.get(), &mut warnings)?;
    if doc.cameras().len() > 0 {
        dropped.insert(format!("{} cameras", doc.cameras().len()));
    }
    for ext in doc.extensions_used() {
        if !gltf_buffers::SUPPORTED_EXTENSIONS.contains(&ext) {
            dropped.insert(format!("extension {ext}"));
        }
    }
    if !dropped.is_empty() {
        let list: Vec<String> = dropped.into_iter().collect();
        warnings.push(format!(
            "glTF file {name}: gloss leaves out {}",
            list.join("; ")
        ));
    }
    Ok(GltfScene {
        nodes,
        order,
        meshes,
        materials,
        clips,
        skin,
        warnings,
    })
}

/// One primitive's triangles (None: points or lines, which gloss does not
/// draw). `vertices` counts the file's vertices so far.
fn primitive(
    parsed: &Parsed,
    p: &gltf::Primitive,
    name: &str,
    mesh: &gltf::Mesh,
    vertices: &mut usize,
) -> Result<Option<MeshData>> {
    let what = format!(
        "{name}: meshes[{}] ('{}') primitives[{}]",
        mesh.index(),
        mesh.name().unwrap_or(""),
        p.index()
    );
    let mode = p.mode();
    if !matches!(
        mode,
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Ok(None);
    }
    let count = p.get(&gltf::Semantic::Positions).map_or(0, |a| a.count());
    *vertices = vertices.saturating_add(count);
    if *vertices > MAX_GLTF_VERTICES {
        bail!("{name} is too large: more than {MAX_GLTF_VERTICES} vertices");
    }
    let r = p.reader(parsed.get());
    let positions: Vec<[f32; 3]> = r
        .read_positions()
        .ok_or_else(|| anyhow::anyhow!("{what} has no POSITION"))?
        .collect();
    let n = positions.len();
    let normals: Option<Vec<[f32; 3]>> = r.read_normals().map(|x| x.collect());
    let uvs: Option<Vec<[f32; 2]>> = r.read_tex_coords(0).map(|x| x.into_f32().collect());
    let colors: Option<Vec<[f32; 3]>> = r.read_colors(0).map(|x| x.into_rgb_f32().collect());
    if normals.as_ref().is_some_and(|v| v.len() != n)
        || uvs.as_ref().is_some_and(|v| v.len() != n)
        || colors.as_ref().is_some_and(|v| v.len() != n)
    {
        bail!("{what}: NORMAL, TEXCOORD_0 or COLOR_0 has a count other than POSITION's {n}");
    }
    let mut data = MeshData::default();
    for i in 0..n {
        let nrm = normals.as_ref().map_or([0.0, 1.0, 0.0], |v| v[i]);
        let uv = uvs.as_ref().map_or([0.0; 2], |v| [v[i][0], 1.0 - v[i][1]]);
        let p = positions[i];
        if !p.iter().chain(&nrm).chain(&uv).all(|x| x.is_finite()) {
            bail!("{what}: vertex {i}: a position, normal or uv is not finite");
        }
        if p.iter().any(|x| x.abs() > MAX_GLTF_VALUE) {
            bail!("{what}: vertex {i}: position {p:?} is past gloss's world limit of 1e9");
        }
        let nv = Vec3::from(nrm);
        let nrm = if nv.length_squared() > 1e-12 {
            nv.normalize().to_array()
        } else {
            [0.0, 1.0, 0.0]
        };
        data.vertices.push(Vertex {
            position: p,
            normal: nrm,
            uv,
            tangent: [1.0, 0.0, 0.0, 1.0],
        });
    }
    if let Some(c) = colors {
        data.colors = c;
    }
    let ix: Vec<u32> = match r.read_indices() {
        Some(ix) => ix.into_u32().collect(),
        None => (0..n as u32).collect(),
    };
    if let Some(bad) = ix.iter().find(|&&i| i as usize >= n) {
        bail!("{what}: index {bad} is out of range ({n} vertices)");
    }
    if mode == Mode::Triangles && !ix.len().is_multiple_of(3) {
        bail!("{what} has a partial triangle ({} indices)", ix.len());
    }
    data.indices = triangles(mode, &ix);
    if data.indices.is_empty() {
        bail!(
            "{what} has no whole triangle ({} indices, {mode:?})",
            ix.len()
        );
    }
    if normals.is_none() {
        compute_normals(&mut data);
    }
    compute_tangents(&mut data);
    Ok(Some(data))
}

/// A list of triangles from `ix` drawn as `mode` (the glTF 2.0
/// specification, §3.7.2.1): a list as it is (a partial last triangle
/// dropped), a strip's triangle i as (i, i+1, i+2) for even i and
/// (i, i+2, i+1) for odd i (so that all wind alike), a fan's as
/// (i+1, i+2, 0).
pub fn triangles(mode: Mode, ix: &[u32]) -> Vec<u32> {
    match mode {
        Mode::TriangleStrip => (0..ix.len().saturating_sub(2))
            .flat_map(|i| {
                if i % 2 == 0 {
                    [ix[i], ix[i + 1], ix[i + 2]]
                } else {
                    [ix[i], ix[i + 2], ix[i + 1]]
                }
            })
            .collect(),
        Mode::TriangleFan => (0..ix.len().saturating_sub(2))
            .flat_map(|i| [ix[i + 1], ix[i + 2], ix[0]])
            .collect(),
        _ => ix[..ix.len() / 3 * 3].to_vec(),
    }
}
