//! Shaders that fail to compile are reported as `glsl/<file>:<line>`, in the
//! main file or an included one; a missing include names the file.

use crate::{contains_all, temp_dir};
use gloss::gl::program::{Program, Sources};
use gloss::gl::{Backend, Headless};
use std::path::{Path, PathBuf};

/// Copy glsl/ and its chapter folders into `dir`.
fn copy_glsl(dir: &Path) {
    fn copy(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).expect("create shader folder");
        for entry in std::fs::read_dir(from).expect("read a glsl/ folder") {
            let entry = entry.expect("glsl/ entry");
            let target = to.join(entry.file_name());
            if entry.file_type().expect("file type").is_dir() {
                copy(&entry.path(), &target);
            } else {
                std::fs::copy(entry.path(), target).expect("copy shader");
            }
        }
    }
    copy(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/glsl")), dir);
}

/// glsl/ copied to a fresh directory, with the first line of `file` that
/// contains `needle` replaced by `broken`. Returns the directory and that
/// line's 1-based number.
fn broken_glsl(test: &str, file: &str, needle: &str, broken: &str) -> (PathBuf, usize) {
    let dir = temp_dir(test);
    copy_glsl(&dir);
    let text = std::fs::read_to_string(dir.join(file)).expect("read shader");
    let mut line_no = None;
    let lines: Vec<String> = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            if line_no.is_none() && l.contains(needle) {
                line_no = Some(i + 1);
                broken.to_owned()
            } else {
                l.to_owned()
            }
        })
        .collect();
    let line_no = line_no.unwrap_or_else(|| panic!("glsl/{file} has no line with {needle:?}"));
    std::fs::write(dir.join(file), lines.join("\n") + "\n").expect("write shader");
    (dir, line_no)
}

/// Build the forward Phong program from `dir`; it must fail. Returns the message.
fn forward_program_fails(dir: PathBuf) -> String {
    let ctx = Headless::new(Backend::Egl, true).expect("headless EGL context");
    let result = Program::new(
        &ctx.gl,
        &Sources::Directory(dir),
        &[
            (glow::VERTEX_SHADER, "lighting/forward.vert"),
            (glow::FRAGMENT_SHADER, "lighting/forward.frag"),
        ],
        &[("MAX_LIGHTS", "16".to_string())],
    );
    match result {
        Ok(_) => panic!("the broken shader compiled"),
        Err(e) => format!("{e:#}"),
    }
}

#[test]
fn shader_sources_from_a_directory_compile() {
    // The unbroken copy compiles, so the failures below are the broken lines.
    let dir = temp_dir("shader_sources_from_a_directory_compile");
    copy_glsl(&dir);
    let ctx = Headless::new(Backend::Egl, true).expect("headless EGL context");
    Program::new(
        &ctx.gl,
        &Sources::Directory(dir),
        &[
            (glow::VERTEX_SHADER, "lighting/forward.vert"),
            (glow::FRAGMENT_SHADER, "lighting/forward.frag"),
        ],
        &[("MAX_LIGHTS", "16".to_string())],
    )
    .unwrap_or_else(|e| panic!("the copied shaders compile: {e:#}"));
}

#[test]
fn shader_compile_error_in_main_file() {
    let (dir, line) = broken_glsl(
        "shader_compile_error_in_main_file",
        "lighting/forward.frag",
        "vec3 V = normalize(",
        "    vec3 V = normalize(u_no_such_uniform);",
    );
    let msg = forward_program_fails(dir);
    contains_all(
        &msg,
        &[
            "shader glsl/lighting/forward.frag failed to compile",
            &format!("glsl/lighting/forward.frag:{line}: "),
            "u_no_such_uniform",
        ],
    );
}

#[test]
fn shader_compile_error_in_included_file() {
    let (dir, line) = broken_glsl(
        "shader_compile_error_in_included_file",
        "common/lighting.glsl",
        "float att = ",
        "    float att = no_such_function(d);",
    );
    let msg = forward_program_fails(dir);
    contains_all(
        &msg,
        &[
            "shader glsl/lighting/forward.frag failed to compile",
            &format!("glsl/common/lighting.glsl:{line}: "),
            "no_such_function",
        ],
    );
}

#[test]
fn shader_file_missing() {
    let (dir, _) = broken_glsl(
        "shader_file_missing",
        "lighting/forward.frag",
        "#include \"common/lighting.glsl\"",
        "#include \"common/lighting_missing.glsl\"",
    );
    let msg = forward_program_fails(dir);
    contains_all(&msg, &["cannot read shader", "lighting_missing.glsl"]);
}
