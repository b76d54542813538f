//! Writes a [`SkinnedMesh`] as a binary glTF 2.0 file (.glb): a JSON chunk
//! that describes the mesh, skin, nodes and animations, and one binary
//! chunk with every array. The asset generator (scenes/assets/generate.rs)
//! writes the skinned arm with it, and the tests write broken skins with it
//! to check the loader's errors. The file is a plain glTF that other tools
//! open (Blender, the Khronos validator): no extensions, accessors with
//! their min / max where the specification asks for them.

use super::skin::{ChannelTrack, SkinnedMesh};
use std::fmt::Write as _;

/// The accessors and views written so far, and the binary chunk.
#[derive(Default)]
struct Arrays {
    bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
}

impl Arrays {
    /// Append `bytes` as a buffer view (4-byte aligned) and describe them by
    /// an accessor; returns the accessor's index.
    fn add(
        &mut self,
        bytes: &[u8],
        count: usize,
        kind: &str,
        component: u32,
        extra: &str,
    ) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(format!(
            r#"{{"buffer":0,"byteOffset":{},"byteLength":{}}}"#,
            self.bin.len(),
            bytes.len()
        ));
        self.bin.extend_from_slice(bytes);
        self.accessors.push(format!(
            r#"{{"bufferView":{},"componentType":{component},"count":{count},"type":"{kind}"{extra}}}"#,
            self.views.len() - 1
        ));
        self.accessors.len() - 1
    }

    fn floats(&mut self, v: &[f32], width: usize, kind: &str, min_max: bool) -> usize {
        let mut extra = String::new();
        if min_max {
            let (mut lo, mut hi) = (vec![f32::INFINITY; width], vec![f32::NEG_INFINITY; width]);
            for c in v.chunks(width) {
                for k in 0..width {
                    lo[k] = lo[k].min(c[k]);
                    hi[k] = hi[k].max(c[k]);
                }
            }
            let list = |x: &[f32]| {
                x.iter()
                    .map(|f| format!("{f:?}"))
                    .collect::<Vec<_>>()
                    .join(",")
            };
            extra = format!(r#","min":[{}],"max":[{}]"#, list(&lo), list(&hi));
        }
        let bytes: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
        self.add(&bytes, v.len() / width, kind, 5126, &extra)
    }
}

fn quote(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The .glb bytes of `s`.
pub fn write_glb(s: &SkinnedMesh) -> Vec<u8> {
    let mut a = Arrays::default();
    let vs = &s.mesh.vertices;
    let pos: Vec<f32> = vs.iter().flat_map(|v| v.position).collect();
    let nor: Vec<f32> = vs.iter().flat_map(|v| v.normal).collect();
    // glTF's uv origin is the top-left of the image, gloss's the bottom-left.
    let uv: Vec<f32> = vs.iter().flat_map(|v| [v.uv[0], 1.0 - v.uv[1]]).collect();
    let position = a.floats(&pos, 3, "VEC3", true);
    let normal = a.floats(&nor, 3, "VEC3", false);
    let texcoord = a.floats(&uv, 2, "VEC2", false);
    let joint_bytes: Vec<u8> = (s.joints.iter().flatten())
        .flat_map(|j| j.to_le_bytes())
        .collect();
    let joints = a.add(&joint_bytes, vs.len(), "VEC4", 5123, "");
    let w: Vec<f32> = s.weights.iter().flatten().copied().collect();
    let weights = a.floats(&w, 4, "VEC4", false);
    let index_bytes: Vec<u8> = s
        .mesh
        .indices
        .iter()
        .flat_map(|i| i.to_le_bytes())
        .collect();
    let indices = a.add(&index_bytes, s.mesh.indices.len(), "SCALAR", 5125, "");
    let ib: Vec<f32> = s
        .inverse_bind
        .iter()
        .flat_map(|m| m.to_cols_array())
        .collect();
    let inverse_bind = a.floats(&ib, 16, "MAT4", false);

    let mut animations = Vec::new();
    for clip in &s.clips {
        let (mut samplers, mut channels) = (Vec::new(), Vec::new());
        for ch in &clip.channels {
            let (path, times, values, width, kind, interp) = match &ch.track {
                ChannelTrack::Translation(t) | ChannelTrack::Scale(t) => (
                    if matches!(ch.track, ChannelTrack::Scale(_)) {
                        "scale"
                    } else {
                        "translation"
                    },
                    t.times().to_vec(),
                    t.values()
                        .iter()
                        .flat_map(|v| v.to_array())
                        .collect::<Vec<f32>>(),
                    3,
                    "VEC3",
                    t.interpolation,
                ),
                ChannelTrack::Rotation(t) => (
                    "rotation",
                    t.times().to_vec(),
                    t.values().iter().flat_map(|q| q.to_array()).collect(),
                    4,
                    "VEC4",
                    t.interpolation,
                ),
            };
            let input = a.floats(&times, 1, "SCALAR", true);
            let output = a.floats(&values, width, kind, false);
            let interpolation = match interp {
                crate::math::keyframes::Interpolation::Step => "STEP",
                _ => "LINEAR",
            };
            samplers.push(format!(
                r#"{{"input":{input},"output":{output},"interpolation":"{interpolation}"}}"#
            ));
            channels.push(format!(
                r#"{{"sampler":{},"target":{{"node":{},"path":"{path}"}}}}"#,
                samplers.len() - 1,
                ch.node
            ));
        }
        animations.push(format!(
            r#"{{"name":{},"samplers":[{}],"channels":[{}]}}"#,
            quote(&clip.name),
            samplers.join(","),
            channels.join(",")
        ));
    }

    let nodes: Vec<String> = (s.nodes.iter().enumerate())
        .map(|(i, n)| {
            let children: Vec<String> = (0..s.nodes.len())
                .filter(|&c| s.nodes[c].parent == Some(i))
                .map(|c| c.to_string())
                .collect();
            let mut j = format!(
                r#"{{"name":{},"translation":{:?},"rotation":{:?},"scale":{:?}"#,
                quote(&n.name),
                n.translation.to_array(),
                n.rotation.to_array(),
                n.scale.to_array()
            );
            if !children.is_empty() {
                let _ = write!(j, r#","children":[{}]"#, children.join(","));
            }
            if i == s.mesh_node {
                j.push_str(r#","mesh":0,"skin":0"#);
            }
            j.push('}');
            j
        })
        .collect();
    let roots: Vec<String> = (0..s.nodes.len())
        .filter(|&i| s.nodes[i].parent.is_none())
        .map(|i| i.to_string())
        .collect();
    let joint_list: Vec<String> = s.joint_nodes.iter().map(|j| j.to_string()).collect();

    while !a.bin.len().is_multiple_of(4) {
        a.bin.push(0);
    }
    let mut json = format!(
        concat!(
            r#"{{"asset":{{"version":"2.0","generator":"gloss gltf_write"}},"#,
            r#""scene":0,"scenes":[{{"nodes":[{roots}]}}],"nodes":[{nodes}],"#,
            r#""meshes":[{{"name":"skin","primitives":[{{"attributes":{{"POSITION":{p},"NORMAL":{n},"TEXCOORD_0":{t},"JOINTS_0":{j},"WEIGHTS_0":{w}}},"indices":{i},"mode":4}}]}}],"#,
            r#""skins":[{{"inverseBindMatrices":{ib},"joints":[{joints}]}}],"#,
            r#""animations":[{anims}],"#,
            r#""buffers":[{{"byteLength":{len}}}],"bufferViews":[{views}],"accessors":[{accessors}]}}"#
        ),
        roots = roots.join(","),
        nodes = nodes.join(","),
        p = position,
        n = normal,
        t = texcoord,
        j = joints,
        w = weights,
        i = indices,
        ib = inverse_bind,
        joints = joint_list.join(","),
        anims = animations.join(","),
        len = a.bin.len(),
        views = a.views.join(","),
        accessors = a.accessors.join(","),
    );
    while !json.len().is_multiple_of(4) {
        json.push(' ');
    }
    let total = 12 + 8 + json.len() + 8 + a.bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(json.as_bytes());
    out.extend_from_slice(&(a.bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&a.bin);
    out
}
