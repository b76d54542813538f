//! The command line: a failed render leaves the user's old picture alone (and
//! no temporary file); bad arguments are refused with "error:" and a clear
//! message.

use crate::{
    BASE, base_with, cli_fails, contains_all, os, png_bytes, render_fails, temp_dir, write,
};
use std::process::Command;

#[test]
fn failed_render_keeps_existing_output() {
    let dir = temp_dir("failed_render_keeps_existing_output");
    let out = dir.join("out.png");
    let old = png_bytes(3, 2);
    std::fs::write(&out, &old).expect("write the user's picture");

    // A scene that does not parse.
    let broken = write(&dir, "broken.toml", format!("{BASE}\nnonsense = [\n"));
    let stderr = render_fails(&broken, &out);
    contains_all(&stderr, &["broken.toml", "TOML parse error"]);
    assert_eq!(std::fs::read(&out).unwrap(), old, "out.png was changed");

    // A scene that parses but fails while rendering (a malformed OBJ).
    write(&dir, "bad.obj", "v 0 0 0\nf 1 2 3\n");
    let bad_mesh = write(
        &dir,
        "bad_mesh.toml",
        base_with("mesh = \"plane\"", "mesh = \"bad.obj\""),
    );
    let stderr = render_fails(&bad_mesh, &out);
    contains_all(&stderr, &["bad.obj"]);
    assert_eq!(std::fs::read(&out).unwrap(), old, "out.png was changed");
    assert!(
        !dir.join("out.png.tmp").exists(),
        "a failed render leaves no temporary file"
    );

    // A good scene replaces it.
    let good = write(&dir, "good.toml", BASE);
    let run = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([os("render"), good.as_os_str(), os("-o"), out.as_os_str()])
        .args(["--size", "32x24"])
        .output()
        .expect("run gloss");
    assert!(
        run.status.success(),
        "rendering the good scene: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let new = image::open(&out).expect("the new out.png decodes");
    assert_eq!((new.width(), new.height()), (32, 24));
    assert!(!dir.join("out.png.tmp").exists());
}

/// `-o` naming a directory is refused before anything is written, and
/// leaves no temporary file beside it.
#[test]
fn render_into_a_directory_leaves_nothing_behind() {
    let dir = temp_dir("render_into_a_directory_leaves_nothing_behind");
    let good = write(&dir, "good.toml", BASE);
    let target = dir.join("pictures");
    std::fs::create_dir_all(&target).unwrap();
    let stderr = render_fails(&good, &target);
    contains_all(&stderr, &["pictures", "is a directory"]);
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

#[test]
fn cli_render_size_zero() {
    let dir = temp_dir("cli_render_size_zero");
    let scene = write(&dir, "scene.toml", BASE);
    let out = dir.join("out.png");
    let stderr = cli_fails(&[
        os("render"),
        scene.as_os_str(),
        os("-o"),
        out.as_os_str(),
        os("--size"),
        os("0x10"),
    ]);
    contains_all(&stderr, &["--size", "0x10", "1..=8192"]);
    assert!(!out.exists());
}

#[test]
fn cli_render_window_backend() {
    let dir = temp_dir("cli_render_window_backend");
    let scene = write(&dir, "scene.toml", BASE);
    let out = dir.join("out.png");
    let stderr = cli_fails(&[
        os("--backend"),
        os("window"),
        os("render"),
        scene.as_os_str(),
        os("-o"),
        out.as_os_str(),
    ]);
    contains_all(&stderr, &["renders headless", "--backend egl or osmesa"]);
    assert!(!out.exists());
}

/// Output into a pipe that closes early (`gloss plan SCENE | head -2`)
/// ends gloss quietly, as it does any Unix tool: no "internal error".
#[cfg(unix)]
#[test]
fn a_closed_pipe_ends_gloss_quietly() {
    use std::process::Stdio;
    let scene = gloss::assets::scene_path(std::path::Path::new("scenes/assignment-bunny.toml"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([os("plan"), scene.as_os_str()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run gloss");
    // Close the pipe before gloss has loaded the scene and printed a line.
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("internal error"), "{stderr}");
    assert!(stderr.is_empty(), "gloss said: {stderr}");
}
