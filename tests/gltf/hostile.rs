//! Hostile glTF files: each refused with a message that names the file
//! and the key, before anything large is allocated, in bounded time; the
//! count checks run under a memory cap in a child process
//! (`prlimit --as`), as a user's `gloss plan` would.

use crate::files::{dir, folder, load, object, scene_text};
use crate::reader::trs;
use glam::{Quat, Vec3};
use gloss::geometry::{GltfBuilder, cube};
use std::time::{Duration, Instant};

#[track_caller]
fn refused(name: &str, b: &GltfBuilder, wanted: &[&str]) -> String {
    let e = format!(
        "{:#}",
        load(name, b, "").expect_err("a hostile file was accepted")
    );
    for w in wanted {
        assert!(e.contains(w), "{w:?} not in: {e}");
    }
    assert!(e.contains("model.gltf"), "the message names the file: {e}");
    e
}

/// A builder with one cube node, ready for a hostile addition.
fn with_cube() -> GltfBuilder {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&cube(), None);
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    b
}

/// `gloss plan` on the scene in `dir` under a 1 GiB address-space cap:
/// its exit status and stderr.
fn plan_capped(dir: &std::path::Path) -> (bool, String) {
    let out = std::process::Command::new("prlimit")
        .arg("--as=1073741824")
        .arg(env!("CARGO_BIN_EXE_gloss"))
        .arg("plan")
        .arg(dir.join("scene.toml"))
        .output()
        .expect("run prlimit gloss plan");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_sparse_accessor_without_a_view_cannot_ask_for_gigabytes() {
    // 2 billion VEC3 zeros would be 24 GB; the file is a few hundred bytes.
    let mut b = with_cube();
    let huge = b.raw_accessor(
        r#"{"componentType":5126,"count":2000000000,"type":"VEC3","sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}"#,
    );
    let mesh = b.primitives(&format!(
        r#"[{{"attributes":{{"POSITION":0,"NORMAL":{huge}}}}}]"#
    ));
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    let e = refused(
        "sparse",
        &b,
        &["accessors[4]", "count 2000000000", "the limit"],
    );
    assert!(
        e.contains(&gloss::geometry::MAX_ACCESSOR_BYTES.to_string()),
        "{e}"
    );
    // A user's run, memory capped: a clear error, no abort.
    let (ok, stderr) = plan_capped(&dir("sparse"));
    assert!(!ok && stderr.contains("accessors[4]"), "{stderr}");
    // Below the overall limit, zeros are still bounded by the file's bytes:
    // a million VEC3 (12 MB) from a file of about 2 KB.
    let mut b = with_cube();
    let zeros = b.raw_accessor(
        r#"{"componentType":5126,"count":1000000,"type":"VEC3","sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}"#,
    );
    let mesh = b.primitives(&format!(
        r#"[{{"attributes":{{"POSITION":0,"NORMAL":{zeros}}}}}]"#
    ));
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    refused(
        "unbacked",
        &b,
        &["accessors[4]", "without a bufferView", "the limit"],
    );
    // Animation times and inverse bind matrices are counted as well: the
    // same accessor as key times.
    let mut b = with_cube();
    let huge = b.raw_accessor(
        r#"{"componentType":5126,"count":900000000,"type":"SCALAR","sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}"#,
    );
    let q = b.floats(&[0.0, 0.0, 0.0, 1.0], 4, "VEC4");
    b.animations.push(format!(
        r#"{{"channels":[{{"sampler":0,"target":{{"node":0,"path":"rotation"}}}}],"samplers":[{{"input":{huge},"output":{q}}}]}}"#
    ));
    refused("sparse-times", &b, &["count 900000000", "the limit"]);
}

#[test]
fn a_buffer_uri_naming_a_fifo_is_refused_without_blocking() {
    let d = folder("fifo");
    let fifo = d.join("data.bin");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    let gltf = r#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":12,"uri":"data.bin"}],
        "nodes":[{}],"scenes":[{"nodes":[0]}]}"#;
    std::fs::write(d.join("model.gltf"), gltf).unwrap();
    std::fs::write(d.join("scene.toml"), scene_text("")).unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    let path = d.join("scene.toml");
    std::thread::spawn(move || {
        let r = gloss::scene::Scene::load(&path).map(|_| ());
        let _ = tx.send(r.map_err(|e| format!("{e:#}")));
    });
    let r = rx
        .recv_timeout(Duration::from_secs(20))
        .expect("loading a FIFO buffer must not block");
    let e = r.expect_err("a FIFO buffer was read");
    assert!(
        e.contains("buffers[0]") && e.contains("FIFO") && e.contains("data.bin"),
        "{e}"
    );
}

#[test]
fn a_chain_of_200000_nodes_loads_in_linear_time() {
    let n = 200_000;
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&cube(), None);
    for i in 0..n - 1 {
        b.nodes.push(format!(
            r#"{{"translation":[1,0,0],"children":[{}]}}"#,
            i + 1
        ));
    }
    b.nodes
        .push(format!(r#"{{"translation":[1,0,0],"mesh":{mesh}}}"#));
    let start = Instant::now();
    let s = load("chain", &b, "").unwrap();
    let took = start.elapsed();
    // Quadratic walks take minutes here; linear ones about a second.
    assert!(took < Duration::from_secs(30), "{n} nodes took {took:?}");
    let last = &s.objects[object(&s, &format!("model/node{}", n - 1))];
    let x = last.model.w_axis.x;
    assert_eq!(x, n as f32);
    eprintln!("{n}-node chain: loaded in {took:?}");
}

#[test]
fn a_zero_quaternion_is_refused_not_turned_into_nan() {
    let mut b = with_cube();
    b.nodes[0] = trs(
        Vec3::ZERO,
        Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        Vec3::ONE,
        r#","mesh":0"#,
    );
    refused("zero-quat", &b, &["nodes[0].rotation", "zero quaternion"]);
    // In rotation keys as well.
    let mut b = crate::reader::spinning_box();
    b.raw_accessor("{}"); // (keeps the indices of the keys below apart)
    let t = b.floats(&[0.0], 1, "SCALAR");
    let q = b.floats(&[0.0; 4], 4, "VEC4");
    b.animations.push(format!(
        r#"{{"name":"bad","channels":[{{"sampler":0,"target":{{"node":1,"path":"rotation"}}}}],"samplers":[{{"input":{t},"output":{q}}}]}}"#
    ));
    // The raw "{}" accessor is invalid: drop it again before writing.
    let _ = b;
    let mut b = crate::reader::spinning_box();
    let t = b.floats(&[0.0], 1, "SCALAR");
    let q = b.floats(&[0.0; 4], 4, "VEC4");
    b.animations.push(format!(
        r#"{{"name":"bad","channels":[{{"sampler":0,"target":{{"node":1,"path":"rotation"}}}}],"samplers":[{{"input":{t},"output":{q}}}]}}"#
    ));
    refused("zero-key", &b, &["rotation key 0", "not a rotation"]);
}

#[test]
fn a_translation_past_the_world_limit_is_refused() {
    let mut b = with_cube();
    b.nodes[0] = trs(
        Vec3::new(2e9, 0.0, 0.0),
        Quat::IDENTITY,
        Vec3::ONE,
        r#","mesh":0"#,
    );
    refused("far", &b, &["nodes[0].translation", "world limit of 1e9"]);
    // In translation keys as well.
    let mut b = crate::reader::spinning_box();
    let t = b.floats(&[0.0], 1, "SCALAR");
    let far = b.floats(&[0.0, 5e9, 0.0], 3, "VEC3");
    b.animations.push(format!(
        r#"{{"name":"away","channels":[{{"sampler":0,"target":{{"node":0,"path":"translation"}}}}],"samplers":[{{"input":{t},"output":{far}}}]}}"#
    ));
    refused(
        "far-key",
        &b,
        &[
            "animation 'away'",
            "translation key 0",
            "world limit of 1e9",
        ],
    );
}

#[test]
fn an_inverse_bind_matrix_of_3e38_is_refused() {
    let (mut arm, _) =
        gloss::geometry::load_gltf(&crate::common::root().join("scenes/assets/arm.glb")).unwrap();
    arm.inverse_bind[1] = glam::Mat4::from_scale(Vec3::splat(3e38));
    let d = folder("ibm");
    std::fs::write(d.join("model.glb"), gloss::geometry::write_glb(&arm)).unwrap();
    std::fs::write(
        d.join("scene.toml"),
        scene_text("").replace("model.gltf", "model.glb"),
    )
    .unwrap();
    let e = format!(
        "{:#}",
        gloss::scene::Scene::load(&d.join("scene.toml")).unwrap_err()
    );
    assert!(
        e.contains("inverseBindMatrices[1]") && e.contains("world limit"),
        "{e}"
    );
}

#[test]
fn gltf_1_and_unknown_required_extensions_are_named() {
    let d = folder("v1");
    std::fs::write(
        d.join("model.gltf"),
        r#"{"asset":{"version":"1.0"},"meshes":{"a":{}}}"#,
    )
    .unwrap();
    std::fs::write(d.join("scene.toml"), scene_text("")).unwrap();
    let e = format!(
        "{:#}",
        gloss::scene::Scene::load(&d.join("scene.toml")).unwrap_err()
    );
    assert!(
        e.contains("glTF 1.0 is not supported") && e.contains("model.gltf"),
        "{e}"
    );
    let mut b = with_cube();
    b.extra.push(r#""extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"]"#.into());
    refused(
        "draco",
        &b,
        &["extensionsRequired", "KHR_draco_mesh_compression"],
    );
}

#[test]
fn a_chain_of_animated_nodes_plays_in_linear_time() {
    // 200,000 nodes in a chain, each turned by one shared sampler: one
    // pass over the tracks per object would be 4e10 steps.
    let n = 200_000;
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&cube(), None);
    for i in 0..n - 1 {
        b.nodes.push(format!(r#"{{"children":[{}]}}"#, i + 1));
    }
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    let t = b.floats(&[0.0, 1.0], 1, "SCALAR");
    let q: Vec<f32> = [0.0f32, 1e-5]
        .iter()
        .flat_map(|a| Quat::from_rotation_y(*a).to_array())
        .collect();
    let q = b.floats(&q, 4, "VEC4");
    let channels: Vec<String> = (0..n)
        .map(|i| format!(r#"{{"sampler":0,"target":{{"node":{i},"path":"rotation"}}}}"#))
        .collect();
    b.animations.push(format!(
        r#"{{"name":"twist","channels":[{}],"samplers":[{{"input":{t},"output":{q}}}]}}"#,
        channels.join(",")
    ));
    let start = Instant::now();
    let mut s = load("animated-chain", &b, "").unwrap();
    s.set_time(1.0).unwrap();
    let took = start.elapsed();
    assert!(
        took < Duration::from_secs(30),
        "{n} animated nodes took {took:?}"
    );
    // Every node turned 1e-5 about y: the cube at the end turned 2 radians.
    let last = &s.objects[object(&s, &format!("model/node{}", n - 1))];
    let x = last.model.transform_vector3(Vec3::X);
    let angle = (-x.z).atan2(x.x);
    let want = (n as f32 * 1e-5 + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU)
        - std::f32::consts::PI;
    assert!((angle - want).abs() < 1e-2, "{angle} vs {want}");
    eprintln!("{n} animated nodes: loaded and posed in {took:?}");
}
