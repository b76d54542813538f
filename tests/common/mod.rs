//! Shared by the image tests: a headless context with GL debug output on,
//! rendering a scene, and comparing images with files written on failure.
#![allow(dead_code)]

use gloss::gl::{Backend, Headless};
use gloss::image_compare::{self, Metrics, Tolerance};
use gloss::renderer::{Output, render_scene};
use gloss::scene::Scene;
use glow::HasContext;
use image::RgbaImage;
use std::path::{Path, PathBuf};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn scene(name: &str) -> Scene {
    Scene::load(&root().join("scenes").join(name)).expect("shipped scene loads")
}

/// Where failing tests write actual/expected/diff images.
pub fn out_dir() -> PathBuf {
    let d = root().join("target/test-output");
    std::fs::create_dir_all(&d).expect("create target/test-output");
    d
}

/// The backend the tests use: EGL unless GLOSS_TEST_BACKEND=osmesa.
pub fn backend() -> Backend {
    match std::env::var("GLOSS_TEST_BACKEND").as_deref() {
        Ok("osmesa") => Backend::Osmesa,
        _ => Backend::Egl,
    }
}

/// A context with debug output on: every render checks for GL errors.
pub fn context(backend: Backend) -> Headless {
    let ctx = Headless::new(backend, true).expect("headless GL context");
    assert!(ctx.debug.enabled);
    ctx
}

pub struct Rendered {
    pub image: RgbaImage,
    /// Linear RGBA, bottom row first (only with Output::Linear32F).
    pub linear: Vec<f32>,
    pub width: u32,
    pub height: u32,
}

/// Render `scene` at its size and read it back. Panics with the GL error
/// messages if the frame raised any.
pub fn render_with(ctx: &Headless, scene: &Scene, output: Output) -> Rendered {
    let r = render_scene(ctx, scene, output)
        .unwrap_or_else(|e| panic!("rendering {}: {e:#}", scene.name));
    let (width, height) = scene.render.size;
    Rendered {
        image: r.read_image(),
        linear: if output == Output::Linear32F {
            r.read_linear()
        } else {
            Vec::new()
        },
        width,
        height,
    }
}

pub fn render(scene: &Scene, output: Output) -> Rendered {
    let ctx = context(backend());
    render_with(&ctx, scene, output)
}

/// Compare two rendered images; on failure write actual, expected and diff
/// under target/test-output and panic naming them.
pub fn assert_close(
    name: &str,
    actual: &RgbaImage,
    expected: &RgbaImage,
    tol: &Tolerance,
) -> Metrics {
    let dir = out_dir();
    let expected_path = dir.join(format!("{name}.reference.png"));
    expected
        .save(&expected_path)
        .expect("write reference image");
    image_compare::check_golden(name, actual, &expected_path, &dir, tol)
        .unwrap_or_else(|e| panic!("{e:#}"))
}

/// Compare against tests/golden/<name>.png (GLOSS_UPDATE_GOLDEN=1 rewrites it).
pub fn assert_golden(name: &str, actual: &RgbaImage, tol: &Tolerance) -> Metrics {
    let golden: &Path = &root().join("tests/golden").join(format!("{name}.png"));
    image_compare::check_golden(name, actual, golden, &out_dir(), tol)
        .unwrap_or_else(|e| panic!("{e:#}"))
}

/// The GL state a pass may change, as (name, value) pairs.
pub fn gl_state(gl: &glow::Context) -> Vec<(String, i64)> {
    let mut v = Vec::new();
    unsafe {
        for (name, cap) in [
            ("DEPTH_TEST", glow::DEPTH_TEST),
            ("BLEND", glow::BLEND),
            ("CULL_FACE", glow::CULL_FACE),
            ("STENCIL_TEST", glow::STENCIL_TEST),
            ("SCISSOR_TEST", glow::SCISSOR_TEST),
            ("DEPTH_CLAMP", glow::DEPTH_CLAMP),
            ("FRAMEBUFFER_SRGB", glow::FRAMEBUFFER_SRGB),
            ("POLYGON_OFFSET_FILL", glow::POLYGON_OFFSET_FILL),
            ("CLIP_DISTANCE0", glow::CLIP_DISTANCE0),
            ("CLIP_DISTANCE1", glow::CLIP_DISTANCE1),
            ("CLIP_DISTANCE7", glow::CLIP_DISTANCE7),
            ("RASTERIZER_DISCARD", glow::RASTERIZER_DISCARD),
            ("TEXTURE_CUBE_MAP_SEAMLESS", glow::TEXTURE_CUBE_MAP_SEAMLESS),
        ] {
            v.push((name.to_string(), gl.is_enabled(cap) as i64));
        }
        let mut polygon = [0i32; 2];
        gl.get_parameter_i32_slice(glow::POLYGON_MODE, &mut polygon);
        v.push(("POLYGON_MODE".to_string(), polygon[0] as i64));
        for (name, p) in [
            ("DEPTH_FUNC", glow::DEPTH_FUNC),
            (
                "TRANSFORM_FEEDBACK_BUFFER_BINDING",
                glow::TRANSFORM_FEEDBACK_BUFFER_BINDING,
            ),
            ("CULL_FACE_MODE", glow::CULL_FACE_MODE),
            ("FRONT_FACE", glow::FRONT_FACE),
            ("BLEND_SRC_RGB", glow::BLEND_SRC_RGB),
            ("BLEND_DST_RGB", glow::BLEND_DST_RGB),
            ("STENCIL_FUNC", glow::STENCIL_FUNC),
            ("STENCIL_REF", glow::STENCIL_REF),
            ("STENCIL_FAIL", glow::STENCIL_FAIL),
            ("STENCIL_PASS_DEPTH_FAIL", glow::STENCIL_PASS_DEPTH_FAIL),
            ("STENCIL_PASS_DEPTH_PASS", glow::STENCIL_PASS_DEPTH_PASS),
            ("STENCIL_BACK_FUNC", glow::STENCIL_BACK_FUNC),
            ("STENCIL_BACK_FAIL", glow::STENCIL_BACK_FAIL),
            (
                "STENCIL_BACK_PASS_DEPTH_FAIL",
                glow::STENCIL_BACK_PASS_DEPTH_FAIL,
            ),
            (
                "STENCIL_BACK_PASS_DEPTH_PASS",
                glow::STENCIL_BACK_PASS_DEPTH_PASS,
            ),
            ("DRAW_FRAMEBUFFER_BINDING", glow::DRAW_FRAMEBUFFER_BINDING),
            ("READ_FRAMEBUFFER_BINDING", glow::READ_FRAMEBUFFER_BINDING),
            ("CURRENT_PROGRAM", glow::CURRENT_PROGRAM),
            ("ACTIVE_TEXTURE", glow::ACTIVE_TEXTURE),
            ("VERTEX_ARRAY_BINDING", glow::VERTEX_ARRAY_BINDING),
        ] {
            v.push((name.to_string(), gl.get_parameter_i32(p) as i64));
        }
        v.push((
            "DEPTH_WRITEMASK".into(),
            gl.get_parameter_bool(glow::DEPTH_WRITEMASK) as i64,
        ));
        let mask: [bool; 4] = gl.get_parameter_bool_array(glow::COLOR_WRITEMASK);
        v.push((
            "COLOR_WRITEMASK".into(),
            mask.iter().filter(|&&b| b).count() as i64,
        ));
        for i in 0..2 {
            v.push((
                format!("UNIFORM_BUFFER_BINDING[{i}]"),
                gl.get_parameter_indexed_i32(glow::UNIFORM_BUFFER_BINDING, i) as i64,
            ));
        }
        v.push((
            "POLYGON_OFFSET_FACTOR".into(),
            gl.get_parameter_f32(glow::POLYGON_OFFSET_FACTOR) as i64,
        ));
        let active = gl.get_parameter_i32(glow::ACTIVE_TEXTURE) as u32;
        // Units 0..6: the G-buffer and the light; 6..14: the shadow maps.
        for u in 0..14 {
            gl.active_texture(glow::TEXTURE0 + u);
            v.push((
                format!("TEXTURE_BINDING_2D[unit {u}]"),
                gl.get_parameter_i32(glow::TEXTURE_BINDING_2D) as i64,
            ));
            v.push((
                format!("TEXTURE_BINDING_CUBE_MAP[unit {u}]"),
                gl.get_parameter_i32(glow::TEXTURE_BINDING_CUBE_MAP) as i64,
            ));
        }
        gl.active_texture(active);
    }
    v
}

/// Draw one frame of `scene` at `w` x `h` and list every GL state a pass
/// left different from the state before the frame (the fresh context's):
/// empty when every pass restored what it changed.
pub fn state_left_changed(ctx: &Headless, scene: &Scene, w: i32, h: i32) -> Vec<String> {
    let gl = &ctx.gl;
    let before = gl_state(gl);
    let mut r = gloss::renderer::Renderer::new(
        gl,
        &ctx.debug,
        scene,
        &gloss::gl::program::Sources::Embedded,
        w,
        h,
    )
    .unwrap_or_else(|e| panic!("{}: {e:#}", scene.name));
    let mut changed = Vec::new();
    r.render_inspected(&scene.camera, &mut |pass| {
        for (b, a) in before.iter().zip(&gl_state(gl)) {
            if b != a {
                changed.push(format!(
                    "{} left {} = {} (was {})",
                    pass.name, a.0, a.1, b.1
                ));
            }
        }
    })
    .unwrap_or_else(|e| panic!("{}: {e:#}", scene.name));
    changed
}

/// What `p` (linked with transform-feedback varyings) hands on for one draw,
/// captured with the rasterizer off: `bytes` of it, read back as floats.
/// `uniforms` sets `p`'s uniforms with `p` in use; `draw` makes the draw
/// between glBeginTransformFeedback(`primitive`) and glEndTransformFeedback.
/// A 1 x 1 framebuffer is bound meanwhile (a draw needs a complete one, even
/// with the rasterizer off, and the headless context has none of its own);
/// what it makes is deleted and the bindings it changed are restored.
/// Panics if the capture raised a GL error.
pub fn capture_feedback(
    gl: &glow::Context,
    p: &gloss::gl::program::Program,
    primitive: u32,
    bytes: usize,
    uniforms: impl FnOnce(&gloss::gl::program::Program),
    draw: impl FnOnce(&glow::Context),
) -> Vec<f32> {
    unsafe {
        let fbo = gl.create_framebuffer().unwrap();
        let rb = gl.create_renderbuffer().unwrap();
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA8, 1, 1);
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        gl.framebuffer_renderbuffer(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::RENDERBUFFER,
            Some(rb),
        );
        let buffer = gl.create_buffer().unwrap();
        gl.bind_buffer(glow::TRANSFORM_FEEDBACK_BUFFER, Some(buffer));
        gl.buffer_data_size(
            glow::TRANSFORM_FEEDBACK_BUFFER,
            bytes as i32,
            glow::STATIC_READ,
        );
        gl.bind_buffer_base(glow::TRANSFORM_FEEDBACK_BUFFER, 0, Some(buffer));
        p.use_program();
        uniforms(p);
        gl.enable(glow::RASTERIZER_DISCARD);
        gl.begin_transform_feedback(primitive);
        draw(gl);
        gl.end_transform_feedback();
        gl.disable(glow::RASTERIZER_DISCARD);
        assert_eq!(
            gl.get_error(),
            glow::NO_ERROR,
            "the capture raised a GL error"
        );
        let mut out = vec![0u8; bytes];
        gl.get_buffer_sub_data(glow::TRANSFORM_FEEDBACK_BUFFER, 0, &mut out);
        gl.bind_buffer_base(glow::TRANSFORM_FEEDBACK_BUFFER, 0, None);
        gl.bind_buffer(glow::TRANSFORM_FEEDBACK_BUFFER, None);
        gl.delete_buffer(buffer);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fbo);
        gl.bind_renderbuffer(glow::RENDERBUFFER, None);
        gl.delete_renderbuffer(rb);
        (out.chunks_exact(4))
            .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
            .collect()
    }
}

/// A program for `capture_feedback`: the test's vertex shader `vert`, which
/// includes the shipped glsl/common/`include` (`#include "common/<include>"`),
/// and a fragment shader that writes white (never run: the capture turns the
/// rasterizer off), linked to capture `varyings`. The shaders and a copy of
/// the include go to a temporary folder, removed once the program is linked.
pub fn feedback_program(
    gl: &std::sync::Arc<glow::Context>,
    include: &str,
    vert: &str,
    varyings: &[&str],
) -> gloss::gl::program::Program {
    use gloss::gl::program::{Program, Sources};
    let dir = std::env::temp_dir().join(format!(
        "gloss-feedback-{}-{}",
        include.replace('.', "-"),
        std::process::id()
    ));
    std::fs::create_dir_all(dir.join("common")).unwrap();
    std::fs::create_dir_all(dir.join("test")).unwrap();
    let shipped = root().join("glsl/common").join(include);
    std::fs::copy(shipped, dir.join("common").join(include)).unwrap();
    std::fs::write(dir.join("test/feedback.vert"), vert).unwrap();
    let frag = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    std::fs::write(dir.join("test/feedback.frag"), frag).unwrap();
    let stages = [
        (glow::VERTEX_SHADER, "test/feedback.vert"),
        (glow::FRAGMENT_SHADER, "test/feedback.frag"),
    ];
    let p = Program::with_feedback(gl, &Sources::Directory(dir.clone()), &stages, &[], varyings);
    let _ = std::fs::remove_dir_all(&dir);
    p.unwrap_or_else(|e| panic!("the test shaders with glsl/common/{include}: {e:#}"))
}

/// Run the gloss binary with `args` in the crate's root, the GL capped as
/// the tests run it; its standard output. Panics with its standard error
/// unless it succeeds.
pub fn gloss(args: &[&str]) -> String {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(args)
        .env("MESA_GL_VERSION_OVERRIDE", "3.3")
        .env("MESA_GLSL_VERSION_OVERRIDE", "330")
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "gloss {args:?}: {err}");
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// How many pixels of `now` differ from `before` in any byte; panics,
/// naming `what`, if the sizes differ.
pub fn pixels_differing(now: &RgbaImage, before: &RgbaImage, what: &str) -> usize {
    assert_eq!(now.dimensions(), before.dimensions(), "{what}: sizes");
    (now.pixels().zip(before.pixels()))
        .filter(|(a, b)| a != b)
        .count()
}
