//! Messages that name what the user wrote: a broken displacement map with
//! no raw bytes, `--time` as `--time`, an object a field made as the field,
//! a link to nothing named like a shipped scene as the link.

use crate::{BASE, contains_all, gloss, gloss_in, temp_dir, write};

const TERRAIN: &str =
    "\n[tessellation]\nsize = 4.0\npatches = 2\nheight = 0.5\ndisplacement = \"bumps.png\"\n";

#[test]
fn a_garbage_displacement_png_is_an_error_in_printable_words() {
    let dir = temp_dir("garbage_displacement");
    write(&dir, "scene.toml", format!("{BASE}{TERRAIN}"));
    let signature = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunks = signature.clone();
    chunks.extend((0u8..=255).cycle().take(1024));
    let cases: Vec<Vec<u8>> = vec![
        chunks,
        b"garbage\x01\x02\xff\x00\x1b[31m".to_vec(),
        [signature, vec![0, 0, 0, 13, 0x1b, 0x9b, 0xff, 0x07]].concat(),
    ];
    for bytes in cases {
        write(&dir, "bumps.png", &bytes);
        for command in ["plan", "render"] {
            let mut args = vec![command, "scene.toml"];
            if command == "render" {
                args.extend(["-o", "out.png"]);
            }
            let run = gloss_in(&dir, &args, &[]);
            let msg = run.failed();
            contains_all(msg, &["scene.toml: tessellation.displacement", "bumps.png"]);
            assert!(
                msg.chars()
                    .all(|c| (c == '\n' || !c.is_control()) && c != '\u{fffd}'),
                "a control character or a raw byte in {msg:?}"
            );
            assert!(!msg.contains("\\u{"), "an escaped byte in {msg:?}");
        }
    }
}

#[test]
fn time_talks_about_time() {
    let dir = temp_dir("time_flag");
    write(&dir, "scene.toml", BASE);
    for t in ["NaN", "inf", "-inf"] {
        let time = format!("--time={t}");
        let run = gloss_in(&dir, &["render", "scene.toml", "-o", "out.png", &time], &[]);
        let msg = run.failed();
        contains_all(msg, &["--time", "expected a finite number of seconds"]);
        assert!(!msg.contains("--set"), "{msg}");
    }
    // A finite time of any size is a time (nothing in BASE moves).
    for t in ["1e19", "-3e38", "0.25"] {
        let time = format!("--time={t}");
        gloss_in(
            &dir,
            &["render", "scene.toml", "-o", "out.png", &time],
            &["out.png"],
        )
        .succeeded();
    }
}

#[test]
fn errors_in_an_object_field_name_the_field() {
    let dir = temp_dir("object_fields_key");
    let field = "\n[[object_fields]]\nname = \"block\"\ncount = 3\nchildren = 2\nseed = 1\narea = [-5.0, 5.0, -5.0, 5.0]\nmesh = \"cube\"\nchild_mesh = \"cube\"\n";
    let cases = [
        (
            "mesh = \"cube\"\nchild",
            "mesh = \"bogus\"\nchild",
            "object_fields[0].mesh (in object block0, which it makes)",
        ),
        (
            "child_mesh = \"cube\"",
            "child_mesh = \"missing.obj\"",
            "object_fields[0].child_mesh (in object block0.0, which it makes)",
        ),
        (
            "child_mesh = \"cube\"",
            "child_mesh = \"cube\"\nchild_material = \"nothing\"",
            "object_fields[0].child_material (in object block0.0, which it makes)",
        ),
    ];
    for (from, to, key) in cases {
        assert_eq!(field.matches(from).count(), 1);
        write(
            &dir,
            "scene.toml",
            format!("{BASE}{}", field.replace(from, to)),
        );
        let run = gloss_in(&dir, &["plan", "scene.toml"], &[]);
        let msg = run.failed();
        contains_all(msg, &["scene.toml: ", key]);
        assert!(!msg.contains("objects["), "{msg}");
    }
    // The file's own objects keep their key.
    write(
        &dir,
        "scene.toml",
        format!(
            "{}{field}",
            BASE.replace("mesh = \"plane\"", "mesh = \"bogus\"")
        ),
    );
    contains_all(
        gloss_in(&dir, &["plan", "scene.toml"], &[]).failed(),
        &["objects[0].mesh"],
    );
}

#[test]
fn a_link_to_nothing_named_like_a_shipped_scene_is_an_error() {
    let dir = temp_dir("dangling_scene");
    std::os::unix::fs::symlink("gone.toml", dir.join("default.toml")).unwrap();
    std::os::unix::fs::symlink("gone.toml", dir.join("plane.toml")).unwrap();
    for name in ["default.toml", "plane.toml"] {
        let run = gloss_in(&dir, &["plan", name], &[]);
        contains_all(
            run.failed(),
            &[
                name,
                "is a symbolic link to gone.toml, which does not exist",
            ],
        );
    }
    // With no file of that name, the shipped scene is used as before.
    std::fs::remove_file(dir.join("plane.toml")).unwrap();
    gloss(&dir, &["plan", "plane.toml"]).succeeded();
}
