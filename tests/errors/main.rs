//! Bad input gets a clear error, never a panic (issue: "every error case is a
//! test asserting the message, not just failure"):
//! * scene files: missing, TOML syntax, unknown keys, wrong types, NaN/inf,
//!   bad attenuation, unknown names, bad references, camera eye == target;
//! * OBJ and PNG files that are malformed, truncated or absurdly large;
//! * shaders that fail to compile, reported as `glsl/<file>:<line>`;
//! * the CLI: stderr starts with "error:", the exit code is non-zero, no
//!   panic, and a failed render leaves the user's old picture alone.

use gloss::gl::program::{Program, Sources};
use gloss::gl::texture::{MAX_TEXTURE_SIDE, load_rgba8};
use gloss::gl::{Backend, GlInfo, Headless};
use gloss::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// A small valid scene (a copy of scenes/plane.toml, so edits there do not
/// move the lines these tests break).
const BASE: &str = r#"name = "plane"

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
fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gloss-errors-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create temp dir");
    d
}

/// BASE with `from` replaced by `to` (which must be there exactly once).
fn base_with(from: &str, to: &str) -> String {
    assert_eq!(BASE.matches(from).count(), 1, "BASE has one {from:?}");
    BASE.replacen(from, to, 1)
}

fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write temp file");
    p
}

fn contains_all(msg: &str, words: &[&str]) {
    for w in words {
        assert!(
            msg.contains(w),
            "the message should contain {w:?}; it is:\n{msg}"
        );
    }
}

/// Run the gloss binary; it must fail cleanly. Returns its stderr.
fn cli_fails(args: &[&std::ffi::OsStr]) -> String {
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

fn os(s: &str) -> &std::ffi::OsStr {
    s.as_ref()
}

/// `gloss render SCENE -o OUT --size 32x24`, which must fail; returns stderr.
fn render_fails(scene: &Path, out: &Path) -> String {
    cli_fails(&[
        os("render"),
        scene.as_os_str(),
        os("-o"),
        out.as_os_str(),
        os("--size"),
        os("32x24"),
    ])
}

/// Write `text` as `scene.toml` in a fresh directory, check that both
/// `Scene::load` and `gloss plan` refuse it with a message holding `words`
/// (and the file name); return the library's message.
fn scene_fails(test: &str, text: &str, words: &[&str]) -> String {
    let dir = temp_dir(test);
    scene_in_dir_fails(&dir, text, words)
}

fn scene_in_dir_fails(dir: &Path, text: &str, words: &[&str]) -> String {
    let path = write(dir, "scene.toml", text);
    let msg = match Scene::load(&path) {
        Ok(_) => panic!(
            "{test}: the scene should be refused:\n{text}",
            test = dir.display()
        ),
        Err(e) => format!("{e:#}"),
    };
    contains_all(&msg, &["scene.toml"]);
    contains_all(&msg, words);
    let stderr = cli_fails(&[os("plan"), path.as_os_str()]);
    contains_all(&stderr, &["scene.toml"]);
    contains_all(&stderr, words);
    msg
}

// ---------------------------------------------------------------------------
// Scene files

#[test]
fn base_scene_is_valid() {
    let dir = temp_dir("base_scene_is_valid");
    let path = write(&dir, "scene.toml", BASE);
    Scene::load(&path).expect("BASE loads");
}

#[test]
fn scene_file_missing() {
    let dir = temp_dir("scene_file_missing");
    let path = dir.join("no-such-scene.toml");
    let msg = format!("{:#}", Scene::load(&path).unwrap_err());
    contains_all(&msg, &["cannot read scene file", "no-such-scene.toml"]);
    let out = dir.join("out.png");
    let stderr = render_fails(&path, &out);
    contains_all(&stderr, &["cannot read scene file", "no-such-scene.toml"]);
    assert!(!out.exists(), "no output written for a missing scene");
}

#[test]
fn scene_toml_syntax_error_names_the_line() {
    let text = base_with("near = 1.0", "near = 1.0.0");
    // "near = 1.0" is line 9 of BASE.
    scene_fails(
        "scene_toml_syntax_error_names_the_line",
        &text,
        &["TOML parse error", "line 9", "near = 1.0.0"],
    );
}

#[test]
fn scene_unknown_top_level_key() {
    let text = format!("colour = \"red\"\n{BASE}");
    scene_fails(
        "scene_unknown_top_level_key",
        &text,
        &[
            "unknown field `colour`",
            "line 1",
            "expected one of",
            "camera",
        ],
    );
}

#[test]
fn scene_unknown_key_in_light() {
    let text = base_with("intensity = 1.5", "intensity = 1.5\nradius = 3.0");
    scene_fails(
        "scene_unknown_key_in_light",
        &text,
        &[
            "unknown field `radius`",
            "line 22",
            "intensity",
            "attenuation",
        ],
    );
}

#[test]
fn scene_unknown_key_in_camera() {
    let text = base_with("half_height = 5.0", "half_height = 5.0\nzoom = 2.0");
    scene_fails(
        "scene_unknown_key_in_camera",
        &text,
        &["unknown field `zoom`", "line 9", "half_height", "fov_y"],
    );
}

#[test]
fn scene_wrong_type() {
    let text = base_with("intensity = 1.5", "intensity = \"bright\"");
    scene_fails(
        "scene_wrong_type",
        &text,
        &[
            "line 21",
            "intensity = \"bright\"",
            "invalid type: string \"bright\"",
            "expected f32",
        ],
    );
}

#[test]
fn scene_nan_color() {
    let text = base_with("color = [1.0, 0.9, 0.8]", "color = [nan, 1, 1]");
    scene_fails(
        "scene_nan_color",
        &text,
        &["lights[0].color", "expected finite numbers", "NaN"],
    );
}

#[test]
fn scene_inf_values() {
    let dir = temp_dir("scene_inf_values");
    let text = base_with("intensity = 1.5", "intensity = inf");
    scene_in_dir_fails(
        &dir,
        &text,
        &["lights[0].intensity", "expected finite numbers", "inf"],
    );
    let text = base_with("eye = [0.0, 10.0, 0.0]", "eye = [0.0, -inf, 0.0]");
    scene_in_dir_fails(
        &dir,
        &text,
        &["camera.eye", "expected finite numbers", "-inf"],
    );
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, nan, 0.032]",
    );
    scene_in_dir_fails(
        &dir,
        &text,
        &["lights[0].attenuation", "Kl (linear)", "finite", "NaN"],
    );
}

#[test]
fn scene_negative_attenuation() {
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, -0.09, 0.032]",
    );
    scene_fails(
        "scene_negative_attenuation",
        &text,
        &[
            "lights[0].attenuation",
            "Kl (linear)",
            "must be >= 0",
            "-0.09",
        ],
    );
}

#[test]
fn scene_all_zero_attenuation() {
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [0.0, 0.0, 0.0]",
    );
    scene_fails(
        "scene_all_zero_attenuation",
        &text,
        &["lights[0].attenuation", "all 0", "infinitely bright"],
    );
}

#[test]
fn scene_unknown_light_type() {
    let text = base_with("type = \"point\"", "type = \"area\"");
    scene_fails(
        "scene_unknown_light_type",
        &text,
        &[
            "lights[0].type",
            "expected directional, point or spot",
            "\"area\"",
        ],
    );
}

#[test]
fn scene_unknown_render_path() {
    let text = base_with("size = [32, 24]", "size = [32, 24]\npath = \"raytraced\"");
    scene_fails(
        "scene_unknown_render_path",
        &text,
        &[
            // The TOML error quotes the line: the key and its value.
            "path = \"raytraced\"",
            "expected forward, deferred, volumes or prepass",
            "\"raytraced\"",
        ],
    );
}

#[test]
fn scene_spot_inner_wider_than_outer() {
    let text = base_with(
        "type = \"point\"",
        "type = \"spot\"\ndirection = [0.0, -1.0, 0.0]\ninner_angle = 40.0\nouter_angle = 30.0",
    );
    scene_fails(
        "scene_spot_inner_wider_than_outer",
        &text,
        &[
            "lights[0].inner_angle/outer_angle",
            "inner_angle <= outer_angle",
            "40",
            "30",
        ],
    );
}

#[test]
fn scene_camera_eye_equals_target() {
    let text = base_with("target = [0.0, 0.0, 0.0]", "target = [0.0, 10.0, 0.0]");
    scene_fails(
        "scene_camera_eye_equals_target",
        &text,
        &["camera", "eye and target are the same point"],
    );
}

#[test]
fn scene_missing_mesh_file() {
    let text = base_with("mesh = \"plane\"", "mesh = \"models/missing.obj\"");
    scene_fails(
        "scene_missing_mesh_file",
        &text,
        &["objects[0].mesh", "missing.obj", "does not exist"],
    );
}

#[test]
fn scene_missing_texture_file() {
    let text = base_with(
        "shininess = 24.0",
        "shininess = 24.0\ndiffuse_texture = \"textures/missing.png\"",
    );
    scene_fails(
        "scene_missing_texture_file",
        &text,
        &[
            "materials.floor.diffuse_texture",
            "missing.png",
            "does not exist",
        ],
    );
}

#[test]
fn scene_unknown_material() {
    let text = base_with("material = \"floor\"", "material = \"marble\"");
    scene_fails(
        "scene_unknown_material",
        &text,
        &["objects[0].material", "no material named \"marble\""],
    );
}

#[test]
fn scene_parent_cycle() {
    let text = format!(
        "{}\n[[objects]]\nname = \"b\"\nmesh = \"cube\"\nparent = \"floor\"\n",
        base_with(
            "material = \"floor\"",
            "material = \"floor\"\nparent = \"b\""
        )
    );
    scene_fails("scene_parent_cycle", &text, &["objects[0].parent", "cycle"]);
}

#[test]
fn scene_unknown_parent() {
    let text = base_with(
        "material = \"floor\"",
        "material = \"floor\"\nparent = \"table\"",
    );
    scene_fails(
        "scene_unknown_parent",
        &text,
        &["objects[0].parent", "no object named \"table\""],
    );
}

// ---------------------------------------------------------------------------
// OBJ files, through `gloss render` of a scene that uses them

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

// ---------------------------------------------------------------------------
// PNG textures

/// BASE with the floor textured by `name` (in `dir`); returns the scene path.
fn textured_scene(dir: &Path, name: &str) -> PathBuf {
    write(
        dir,
        "scene.toml",
        base_with(
            "shininess = 24.0",
            &format!("shininess = 24.0\ndiffuse_texture = \"{name}\""),
        ),
    )
}

fn png_bytes(w: u32, h: u32) -> Vec<u8> {
    let img = image::RgbaImage::from_pixel(w, h, image::Rgba([200, 100, 50, 255]));
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .expect("encode PNG");
    bytes
}

/// CRC-32 (ISO 3309, as PNG uses), bit by bit.
fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in data {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

#[test]
fn crc32_matches_a_real_png() {
    // The IHDR CRC the image crate wrote must be what our crc32 computes.
    let png = png_bytes(1, 1);
    assert_eq!(&png[12..16], b"IHDR");
    let stored = u32::from_be_bytes(png[29..33].try_into().unwrap());
    assert_eq!(crc32(&png[12..29]), stored);
}

#[test]
fn png_random_bytes() {
    let dir = temp_dir("png_random_bytes");
    // Deterministic noise that starts like nothing in particular.
    let mut x = 0x1234_5678u32;
    let noise: Vec<u8> = (0..4096)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x as u8
        })
        .collect();
    let png = write(&dir, "noise.png", &noise);
    let msg = format!("{:#}", load_rgba8(&png).unwrap_err());
    contains_all(&msg, &["texture", "noise.png", "is not a readable image"]);
    let stderr = render_fails(&textured_scene(&dir, "noise.png"), &dir.join("out.png"));
    contains_all(
        &stderr,
        &["texture", "noise.png", "is not a readable image"],
    );
}

#[test]
fn png_truncated() {
    let dir = temp_dir("png_truncated");
    let real = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/assets/checker.png"
    ))
    .expect("read scenes/assets/checker.png");
    assert!(real.len() > 100);
    let png = write(&dir, "truncated.png", &real[..100]);
    let msg = format!("{:#}", load_rgba8(&png).unwrap_err());
    contains_all(&msg, &["texture", "truncated.png", "is malformed"]);
    let stderr = render_fails(&textured_scene(&dir, "truncated.png"), &dir.join("out.png"));
    contains_all(&stderr, &["texture", "truncated.png", "is malformed"]);
}

#[test]
fn png_absurdly_large() {
    let dir = temp_dir("png_absurdly_large");
    // A real 1x1 PNG whose header claims 100000x100000 (40 GB of RGBA8), with
    // a correct IHDR CRC so only the size is wrong.
    let mut png = png_bytes(1, 1);
    assert_eq!(&png[12..16], b"IHDR");
    png[16..20].copy_from_slice(&100_000u32.to_be_bytes());
    png[20..24].copy_from_slice(&100_000u32.to_be_bytes());
    let crc = crc32(&png[12..29]);
    png[29..33].copy_from_slice(&crc.to_be_bytes());
    let path = write(&dir, "huge.png", &png);

    let start = Instant::now();
    let msg = format!("{:#}", load_rgba8(&path).unwrap_err());
    let took = start.elapsed();
    contains_all(
        &msg,
        &[
            "texture",
            "huge.png",
            "100000x100000",
            &format!("1..={MAX_TEXTURE_SIDE}"),
        ],
    );
    assert_eq!(MAX_TEXTURE_SIDE, 8192);
    assert!(
        took < Duration::from_secs(1),
        "refusing a huge PNG should not decode it: took {took:?}"
    );

    let stderr = render_fails(&textured_scene(&dir, "huge.png"), &dir.join("out.png"));
    contains_all(&stderr, &["huge.png", "100000x100000", "1..=8192"]);
}

// ---------------------------------------------------------------------------
// Shaders

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

// ---------------------------------------------------------------------------
// Nothing the user had is lost

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

// ---------------------------------------------------------------------------
// Command line

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

// ---------------------------------------------------------------------------
// OpenGL version

fn fake_info(major: i32, minor: i32, core_profile: bool) -> GlInfo {
    GlInfo {
        backend: Backend::Egl,
        version: format!("{major}.{minor} Fake"),
        renderer: "fake".into(),
        vendor: "fake".into(),
        glsl: "1.50".into(),
        major,
        minor,
        core_profile,
        debug_context: false,
        khr_debug: false,
        max_uniform_block_size: 16384,
    }
}

#[test]
fn gl_version_too_old() {
    let msg = format!("{:#}", fake_info(3, 2, true).require_33_core().unwrap_err());
    contains_all(&msg, &["OpenGL 3.2", "needs OpenGL 3.3 core"]);
    let msg = format!(
        "{:#}",
        fake_info(2, 1, false).require_33_core().unwrap_err()
    );
    contains_all(&msg, &["OpenGL 2.1", "needs OpenGL 3.3 core"]);
}

#[test]
fn gl_compatibility_profile() {
    let msg = format!(
        "{:#}",
        fake_info(4, 6, false).require_33_core().unwrap_err()
    );
    contains_all(&msg, &["not a core profile", "needs OpenGL 3.3 core"]);
    fake_info(3, 3, true)
        .require_33_core()
        .expect("3.3 core is enough");
}
