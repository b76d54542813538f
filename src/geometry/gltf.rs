//! Skinned meshes from glTF 2.0 files (.glb, or .gltf with its .bin beside
//! it), read with the `gltf` crate: the first node that has both a mesh and
//! a skin gives the skin (every triangle primitive of its mesh, merged), its
//! joints and inverse bind matrices, the whole node tree, and every
//! animation as a [`Clip`].
//!
//! What is refused, with an error that names the file: a file over 64 MiB
//! or with more than 16 million vertices, a malformed file, no skinned
//! mesh, a primitive that is not triangles or lacks POSITION, JOINTS_0 or
//! WEIGHTS_0, a joint index out of range, NaN or infinite numbers, a vertex
//! whose weights are all zero (naming the mesh and the vertex), a node with
//! two parents, a zero quaternion, an inverse bind matrix past the world
//! limit, and CUBICSPLINE animation samplers
//! (gloss's cubic keys are Catmull-Rom; a clip with explicit tangents is
//! refused rather than played differently). Weights that do not sum to 1
//! are scaled so that they do, and the returned warnings say so. Buffers
//! (the .glb chunk, data: URIs, files) and every accessor's count are
//! checked first, in `gltf_buffers`.

use super::gltf_buffers::Parsed;
use super::skin::{Channel, ChannelTrack, Clip, SkinNode, SkinnedMesh};
use super::{MeshData, Vertex, compute_normals, compute_tangents};
use crate::assets;
use crate::math::keyframes::{Interpolation, Track};
use crate::math::skinning::{MAX_INFLUENCES, normalised_weights};
use anyhow::{Result, anyhow, bail};
use glam::{Mat4, Quat, Vec3};
use gltf::animation::util::ReadOutputs;
use std::path::Path;

pub use super::gltf_buffers::MAX_GLTF_BYTES;
use super::gltf_nodes::MAX_GLTF_VALUE;

/// Most vertices `load_gltf` accepts in the skinned mesh.
pub const MAX_GLTF_VERTICES: usize = 16_000_000;

/// Read the skinned mesh in the glTF file at `path`; also returns warnings
/// (weights renormalised, morph targets ignored).
pub fn load_gltf(path: &Path) -> Result<(SkinnedMesh, Vec<String>)> {
    let name = path.display().to_string();
    let bytes = assets::read(path, MAX_GLTF_BYTES, "glTF file")?;
    read_guarded(&bytes, path, &name)
}

/// `read`, with any panic inside the gltf crate turned into an error. The
/// crate checks most of a file, but some malformed files (a mesh with an
/// attribute name it cannot parse, found by the corruption test) make it
/// unwrap what it did not check. So a hostile file is an error, never a
/// crash, and the panic's message is kept off stderr.
pub fn read_guarded(bytes: &[u8], path: &Path, name: &str) -> Result<(SkinnedMesh, Vec<String>)> {
    match quietly(|| read(bytes, path, name)) {
        Ok(r) => r,
        Err(_) => bail!("malformed glTF file {name}: the gltf crate could not read it"),
    }
}

thread_local! {
    static QUIET: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// catch_unwind, with the panic hook silent on this thread meanwhile (the
/// hook stays as it was for every other panic, on every thread).
pub(super) fn quietly<T>(f: impl FnOnce() -> T + std::panic::UnwindSafe) -> std::thread::Result<T> {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !QUIET.with(|q| q.get()) {
                previous(info)
            }
        }));
    });
    QUIET.with(|q| q.set(true));
    let r = std::panic::catch_unwind(f);
    QUIET.with(|q| q.set(false));
    r
}

/// `load_gltf` on bytes already read; `path` locates external buffers.
pub fn read(bytes: &[u8], path: &Path, name: &str) -> Result<(SkinnedMesh, Vec<String>)> {
    let parsed =
        super::gltf_buffers::parse(bytes, path, name).map_err(|e| anyhow!("glTF file {e:#}"))?;
    let node = parsed
        .doc
        .nodes()
        .find(|n| n.mesh().is_some() && n.skin().is_some())
        .ok_or_else(|| {
            anyhow!("glTF file {name} has no skinned mesh (no node with both a mesh and a skin)")
        })?;
    skin_of(&parsed, &node, name)
}

/// The skin of `node` (it has a mesh and a skin) in a parsed file, with
/// the whole node tree and every animation.
pub fn skin_of(
    parsed: &Parsed,
    node: &gltf::Node,
    name: &str,
) -> Result<(SkinnedMesh, Vec<String>)> {
    let file = &parsed.doc;
    let get = parsed.get();
    let mut warnings = Vec::new();
    let (mesh, skin) = (node.mesh().unwrap(), node.skin().unwrap());
    let mesh_name = mesh
        .name()
        .map_or(format!("mesh {}", mesh.index()), |n| format!("mesh '{n}'"));
    let joint_count = skin.joints().count();
    if joint_count == 0 || joint_count > u16::MAX as usize + 1 {
        bail!("glTF file {name}: the skin has {joint_count} joints (1 to 65536 allowed)");
    }

    let mut data = MeshData::default();
    let (mut joints, mut weights) = (Vec::new(), Vec::new());
    let mut has_normals = true;
    let (mut renormalised, mut first_renormalised) = (0usize, None);
    for prim in mesh.primitives() {
        let what = format!("glTF file {name}: {mesh_name} primitive {}", prim.index());
        if prim.mode() != gltf::mesh::Mode::Triangles {
            bail!("{what} is {:?}, not triangles", prim.mode());
        }
        if prim.morph_targets().len() > 0 {
            warnings.push(format!("{what}: morph targets are ignored"));
        }
        let count = prim
            .get(&gltf::Semantic::Positions)
            .map_or(0, |a| a.count());
        if data.vertices.len() + count > MAX_GLTF_VERTICES {
            bail!("glTF file {name} is too large: more than {MAX_GLTF_VERTICES} vertices");
        }
        let r = prim.reader(get.clone());
        let missing = |attr: &str| anyhow!("{what} has no {attr} (or it lies outside its buffer)");
        let positions: Vec<[f32; 3]> = r
            .read_positions()
            .ok_or_else(|| missing("POSITION"))?
            .collect();
        let n = positions.len();
        let normals: Option<Vec<[f32; 3]>> = r.read_normals().map(|x| x.collect());
        let uvs: Option<Vec<[f32; 2]>> = r.read_tex_coords(0).map(|x| x.into_f32().collect());
        let js: Vec<[u16; 4]> = r
            .read_joints(0)
            .ok_or_else(|| missing("JOINTS_0"))?
            .into_u16()
            .collect();
        let ws: Vec<[f32; 4]> = r
            .read_weights(0)
            .ok_or_else(|| missing("WEIGHTS_0"))?
            .into_f32()
            .collect();
        if js.len() != n || ws.len() != n {
            bail!(
                "{what}: {n} positions but {} JOINTS_0 and {} WEIGHTS_0",
                js.len(),
                ws.len()
            );
        }
        if normals.as_ref().is_some_and(|v| v.len() != n)
            || uvs.as_ref().is_some_and(|v| v.len() != n)
        {
            bail!("{what}: NORMAL or TEXCOORD_0 has a count other than POSITION's {n}");
        }
        has_normals &= normals.is_some();
        let base = data.vertices.len();
        for i in 0..n {
            let vertex = base + i;
            let at = format!("glTF file {name}: {mesh_name} vertex {vertex}");
            let p = positions[i];
            let nrm = normals.as_ref().map_or([0.0; 3], |v| v[i]);
            let uv = uvs.as_ref().map_or([0.0; 2], |v| [v[i][0], 1.0 - v[i][1]]);
            if !p.iter().chain(&nrm).chain(&uv).all(|x| x.is_finite()) {
                bail!("{at}: a position, normal or uv is not finite");
            }
            let (w, scaled) = normalised_weights(&at, ws[i])?;
            if scaled {
                renormalised += 1;
                first_renormalised.get_or_insert((vertex, ws[i].iter().sum::<f32>()));
            }
            let mut j = js[i];
            for k in 0..MAX_INFLUENCES {
                if w[k] == 0.0 {
                    // Unused: point it at joint 0, so no shader reads past the array.
                    j[k] = 0;
                } else if j[k] as usize >= joint_count {
                    bail!(
                        "{at}: joint {} is out of range (the skin has {joint_count} joints)",
                        j[k]
                    );
                }
            }
            data.vertices.push(Vertex {
                position: p,
                normal: nrm,
                uv,
                tangent: [1.0, 0.0, 0.0, 1.0],
            });
            joints.push(j);
            weights.push(w);
        }
        match r.read_indices() {
            Some(ix) => {
                let ix: Vec<u32> = ix.into_u32().collect();
                if !ix.len().is_multiple_of(3) {
                    bail!("{what} has a partial triangle ({} indices)", ix.len());
                }
                if let Some(bad) = ix.iter().find(|&&i| i as usize >= n) {
                    bail!("{what}: index {bad} is out of range ({n} vertices)");
                }
                data.indices.extend(ix.iter().map(|&i| i + base as u32));
            }
            None => data.indices.extend((0..n as u32).map(|i| i + base as u32)),
        }
    }
    if data.indices.is_empty() {
        bail!("glTF file {name}: {mesh_name} has no triangles");
    }
    if let Some((v, sum)) = first_renormalised {
        warnings.push(format!(
            "glTF file {name}: {mesh_name}: the weights of {renormalised} vertices do not sum to 1 (vertex {v}: {sum}); scaled so that they do"
        ));
    }
    if !has_normals {
        compute_normals(&mut data);
    }
    // A vertex on a mirror seam of the uvs is split in two: its copy
    // takes the same joints and weights.
    for source in compute_tangents(&mut data) {
        joints.push(joints[source]);
        weights.push(weights[source]);
    }

    let nodes = read_nodes(file, name)?;
    let inverse_bind: Vec<Mat4> = match skin.reader(get.clone()).read_inverse_bind_matrices() {
        Some(m) => m.map(|c| Mat4::from_cols_array_2d(&c)).collect(),
        None => vec![Mat4::IDENTITY; joint_count],
    };
    if inverse_bind.len() != joint_count || !inverse_bind.iter().all(|m| m.is_finite()) {
        bail!(
            "glTF file {name}: the skin's inverse bind matrices are not {joint_count} finite matrices"
        );
    }
    let limit = MAX_GLTF_VALUE;
    if let Some(j) =
        (inverse_bind.iter()).position(|m| m.abs().to_cols_array().iter().any(|x| *x > limit))
    {
        bail!(
            "glTF file {name}: skins[{}].inverseBindMatrices[{j}] has an entry past gloss's world limit of {limit:e}",
            skin.index()
        );
    }
    let clips = read_clips(file, name, &get, &mut warnings)?;
    // Every node index in range, so that posing can index without checks
    // (the crate validates them; this holds even if it did not).
    let in_range = |n: usize| n < nodes.len();
    let joint_nodes: Vec<usize> = skin.joints().map(|j| j.index()).collect();
    let channel_nodes = clips
        .iter()
        .flat_map(|c| c.channels.iter().map(|ch| ch.node));
    if !(in_range(node.index())
        && joint_nodes
            .iter()
            .copied()
            .chain(channel_nodes)
            .all(in_range))
    {
        bail!("malformed glTF file {name}: a node index is out of range");
    }
    let skinned = SkinnedMesh {
        mesh: data,
        joints,
        weights,
        nodes,
        joint_nodes,
        inverse_bind,
        mesh_node: node.index(),
        clips,
    };
    Ok((skinned, warnings))
}

/// Every node's rest transform and parent; a node with two parents, or a
/// cycle, is an error.
fn read_nodes(file: &gltf::Gltf, name: &str) -> Result<Vec<SkinNode>> {
    let (nodes, _) = super::gltf_nodes::read_nodes(file, name)?;
    Ok(nodes
        .into_iter()
        .map(|n| SkinNode {
            name: n.name,
            parent: n.parent,
            translation: n.translation,
            rotation: n.rotation,
            scale: n.scale,
        })
        .collect())
}

pub(super) fn read_clips<'s>(
    file: &gltf::Gltf,
    name: &str,
    get: &(impl Fn(gltf::Buffer) -> Option<&'s [u8]> + Clone),
    warnings: &mut Vec<String>,
) -> Result<Vec<Clip>> {
    let mut clips = Vec::new();
    for a in file.animations() {
        let clip_name = a
            .name()
            .map_or(format!("animation {}", a.index()), str::to_owned);
        let mut channels = Vec::new();
        for ch in a.channels() {
            let what = format!(
                "glTF file {name}: animation '{clip_name}' channel {}",
                ch.index()
            );
            let interpolation = match ch.sampler().interpolation() {
                gltf::animation::Interpolation::Step => Interpolation::Step,
                gltf::animation::Interpolation::Linear => Interpolation::Linear,
                gltf::animation::Interpolation::CubicSpline => bail!(
                    "{what}: CUBICSPLINE samplers are not read by gloss (use LINEAR or STEP keys)"
                ),
            };
            let r = ch.reader(get.clone());
            let times: Vec<f32> = r
                .read_inputs()
                .ok_or_else(|| anyhow!("{what}: its key times lie outside their buffer"))?
                .collect();
            let outputs = r
                .read_outputs()
                .ok_or_else(|| anyhow!("{what}: its key values lie outside their buffer"))?;
            let track = match outputs {
                ReadOutputs::Translations(v) => ChannelTrack::Translation(Track::new(
                    &what,
                    times,
                    within_world(&what, "translation", v)?,
                    interpolation,
                )?),
                ReadOutputs::Scales(v) => ChannelTrack::Scale(Track::new(
                    &what,
                    times,
                    within_world(&what, "scale", v)?,
                    interpolation,
                )?),
                ReadOutputs::Rotations(v) => ChannelTrack::Rotation(Track::new(
                    &what,
                    times,
                    rotations(&what, v.into_f32())?,
                    interpolation,
                )?),
                ReadOutputs::MorphTargetWeights(_) => {
                    warnings.push(format!("{what}: morph target weights are ignored"));
                    continue;
                }
            };
            channels.push(Channel {
                node: ch.target().node().index(),
                track,
            });
        }
        clips.push(Clip {
            name: clip_name,
            channels,
        });
    }
    Ok(clips)
}

#[cfg(test)]
mod tests;

/// Rotation keys as unit quaternions; a zero quaternion (no rotation at
/// all, NaN once normalised) is an error naming the key.
fn rotations(what: &str, keys: impl Iterator<Item = [f32; 4]>) -> Result<Vec<Quat>> {
    keys.enumerate()
        .map(|(k, q)| {
            let q = Quat::from_array(q);
            if !q.is_finite() || q.length_squared() < 1e-12 {
                bail!(
                    "{what}: rotation key {k} is {q}, not a rotation (the identity is [0, 0, 0, 1])"
                );
            }
            Ok(q.normalize())
        })
        .collect()
}

/// Translation or scale keys, each within the world limit (1e9).
fn within_world(what: &str, kind: &str, keys: impl Iterator<Item = [f32; 3]>) -> Result<Vec<Vec3>> {
    let limit = MAX_GLTF_VALUE;
    keys.enumerate()
        .map(|(k, v)| {
            let v = Vec3::from(v);
            if !(v.is_finite() && v.abs().max_element() <= limit) {
                bail!("{what}: {kind} key {k} is {v}, past gloss's world limit of {limit:e}");
            }
            Ok(v)
        })
        .collect()
}
