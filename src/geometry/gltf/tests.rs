use super::read;
use crate::geometry::skin::SkinnedMesh;
use crate::geometry::{load_gltf, write_glb};
use glam::{Mat4, Quat, Vec3};
use std::path::{Path, PathBuf};

fn arm_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/assets/arm.glb")
}

fn arm() -> SkinnedMesh {
    let (arm, warnings) = load_gltf(&arm_path()).expect("arm.glb loads");
    assert!(warnings.is_empty(), "{warnings:?}");
    arm
}

fn reread(s: &SkinnedMesh) -> anyhow::Result<(SkinnedMesh, Vec<String>)> {
    read(&write_glb(s), Path::new("test.glb"), "test.glb")
}

/// The .glb's JSON chunk edited by `f`, the binary chunk kept.
fn edit_json(glb: &[u8], f: impl Fn(&str) -> String) -> Vec<u8> {
    let len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let mut json = f(std::str::from_utf8(&glb[20..20 + len]).unwrap());
    while !json.len().is_multiple_of(4) {
        json.push(' ');
    }
    let bin = &glb[20 + len..];
    let total = 20 + json.len() + bin.len();
    let mut out = b"glTF".to_vec();
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(json.as_bytes());
    out.extend_from_slice(bin);
    out
}

#[track_caller]
fn error(bytes: &[u8]) -> String {
    match read(bytes, Path::new("t.glb"), "t.glb") {
        Ok(_) => panic!("a malformed file was accepted"),
        Err(e) => format!("{e:#}"),
    }
}

#[test]
fn the_arm_is_a_skin_of_three_joints_with_two_clips() {
    let a = arm();
    assert_eq!(a.joint_nodes.len(), 3);
    assert_eq!(a.nodes[a.joint_nodes[1]].name, "elbow");
    let names: Vec<&str> = a.clips.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["wave", "twist"]);
    assert_eq!(a.clip_span(1), Some((0.0, 2.0)));
    for w in &a.weights {
        assert!((w.iter().sum::<f32>() - 1.0).abs() < 1e-6);
    }
    // Writing what was read and reading it again changes nothing.
    let (b, _) = reread(&a).unwrap();
    assert_eq!(a.mesh.vertices, b.mesh.vertices);
    assert_eq!(a.mesh.indices, b.mesh.indices);
    assert_eq!((&a.joints, &a.weights), (&b.joints, &b.weights));
    assert_eq!(a.clips, b.clips);
    assert_eq!(a.nodes, b.nodes);
}

#[test]
fn the_rest_pose_is_the_bind_pose_and_a_clip_moves_the_hand_where_the_angles_say() {
    let a = arm();
    for m in a.joint_matrices(None, 0.0) {
        assert!(m.abs_diff_eq(Mat4::IDENTITY, 1e-6), "{m}");
    }
    // "wave" at 2 s: shoulder 30°, elbow 90°, wrist 40° about z, joints at
    // x = 0, 1, 2. The hand's tip, x = 3 in the bind pose, goes to
    // R(30)(1, 0) + R(120)(1, 0) + R(160)(1, 0).
    let j = a.joint_matrices(a.clip("wave"), 2.0);
    let dir = |deg: f32| Vec3::new(deg.to_radians().cos(), deg.to_radians().sin(), 0.0);
    let tip = dir(30.0) + dir(120.0) + dir(160.0);
    let got = j[2].transform_point3(Vec3::new(3.0, 0.0, 0.0));
    assert!(got.abs_diff_eq(tip, 1e-5), "{got} vs {tip}");
    // Halfway through a key interval the rotation is halfway (slerp).
    let q = a.node_globals(a.clip("twist"), 0.5)[a.joint_nodes[1]];
    let expect = Mat4::from_translation(Vec3::X)
        * Mat4::from_quat(Quat::from_rotation_x(45f32.to_radians()));
    assert!(q.abs_diff_eq(expect, 1e-6));
}

#[test]
fn weights_off_one_are_renormalised_with_a_warning_and_all_zero_is_an_error() {
    let mut a = arm();
    a.weights[7] = [0.25, 0.25, 0.0, 0.0];
    let (b, warnings) = reread(&a).unwrap();
    assert_eq!(b.weights[7], [0.5, 0.5, 0.0, 0.0]);
    assert_eq!(warnings.len(), 1);
    assert!(
        warnings[0].contains("vertex 7: 0.5") && warnings[0].contains("1 vertices"),
        "{warnings:?}"
    );

    a.weights[9] = [0.0; 4];
    let e = reread(&a).unwrap_err().to_string();
    assert!(
        e.contains("mesh 'skin' vertex 9") && e.contains("every weight is 0"),
        "{e}"
    );
}

#[test]
fn a_joint_out_of_range_is_an_error_unless_its_weight_is_zero() {
    let mut a = arm();
    a.joints[3] = [0, 3, 0, 0];
    a.weights[3] = [1.0, 0.0, 0.0, 0.0];
    let (b, _) = reread(&a).unwrap();
    assert_eq!(
        b.joints[3],
        [0, 0, 0, 0],
        "an unused slot points at joint 0"
    );
    a.weights[3] = [0.5, 0.5, 0.0, 0.0];
    let e = reread(&a).unwrap_err().to_string();
    assert!(
        e.contains("vertex 3: joint 3 is out of range (the skin has 3 joints)"),
        "{e}"
    );
}

#[test]
fn malformed_files_are_clear_errors() {
    let glb = write_glb(&arm());
    for cut in [0, 11, 40, glb.len() / 2, glb.len() - 1] {
        let e = error(&glb[..cut]);
        assert!(e.contains("t.glb"), "cut at {cut}: {e}");
    }
    let e = error(&edit_json(&glb, |j| {
        j.replace("\"LINEAR\"", "\"CUBICSPLINE\"")
    }));
    assert!(e.contains("CUBICSPLINE samplers are not read"), "{e}");
    let e = error(&edit_json(&glb, |j| {
        j.replace(",\"mesh\":0,\"skin\":0", "")
    }));
    assert!(e.contains("has no skinned mesh"), "{e}");
    let e = error(&edit_json(&glb, |j| {
        j.replace("\"JOINTS_0\"", "\"JOINTS_1\"")
    }));
    assert!(e.contains("has no JOINTS_0"), "{e}");
    let e = error(&edit_json(&glb, |j| {
        j.replace(
            "{\"byteLength\":",
            "{\"uri\":\"data:application/octet-stream;base64,AAAA\",\"byteLength\":",
        )
    }));
    // A data: URI is read (the tests under tests/gltf use nothing else);
    // this one is shorter than the buffer says.
    assert!(e.contains("buffers[0] holds 3 bytes"), "{e}");
    let e = error(&edit_json(&glb, |j| j.replace("\"mode\":4", "\"mode\":1")));
    assert!(e.contains("not triangles"), "{e}");
    // The wrist made the shoulder's second parent, then the arm's only one (a cycle).
    for child in [1, 0] {
        let e = error(&edit_json(&glb, |j| {
            j.replace(
                "\"name\":\"wrist\",",
                &format!("\"name\":\"wrist\",\"children\":[{child}],"),
            )
        }));
        assert!(
            e.contains("two parents") || e.contains("its own ancestor"),
            "{e}"
        );
    }
}

#[test]
fn a_file_too_large_is_refused_before_it_is_read() {
    let dir = std::env::temp_dir().join(format!("gloss-gltf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big = dir.join("big.glb");
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(crate::geometry::MAX_GLTF_BYTES + 1).unwrap();
    let e = load_gltf(&big).unwrap_err().to_string();
    assert!(e.contains("larger than") && e.contains("big.glb"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn corrupted_files_are_errors_never_panics() {
    // Bytes of the arm changed at random (a fixed seed): each read is Ok
    // or an error. Some of these make the gltf crate panic inside; the
    // guard turns that into an error, and no panic escapes.
    let glb = write_glb(&arm());
    let mut state = 0x9e37_79b9_u64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 33) as usize
    };
    let mut panics = 0;
    for _ in 0..2000 {
        let mut bytes = glb.clone();
        for _ in 0..1 + next() % 8 {
            // Half the time in the JSON chunk, where structure lives.
            let json = 20 + u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
            let at = next() % if next() % 2 == 0 { json } else { bytes.len() };
            bytes[at] = next() as u8;
        }
        let r = std::panic::catch_unwind(|| {
            super::read_guarded(&bytes, Path::new("t.glb"), "t.glb").map(|_| ())
        });
        match r {
            Err(_) => panics += 1,
            Ok(Err(e)) => assert!(e.to_string().contains("t.glb"), "{e}"),
            Ok(Ok(())) => {}
        }
    }
    assert_eq!(panics, 0);
}
