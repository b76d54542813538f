//! Bad input gets a clear error, never a panic (issue: "every error case is a
//! test asserting the message, not just failure"):
//! * scene files: missing, TOML syntax, unknown keys, wrong types, NaN/inf,
//!   bad attenuation, unknown names, bad references, camera eye == target;
//! * OBJ and PNG files that are malformed, truncated or absurdly large;
//! * shaders that fail to compile, reported as `glsl/<file>:<line>`;
//! * the CLI: stderr starts with "error:", the exit code is non-zero, no
//!   panic, and a failed render leaves the user's old picture alone;
//! * a file a scene names that is a directory, a FIFO or a device is named
//!   for what it is; `gloss plan` refuses what `gloss render` refuses;
//! * keys that have no effect get a warning.

mod ambient_occlusion;
mod cli;
mod gl_version;
mod mirror;
mod obj;
mod paths;
mod plan;
mod png;
mod scene;
mod shaders;
mod warnings;

use std::path::{Path, PathBuf};
use std::process::Command;

/// A small valid scene (a copy of scenes/plane.toml, so edits there do not
/// move the lines these tests break).
pub const BASE: &str = r#"name = "plane"

[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 5.0
near = 1.0
far = 20.0

[render]
size = [32, 24]
ambient = [0.05, 0.05, 0.05]
background = [0.0, 0.0, 0.0]

[[lights]]
type = "point"
position = [1.0, 2.0, -0.5]
color = [1.0, 0.9, 0.8]
intensity = 1.5
attenuation = [1.0, 0.09, 0.032]

[materials.floor]
diffuse = [0.7, 0.5, 0.3]
specular = [0.5, 0.5, 0.5]
shininess = 24.0

[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [10.0, 1.0, 10.0]
"#;

/// A fresh, empty directory for one test.
pub fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gloss-errors-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create temp dir");
    d
}

/// BASE with `from` replaced by `to` (which must be there exactly once).
pub fn base_with(from: &str, to: &str) -> String {
    assert_eq!(BASE.matches(from).count(), 1, "BASE has one {from:?}");
    BASE.replacen(from, to, 1)
}

pub fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write temp file");
    p
}

pub fn contains_all(msg: &str, words: &[&str]) {
    for w in words {
        assert!(
            msg.contains(w),
            "the message should contain {w:?}; it is:\n{msg}"
        );
    }
}

/// Run the gloss binary; it must fail cleanly. Returns its stderr.
pub fn cli_fails(args: &[&std::ffi::OsStr]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(args)
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("run gloss");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        !out.status.success(),
        "gloss {args:?} should fail; stderr:\n{stderr}"
    );
    assert!(
        out.status.code().is_some_and(|c| c != 0),
        "gloss {args:?} should exit with a non-zero code, not a signal: {:?}",
        out.status
    );
    assert!(
        stderr.starts_with("error:"),
        "stderr should start with \"error:\":\n{stderr}"
    );
    for bad in [
        "panicked",
        "RUST_BACKTRACE",
        "internal error",
        "stack backtrace",
    ] {
        assert!(
            !stderr.contains(bad),
            "stderr should not contain {bad:?}:\n{stderr}"
        );
    }
    stderr
}

pub fn os(s: &str) -> &std::ffi::OsStr {
    s.as_ref()
}

/// `gloss render SCENE -o OUT --size 32x24`, which must fail; returns stderr.
pub fn render_fails(scene: &Path, out: &Path) -> String {
    cli_fails(&[
        os("render"),
        scene.as_os_str(),
        os("-o"),
        out.as_os_str(),
        os("--size"),
        os("32x24"),
    ])
}

pub fn png_bytes(w: u32, h: u32) -> Vec<u8> {
    let img = image::RgbaImage::from_pixel(w, h, image::Rgba([200, 100, 50, 255]));
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .expect("encode PNG");
    bytes
}
