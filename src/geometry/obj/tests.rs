//! load_obj: its limits, its errors, and the shipped OBJs.

use super::*;
use crate::geometry::tests::check_mesh;
use std::path::PathBuf;

fn temp_obj(name: &str, contents: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gloss-geometry-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

fn load_err(name: &str, contents: &str) -> String {
    let path = temp_obj(name, contents.as_bytes());
    let err = load_obj(&path).expect_err("should fail");
    let msg = format!("{err:#}");
    assert!(msg.contains(name), "error does not name the file: {msg}");
    msg
}

const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

#[test]
fn load_obj_quad_without_normals() {
    let path = temp_obj(
        "quad.obj",
        format!("{QUAD}o a\nf 1/1 2/2 3/3 4/4\n").as_bytes(),
    );
    let m = load_obj(&path).unwrap();
    assert_eq!((m.vertices.len(), m.indices.len()), (4, 6));
    check_mesh("quad.obj", &m);
    for v in &m.vertices {
        assert_eq!(v.normal, [0.0, 0.0, 1.0]);
        assert_eq!(v.tangent, [1.0, 0.0, 0.0, 1.0]);
    }
}

#[test]
fn load_obj_merges_models_and_keeps_file_normals() {
    let text = format!("{QUAD}vn 0 0 2\no a\nf 1/1/1 2/2/1 3/3/1\no b\nf 1/1 3/3 4/4\n");
    let m = load_obj(&temp_obj("two.obj", text.as_bytes())).unwrap();
    assert_eq!(m.triangle_count(), 2);
    check_mesh("two.obj", &m);
    // The first object's file normal (normalised); no uvs -> still finite.
    assert_eq!(m.vertices[0].normal, [0.0, 0.0, 1.0]);
    let m = load_obj(&temp_obj(
        "nouv.obj",
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    ))
    .unwrap();
    check_mesh("nouv.obj", &m);
}

#[test]
fn load_obj_missing_file() {
    let path = std::env::temp_dir().join("gloss-no-such-dir/missing.obj");
    let msg = format!("{:#}", load_obj(&path).unwrap_err());
    assert!(
        msg.contains("OBJ file") && msg.contains("missing.obj does not exist"),
        "{msg}"
    );
}

#[test]
fn load_obj_malformed() {
    let msg = load_err("malformed.obj", "v 1.0 abc 2.0\nf 1 1 1\n");
    assert!(
        msg.contains("malformed OBJ file") && msg.contains("position parse error"),
        "{msg}"
    );
    let msg = load_err("badface.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n");
    assert!(
        msg.contains("malformed OBJ file") && msg.contains("face parse error"),
        "{msg}"
    );
    let path = temp_obj("binary.obj", &[0xff, 0xfe, 0x00, 0x76, 0x20, 0x31, 0x0a]);
    let msg = format!("{:#}", load_obj(&path).unwrap_err());
    assert!(
        msg.contains("malformed OBJ file") && msg.contains("binary.obj"),
        "{msg}"
    );
}

#[test]
fn load_obj_no_triangles() {
    let msg = load_err("empty.obj", "");
    assert!(msg.contains("contains no triangles"), "{msg}");
    let msg = load_err("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\np 1\n");
    assert!(msg.contains("contains no triangles"), "{msg}");
}

#[test]
fn load_obj_non_finite() {
    let msg = load_err("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
    let msg = load_err("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
    assert!(msg.contains("NaN or infinite vertex position"), "{msg}");
    let msg = load_err(
        "nanvt.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt NaN 0\nf 1/1 2/1 3/1\n",
    );
    assert!(msg.contains("NaN or infinite texture coordinate"), "{msg}");
}

#[test]
fn load_obj_index_out_of_range() {
    let msg = load_err("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
    assert!(msg.contains("face index out of range"), "{msg}");
    let msg = load_err(
        "rangevt.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/5 3/1\n",
    );
    assert!(msg.contains("face index out of range"), "{msg}");
}

#[test]
fn load_obj_too_large() {
    // The real limits are 256 MiB and 16M vertices; the same checks run
    // here with small limits so the test files stay small.
    let path = temp_obj("big.obj", format!("{QUAD}f 1 2 3 4\n").as_bytes());
    let msg = format!(
        "{:#}",
        load_obj_limited(&path, 16, MAX_OBJ_VERTICES, false).unwrap_err()
    );
    assert!(
        msg.contains("big.obj") && msg.contains("too large") && msg.contains("bytes"),
        "{msg}"
    );
    let msg = format!(
        "{:#}",
        load_obj_limited(&path, MAX_OBJ_BYTES, 3, false).unwrap_err()
    );
    assert!(
        msg.contains("big.obj") && msg.contains("too large") && msg.contains("vertex positions"),
        "{msg}"
    );
    // 3 positions but 6 vertices once split by uv.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/2 2/2\n";
    let path = temp_obj("split.obj", text.as_bytes());
    let msg = format!(
        "{:#}",
        load_obj_limited(&path, MAX_OBJ_BYTES, 5, false).unwrap_err()
    );
    assert!(
        msg.contains("split.obj") && msg.contains("after splitting"),
        "{msg}"
    );
    assert!(load_obj_limited(&path, MAX_OBJ_BYTES, 6, false).is_ok());
}

#[test]
fn committed_assets_load() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/assets");
    for name in ["knot.obj", "rock.obj"] {
        let path = dir.join(name);
        if !path.exists() {
            continue; // generated by `cargo run --release --example gen_assets`
        }
        let m = load_obj(&path).unwrap();
        check_mesh(name, &m);
        assert!(m.triangle_count() > 50);
    }
}
