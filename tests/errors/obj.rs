//! OBJ files, through `gloss render` of a scene that uses them: malformed,
//! binary, out-of-range indices, NaN coordinates, no triangles.

use crate::{base_with, contains_all, render_fails, temp_dir, write};
use gloss::scene::Scene;

/// A scene whose only object is `mesh`, rendered by the CLI: it must fail with
/// a message naming the .obj file and holding `words`.
fn obj_render_fails(test: &str, obj: &[u8], words: &[&str]) {
    let dir = temp_dir(test);
    write(&dir, "bad.obj", obj);
    let scene = write(
        &dir,
        "scene.toml",
        base_with("mesh = \"plane\"", "mesh = \"bad.obj\""),
    );
    Scene::load(&scene).expect("the scene itself is fine");
    let out = dir.join("out.png");
    let stderr = render_fails(&scene, &out);
    contains_all(&stderr, &["bad.obj"]);
    contains_all(&stderr, words);
    assert!(!out.exists(), "no picture for a failed render");
}

#[test]
fn obj_garbage_text() {
    obj_render_fails(
        "obj_garbage_text",
        b"v 1.0 abc 2.0\nv 0 0 0\nv 1 1 1\nf 1 2 3\n",
        &["malformed OBJ file", "position parse error"],
    );
}

#[test]
fn obj_binary_garbage() {
    obj_render_fails(
        "obj_binary_garbage",
        &[0x89, 0xff, 0xfe, 0x00, 0x76, 0x20, 0x31, 0x0a, 0x00, 0x00],
        &["malformed OBJ file"],
    );
}

#[test]
fn obj_face_index_out_of_range() {
    obj_render_fails(
        "obj_face_index_out_of_range",
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
        &["face index out of range"],
    );
}

#[test]
fn obj_nan_coordinates() {
    obj_render_fails(
        "obj_nan_coordinates",
        b"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        &["NaN or infinite vertex position"],
    );
}

#[test]
fn obj_empty() {
    obj_render_fails("obj_empty", b"# nothing here\n", &["contains no triangles"]);
}
