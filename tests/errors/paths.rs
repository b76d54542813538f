//! A file a scene names (mesh, texture, sprite, a mirror's roughness) that
//! is there but is no regular file is named for what it is, not reported
//! as missing: a directory, a FIFO (never opened, so nothing blocks), a
//! symbolic link to /dev/zero (a character device), a dangling link. And
//! extensions are read in any case: `ROCK.OBJ`, `FLOOR.PNG`.

use crate::{BASE, base_with, cli_fails, contains_all, os, png_bytes, temp_dir, write};
use gloss::scene::Scene;
use std::path::Path;
use std::sync::mpsc;
use std::time::Duration;

const MESH: &str = "mesh = \"plane\"";
const TEXTURE: &str = "shininess = 24.0";

fn with_mesh(name: &str) -> String {
    base_with(MESH, &format!("mesh = \"{name}\""))
}

fn with_texture(name: &str) -> String {
    base_with(
        TEXTURE,
        &format!("shininess = 24.0\ndiffuse_texture = \"{name}\""),
    )
}

fn with_sprite(name: &str) -> String {
    format!(
        "{BASE}\n[[billboards]]\nsprite = \"{name}\"\ncenter = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\n"
    )
}

fn mkfifo(path: &Path) {
    let ok = std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .expect("run mkfifo");
    assert!(ok.success(), "mkfifo {}", path.display());
}

/// `f` finishes within 20 s (a FIFO opened for reading would block forever).
fn finishes<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(Duration::from_secs(20))
        .unwrap_or_else(|_| panic!("{what} blocked"))
}

#[test]
fn a_directory_is_named_as_one() {
    for (test, text, words) in [
        (
            "mesh_is_a_directory",
            with_mesh("rock.obj"),
            ["objects[0].mesh", "rock.obj is a directory"],
        ),
        (
            "texture_is_a_directory",
            with_texture("floor.png"),
            [
                "materials.floor.diffuse_texture",
                "floor.png is a directory",
            ],
        ),
        (
            "sprite_is_a_directory",
            with_sprite("floor.png"),
            ["billboards[0].sprite", "floor.png is a directory"],
        ),
    ] {
        let dir = temp_dir(test);
        std::fs::create_dir_all(dir.join("rock.obj")).unwrap();
        std::fs::create_dir_all(dir.join("floor.png")).unwrap();
        let path = write(&dir, "scene.toml", &text);
        let msg = format!("{:#}", Scene::load(&path).unwrap_err());
        contains_all(&msg, &words);
        assert!(!msg.contains("does not exist"), "{msg}");
        let stderr = cli_fails(&[os("plan"), path.as_os_str()]);
        contains_all(&stderr, &words);
    }
}

#[test]
fn a_fifo_is_named_and_never_opened() {
    let dir = temp_dir("path_is_a_fifo");
    for name in ["pipe.obj", "pipe.png"] {
        mkfifo(&dir.join(name));
    }
    for (text, words) in [
        (
            with_mesh("pipe.obj"),
            [
                "objects[0].mesh",
                "pipe.obj is a FIFO (named pipe), not a regular file",
            ],
        ),
        (
            with_texture("pipe.png"),
            [
                "materials.floor.diffuse_texture",
                "pipe.png is a FIFO (named pipe)",
            ],
        ),
        (
            with_sprite("pipe.png"),
            ["billboards[0].sprite", "pipe.png is a FIFO (named pipe)"],
        ),
    ] {
        let path = write(&dir, "scene.toml", &text);
        let msg = finishes("loading a scene naming a FIFO", move || {
            format!("{:#}", Scene::load(&path).unwrap_err())
        });
        contains_all(&msg, &words);
    }
    // The loaders themselves, called with the FIFO directly.
    let obj = dir.join("pipe.obj");
    let msg = finishes("load_obj on a FIFO", move || {
        format!("{:#}", gloss::geometry::load_obj(&obj).unwrap_err())
    });
    contains_all(&msg, &["OBJ file", "pipe.obj is a FIFO"]);
    let png = dir.join("pipe.png");
    let msg = finishes("load_rgba8 on a FIFO", move || {
        format!("{:#}", gloss::gl::texture::load_rgba8(&png).unwrap_err())
    });
    contains_all(&msg, &["texture", "pipe.png is a FIFO"]);
}

#[test]
fn a_link_to_dev_zero_says_where_it_points() {
    let dir = temp_dir("path_links_to_dev_zero");
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.png")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.obj")).unwrap();
    std::os::unix::fs::symlink(dir.join("gone.obj"), dir.join("dangling.obj")).unwrap();
    for (text, words) in [
        (
            with_texture("zero.png"),
            [
                "materials.floor.diffuse_texture",
                "zero.png is a symbolic link to /dev/zero, which is a character device",
            ],
        ),
        (
            with_mesh("zero.obj"),
            [
                "objects[0].mesh",
                "zero.obj is a symbolic link to /dev/zero, which is a character device",
            ],
        ),
        (
            with_mesh("dangling.obj"),
            ["objects[0].mesh", "gone.obj, which does not exist"],
        ),
    ] {
        let path = write(&dir, "scene.toml", &text);
        let msg = finishes("loading a scene naming /dev/zero", move || {
            format!("{:#}", Scene::load(&path).unwrap_err())
        });
        contains_all(&msg, &words);
    }
    // A mirror's roughness texture goes through the same check.
    let text = format!(
        "{BASE}\n[[objects]]\nname = \"glass\"\nmesh = \"plane\"\nmirror = {{ roughness = \"zero.png\" }}\n"
    );
    let path = write(&dir, "scene.toml", &text);
    let msg = format!("{:#}", Scene::load(&path).unwrap_err());
    contains_all(
        &msg,
        &["objects[1].mirror.roughness", "symbolic link to /dev/zero"],
    );
}

const QUAD: &str = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 3 2\nf 1 4 3\n";

#[test]
fn extensions_are_read_in_any_case() {
    let dir = temp_dir("extensions_in_any_case");
    write(&dir, "QUAD.OBJ", QUAD);
    write(&dir, "quad.Obj", QUAD);
    write(&dir, "FLOOR.PNG", png_bytes(2, 2));
    write(&dir, "TREE.Png", png_bytes(2, 2));
    for mesh in ["QUAD.OBJ", "quad.Obj"] {
        let text =
            with_mesh(mesh).replace(TEXTURE, "shininess = 24.0\ndiffuse_texture = \"FLOOR.PNG\"");
        let text = format!(
            "{text}\n[[billboards]]\nsprite = \"TREE.Png\"\ncenter = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\n"
        );
        let path = write(&dir, "scene.toml", &text);
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{mesh}: {e:#}"));
        assert!(
            matches!(&scene.objects[0].mesh, gloss::scene::MeshSource::Obj(p) if p.ends_with(mesh)),
            "{mesh} is an OBJ mesh: {:?}",
            scene.objects[0].mesh
        );
        assert_eq!(scene.sprites.len(), 1);
        // gloss plan loads the mesh, the texture and the sprite.
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .args([os("plan"), path.as_os_str()])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    // Any other extension is still refused, naming what it takes.
    let text = with_mesh("quad.stl");
    let path = write(&dir, "scene.toml", &text);
    let msg = format!("{:#}", Scene::load(&path).unwrap_err());
    contains_all(
        &msg,
        &[
            "objects[0].mesh",
            "a path to an .obj, .glb or .gltf file",
            "quad.stl",
        ],
    );
}
