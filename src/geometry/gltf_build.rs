//! Writes small glTF 2.0 scenes (.gltf, one buffer as a data: URI) from
//! gloss meshes and JSON fragments: the tests build files with exact
//! expectations with it (a nested cube, a masked quad, a spinning box),
//! and the asset generator (scenes/assets/generate.rs) the shipped scene.
//! Nodes, materials, textures and animations are given as the JSON the
//! specification writes, so a test can write any node, sampler or
//! extension it needs, and a hostile one anything at all.

use super::MeshData;
use base64::Engine as _;

/// The arrays and objects of a file being built.
#[derive(Default)]
pub struct GltfBuilder {
    bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
    meshes: Vec<String>,
    pub nodes: Vec<String>,
    pub materials: Vec<String>,
    pub textures: Vec<String>,
    pub images: Vec<String>,
    pub samplers: Vec<String>,
    pub animations: Vec<String>,
    /// Extra top-level members, `"key": value` each.
    pub extra: Vec<String>,
}

impl GltfBuilder {
    fn view(&mut self, bytes: &[u8]) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(format!(
            r#"{{"buffer":0,"byteOffset":{},"byteLength":{}}}"#,
            self.bin.len(),
            bytes.len()
        ));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    /// An accessor of f32 items of `kind` ("SCALAR", "VEC3", "MAT4", ...)
    /// with `width` floats each; returns its index.
    pub fn floats(&mut self, v: &[f32], width: usize, kind: &str) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
        let view = self.view(&bytes);
        let count = v.len() / width;
        // POSITION needs min and max; harmless elsewhere.
        let mut extra = String::new();
        if kind == "VEC3" && count > 0 {
            let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
            for c in v.chunks(3) {
                for k in 0..3 {
                    lo[k] = lo[k].min(c[k]);
                    hi[k] = hi[k].max(c[k]);
                }
            }
            extra = format!(r#","min":{lo:?},"max":{hi:?}"#);
        }
        self.accessors.push(format!(
            r#"{{"bufferView":{view},"componentType":5126,"count":{count},"type":"{kind}"{extra}}}"#
        ));
        self.accessors.len() - 1
    }

    /// An accessor of u32 scalars (indices).
    pub fn indices(&mut self, v: &[u32]) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = self.view(&bytes);
        self.accessors.push(format!(
            r#"{{"bufferView":{view},"componentType":5125,"count":{},"type":"SCALAR"}}"#,
            v.len()
        ));
        self.accessors.len() - 1
    }

    /// An accessor written as it is (a hostile test's).
    pub fn raw_accessor(&mut self, json: &str) -> usize {
        self.accessors.push(json.to_owned());
        self.accessors.len() - 1
    }

    /// A mesh of one triangle-list primitive (`material` a JSON index or
    /// none); uvs written glTF's way (v down). Returns the mesh's index.
    pub fn mesh(&mut self, m: &MeshData, material: Option<usize>) -> usize {
        let p: Vec<f32> = m.vertices.iter().flat_map(|v| v.position).collect();
        let n: Vec<f32> = m.vertices.iter().flat_map(|v| v.normal).collect();
        let uv: Vec<f32> = (m.vertices.iter())
            .flat_map(|v| [v.uv[0], 1.0 - v.uv[1]])
            .collect();
        let (p, n, uv) = (
            self.floats(&p, 3, "VEC3"),
            self.floats(&n, 3, "VEC3"),
            self.floats(&uv, 2, "VEC2"),
        );
        let ix = self.indices(&m.indices);
        let material = material.map_or(String::new(), |m| format!(r#","material":{m}"#));
        self.primitives(&format!(
            r#"[{{"attributes":{{"POSITION":{p},"NORMAL":{n},"TEXCOORD_0":{uv}}},"indices":{ix}{material}}}]"#
        ))
    }

    /// A mesh with the primitives array given as JSON.
    pub fn primitives(&mut self, json: &str) -> usize {
        self.meshes.push(format!(r#"{{"primitives":{json}}}"#));
        self.meshes.len() - 1
    }

    /// Add `json` to `list`, returning its index.
    pub fn add(list: &mut Vec<String>, json: &str) -> usize {
        list.push(json.to_owned());
        list.len() - 1
    }

    /// The file: every node a root unless another names it as a child.
    pub fn gltf(&self) -> String {
        let children: std::collections::HashSet<usize> = (self.nodes.iter())
            .filter_map(|n| n.split("\"children\":[").nth(1))
            .filter_map(|rest| rest.split(']').next())
            .flat_map(|list| list.split(',').filter_map(|x| x.trim().parse().ok()))
            .collect();
        let roots: Vec<String> = (0..self.nodes.len())
            .filter(|i| !children.contains(i))
            .map(|i| i.to_string())
            .collect();
        let b64 = base64::engine::general_purpose::STANDARD.encode(&self.bin);
        let list = |v: &[String]| format!("[{}]", v.join(","));
        let mut parts = vec![
            r#""asset":{"version":"2.0","generator":"gloss gltf_build"}"#.to_string(),
            format!(r#""scene":0,"scenes":[{{"nodes":[{}]}}]"#, roots.join(",")),
        ];
        if !self.bin.is_empty() {
            parts.push(format!(
                r#""buffers":[{{"byteLength":{},"uri":"data:application/octet-stream;base64,{b64}"}}]"#,
                self.bin.len()
            ));
        }
        for (k, v) in [
            ("nodes", &self.nodes),
            ("meshes", &self.meshes),
            ("accessors", &self.accessors),
            ("bufferViews", &self.views),
            ("materials", &self.materials),
            ("textures", &self.textures),
            ("images", &self.images),
            ("samplers", &self.samplers),
            ("animations", &self.animations),
        ] {
            if !v.is_empty() {
                parts.push(format!(r#""{k}":{}"#, list(v)));
            }
        }
        parts.extend(self.extra.iter().cloned());
        format!("{{{}}}", parts.join(",\n"))
    }
}
