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
