//! `gloss plan` refuses what `gloss render` refuses, with the same message:
//! it loads the meshes, textures and sprites through the renderer's own
//! functions and checks the light count against the most any GL holds. What
//! only a GL can check it names on a line of its own.

use crate::{
    BASE, base_with, cli_fails, contains_all, os, png_bytes, render_fails, temp_dir, write,
};
use std::path::Path;

/// The line of `stderr` that starts with "error:".
fn error_line(stderr: &str) -> &str {
    stderr
        .lines()
        .find(|l| l.starts_with("error:"))
        .unwrap_or_else(|| panic!("no error line in:\n{stderr}"))
}

/// `gloss plan` and `gloss render` both refuse `scene` with the same message.
fn plan_fails_as_render_does(scene: &Path, words: &[&str]) -> String {
    let render = render_fails(scene, &scene.with_file_name("out.png"));
    let plan = cli_fails(&[os("plan"), scene.as_os_str()]);
    contains_all(&plan, words);
    assert_eq!(error_line(&plan), error_line(&render));
    plan
}

#[test]
fn a_malformed_obj_fails_plan_as_it_fails_render() {
    let dir = temp_dir("plan_malformed_obj");
    write(
        &dir,
        "bad.obj",
        "v 1.0 abc 2.0\nv 0 0 0\nv 1 1 1\nf 1 2 3\n",
    );
    let scene = write(
        &dir,
        "scene.toml",
        base_with("mesh = \"plane\"", "mesh = \"bad.obj\""),
    );
    plan_fails_as_render_does(
        &scene,
        &["malformed OBJ file", "bad.obj", "position parse error"],
    );
}

#[test]
fn a_malformed_png_fails_plan_as_it_fails_render() {
    let dir = temp_dir("plan_malformed_png");
    let mut png = png_bytes(4, 4);
    png.truncate(png.len() / 2);
    write(&dir, "floor.png", &png);
    write(&dir, "tree.png", b"not a png at all");
    let textured = base_with(
        "shininess = 24.0",
        "shininess = 24.0\ndiffuse_texture = \"floor.png\"",
    );
    let scene = write(&dir, "scene.toml", &textured);
    plan_fails_as_render_does(&scene, &["texture", "floor.png"]);
    let sprite = format!(
        "{BASE}\n[[billboards]]\nsprite = \"tree.png\"\ncenter = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\n"
    );
    let scene = write(&dir, "scene.toml", &sprite);
    plan_fails_as_render_does(
        &scene,
        &["billboard sprite", "tree.png", "not a readable image"],
    );
}

#[test]
fn more_lights_than_any_gl_holds_fail_plan_and_render() {
    let dir = temp_dir("plan_too_many_lights");
    let text = format!(
        "{BASE}\n[light_grid]\ncount = 1024\narea = [-5.0, 5.0, -5.0, 5.0]\nheight = [0.5, 2.0]\n"
    );
    let scene = write(&dir, "scene.toml", &text);
    // 1 listed light + 1024 generated ones: one more than the block holds.
    let render = render_fails(&scene, &dir.join("out.png"));
    let plan = cli_fails(&[os("plan"), scene.as_os_str()]);
    let same = "scene.toml: 1025 lights, but at most 1024 fit in the lights uniform block";
    contains_all(&render, &[same, "GL_MAX_UNIFORM_BLOCK_SIZE"]);
    contains_all(&plan, &[same, "gloss's limit on any GL"]);
}

#[test]
fn plan_names_what_it_cannot_check_without_gl() {
    let dir = temp_dir("plan_unchecked");
    let text = format!(
        "{BASE}\n[light_grid]\ncount = 300\narea = [-5.0, 5.0, -5.0, 5.0]\nheight = [0.5, 2.0]\n"
    )
    .replace("size = [32, 24]", "size = [32, 24]\nmsaa = 4");
    let scene = write(&dir, "scene.toml", &text);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([os("plan"), scene.as_os_str()])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = stdout
        .lines()
        .find(|l| l.starts_with("not checked without a GL context"))
        .unwrap_or_else(|| panic!("no unchecked line:\n{stdout}"));
    contains_all(
        line,
        &[
            "the shaders compile",
            "GL_MAX_TEXTURE_SIZE for the 32x24 targets",
            "GL_MAX_SAMPLES for render.msaa = 4",
            "GL_MAX_UNIFORM_BLOCK_SIZE for 301 lights (every GL 3.3 holds 256)",
        ],
    );
}

#[test]
fn the_tiled_path_holds_more_lights_than_the_block_but_not_without_limit() {
    let dir = temp_dir("plan_tiled_lights");
    let grid = |count: u32| {
        format!(
            "{BASE}\n[light_grid]\ncount = {count}\narea = [-5.0, 5.0, -5.0, 5.0]\nheight = [0.5, 2.0]\n"
        )
        .replace("size = [32, 24]", "size = [32, 24]\npath = \"tiled\"")
    };
    // 1025 lights: the tiled path reads them from a buffer texture.
    let scene = write(&dir, "many.toml", grid(1024));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            os("render"),
            scene.as_os_str(),
            os("-o"),
            dir.join("many.png").as_os_str(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // With a transparent object, lit forward from the block, it cannot.
    let glass = grid(1024).replace(
        "[materials.floor]",
        "[materials.glass]\ndiffuse = [0.5, 0.5, 0.5]\nopacity = 0.5\n\n[[objects]]\nname = \"pane\"\nmesh = \"cube\"\nmaterial = \"glass\"\n\n[materials.floor]",
    );
    let scene = write(&dir, "glass.toml", &glass);
    let render = render_fails(&scene, &dir.join("glass.png"));
    let plan = cli_fails(&[os("plan"), scene.as_os_str()]);
    let same = "glass.toml: 1025 lights, but at most 1024 fit in the lights uniform block";
    contains_all(&render, &[same]);
    contains_all(&plan, &[same]);
    // Past one shader loop's 65535 iterations: refused by plan and render alike.
    let scene = write(&dir, "huge.toml", grid(70_000));
    let render = render_fails(&scene, &dir.join("huge.png"));
    let plan = cli_fails(&[os("plan"), scene.as_os_str()]);
    let same = "huge.toml: 70001 lights, but the tiled path shades at most 65535";
    contains_all(&render, &[same, "llvmpipe"]);
    contains_all(&plan, &[same]);
}
