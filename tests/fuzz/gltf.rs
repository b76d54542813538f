//! `geometry::load_gltf` (the gltf crate inside) on the shipped arm with
//! bytes changed, in its JSON chunk and in its binary one: it never panics,
//! returns a skin whose indices, joints and weights are sound and whose
//! numbers are finite, or an error naming the file.

use crate::{root, run, scratch};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::sync::OnceLock;

fn arm() -> &'static [u8] {
    static ARM: OnceLock<Vec<u8>> = OnceLock::new();
    ARM.get_or_init(|| std::fs::read(root().join("scenes/assets/arm.glb")).unwrap())
}

/// The JSON chunk's end: edits there change the file's structure.
fn json_end() -> usize {
    20 + u32::from_le_bytes(arm()[12..16].try_into().unwrap()) as usize
}

pub fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let path = scratch("case.glb");
    std::fs::write(&path, bytes).expect("write the case");
    match gloss::geometry::load_gltf(&path) {
        Ok((skin, _)) => {
            crate::accepted();
            let (n, joints) = (skin.mesh.vertices.len(), skin.joint_nodes.len());
            prop_assert!(skin.mesh.indices.len() % 3 == 0 && !skin.mesh.indices.is_empty());
            prop_assert!(skin.mesh.indices.iter().all(|&i| (i as usize) < n));
            prop_assert!(skin.joints.len() == n && skin.weights.len() == n);
            for (j, w) in skin.joints.iter().zip(&skin.weights) {
                prop_assert!((w.iter().sum::<f32>() - 1.0).abs() < 1e-3, "{w:?}");
                prop_assert!(j.iter().all(|&j| (j as usize) < joints), "{j:?}");
            }
            for v in &skin.mesh.vertices {
                let all = v.position.iter().chain(&v.normal).chain(&v.uv);
                prop_assert!(all.clone().all(|x| x.is_finite()), "{v:?}");
            }
            let posed = skin.joint_matrices(skin.clips.first().map(|_| 0), 0.5);
            prop_assert!(posed.len() == joints);
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(m.contains("case.glb"), "the message names no file: {m}");
        }
    }
    Ok(())
}

#[test]
fn load_gltf_takes_any_mutated_arm() {
    let edit = (any::<bool>(), any::<usize>(), any::<u8>());
    let case = proptest::collection::vec(edit, 1..6).prop_map(|edits| {
        let mut bytes = arm().to_vec();
        for (in_json, at, byte) in edits {
            let at = at % if in_json { json_end() } else { bytes.len() };
            bytes[at] = byte;
        }
        bytes
    });
    run("gltf-mutated", case, |b| b.clone(), |b| check(&b));
}

#[test]
fn load_gltf_takes_any_cut_arm() {
    run(
        "gltf-cut",
        0..arm().len(),
        |&n| arm()[..n].to_vec(),
        |n| check(&arm()[..n]),
    );
}

/// A whole glTF scene as gloss's tests build them (nested nodes, a
/// matrix, two materials with a texture and MASK, a strip, a sparse
/// accessor, a node animation), as .gltf text with its buffer inline.
fn scene_file() -> &'static str {
    static FILE: OnceLock<String> = OnceLock::new();
    FILE.get_or_init(|| {
        use gloss::geometry::{GltfBuilder, cube};
        let mut b = GltfBuilder::default();
        let mesh = b.mesh(&cube(), Some(0));
        let strip = b.primitives(
            r#"[{"attributes":{"POSITION":0},"mode":5,"material":1},{"attributes":{"POSITION":0},"mode":6}]"#,
        );
        let sparse = b.raw_accessor(
            r#"{"bufferView":0,"componentType":5126,"count":24,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1],"sparse":{"count":2,"indices":{"bufferView":3,"componentType":5125},"values":{"bufferView":0}}}"#,
        );
        let sparse_mesh =
            b.primitives(&format!(r#"[{{"attributes":{{"POSITION":{sparse}}},"indices":3}}]"#));
        b.materials.push(r#"{"name":"a","alphaMode":"MASK","alphaCutoff":0.4,"doubleSided":true,"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0.3,"roughnessFactor":0.6}}"#.into());
        b.materials.push(r#"{"name":"b","alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[1,0.5,0.2,0.5]}}"#.into());
        b.textures.push(r#"{"source":0,"sampler":0}"#.into());
        b.images.push(r#"{"uri":"missing.png"}"#.into());
        b.samplers.push(r#"{"magFilter":9728,"minFilter":9987,"wrapS":33648}"#.into());
        b.nodes.push(
            r#"{"name":"a","translation":[1,2,3],"rotation":[0,0.6,0,0.8],"scale":[2,2,2],"children":[1,2]}"#
                .to_string(),
        );
        b.nodes.push(format!(r#"{{"name":"b","mesh":{mesh},"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0.5,0,0,1]}}"#));
        b.nodes.push(format!(r#"{{"name":"c","mesh":{strip},"children":[3]}}"#));
        b.nodes.push(format!(r#"{{"name":"d","mesh":{sparse_mesh}}}"#));
        let t = b.floats(&[0.0, 1.0], 1, "SCALAR");
        let q = b.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0], 4, "VEC4");
        b.animations.push(format!(
            r#"{{"name":"spin","channels":[{{"sampler":0,"target":{{"node":2,"path":"rotation"}}}}],"samplers":[{{"input":{t},"output":{q},"interpolation":"STEP"}}]}}"#
        ));
        b.gltf()
    })
}

/// The whole-scene reader on one file: no panic, memory within a multiple
/// of the file's size, and either a sound scene or an error naming the file.
pub fn check_scene(bytes: &[u8]) -> Result<(), TestCaseError> {
    let path = scratch("case.gltf");
    std::fs::write(&path, bytes).expect("write the case");
    let (result, peak) = crate::alloc::peak_bytes(|| gloss::geometry::load_gltf_scene(&path));
    let allowed = (8 << 20) + 400 * bytes.len();
    prop_assert!(
        peak <= allowed,
        "held {peak} bytes for a {}-byte file",
        bytes.len()
    );
    match result {
        Ok(scene) => {
            crate::accepted();
            prop_assert!(scene.order.len() == scene.nodes.len());
            for prims in &scene.meshes {
                for p in prims {
                    let n = p.data.vertices.len();
                    prop_assert!(p.data.indices.len() % 3 == 0);
                    prop_assert!(p.data.indices.iter().all(|&i| (i as usize) < n));
                    prop_assert!(
                        p.data
                            .vertices
                            .iter()
                            .all(|v| v.position.iter().all(|x| x.is_finite()))
                    );
                }
            }
            for n in &scene.nodes {
                prop_assert!(n.rotation.is_finite() && n.translation.is_finite());
            }
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(m.contains("case.gltf"), "the message names no file: {m}");
        }
    }
    Ok(())
}

#[test]
fn load_gltf_scene_takes_any_mutated_scene() {
    // Edits in the JSON (before the inline buffer): bytes changed, and
    // numbers made extreme.
    let json_end = scene_file().find("data:").unwrap();
    let extreme = [
        "4294967295",
        "-1",
        "1e39",
        "0",
        "2000000000",
        "65536",
        "[]",
        "null",
    ];
    let edit = (any::<bool>(), any::<usize>(), any::<u8>(), 0..extreme.len());
    let case = proptest::collection::vec(edit, 1..5).prop_map(move |edits| {
        let mut text = scene_file().as_bytes().to_vec();
        for (number, at, byte, k) in edits {
            let at = at % json_end;
            if number {
                // The number that starts at or after `at`, replaced.
                let Some(s) = (at..json_end).find(|&i| text[i].is_ascii_digit()) else {
                    continue;
                };
                let e = (s..json_end)
                    .find(|&i| !text[i].is_ascii_digit())
                    .unwrap_or(s);
                text.splice(s..e, extreme[k].bytes());
            } else {
                text[at] = byte;
            }
        }
        text
    });
    run("gltf-scene", case, |b| b.clone(), |b| check_scene(&b));
}

#[test]
fn load_gltf_scene_takes_any_cut_scene() {
    let n = scene_file().len();
    run(
        "gltf-scene-cut",
        0..n,
        |&k| scene_file().as_bytes()[..k].to_vec(),
        |k| check_scene(&scene_file().as_bytes()[..k]),
    );
}

#[test]
fn the_scene_seed_loads() {
    let path = scratch("seed.gltf");
    std::fs::write(&path, scene_file()).unwrap();
    let s = gloss::geometry::load_gltf_scene(&path).unwrap();
    assert_eq!(s.nodes.len(), 4);
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
}
