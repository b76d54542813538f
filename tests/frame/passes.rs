//! Every pass of every path restores the GL state it changed (the default
//! state of a fresh context, snapshotted after each pass), no pass samples a
//! texture attached to the framebuffer it draws into (the draw-time check in
//! src/gl/debug.rs), and both checks can fail.

use crate::common;
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::renderer::Renderer;
use gloss::scene::RenderPath;
use glow::HasContext;

/// The GL state a pass may change, as (name, value) pairs.
fn snapshot(gl: &glow::Context) -> Vec<(String, i64)> {
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
        ] {
            v.push((name.to_string(), gl.is_enabled(cap) as i64));
        }
        for (name, p) in [
            ("DEPTH_FUNC", glow::DEPTH_FUNC),
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
        v.push((
            "UNIFORM_BUFFER_BINDING[0]".into(),
            gl.get_parameter_indexed_i32(glow::UNIFORM_BUFFER_BINDING, 0) as i64,
        ));
        let active = gl.get_parameter_i32(glow::ACTIVE_TEXTURE) as u32;
        for u in 0..8 {
            gl.active_texture(glow::TEXTURE0 + u);
            v.push((
                format!("TEXTURE_BINDING_2D[unit {u}]"),
                gl.get_parameter_i32(glow::TEXTURE_BINDING_2D) as i64,
            ));
        }
        gl.active_texture(active);
    }
    v
}

#[test]
fn every_pass_restores_the_gl_state_it_changed() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let base = common::scene("mixed-lights.toml");
    // The state of a fresh context: every pass must leave it so.
    let fresh = snapshot(gl);
    for (path, stencil) in [
        (RenderPath::Forward, false),
        (RenderPath::Deferred, false),
        (RenderPath::Volumes, false),
        (RenderPath::Volumes, true),
        (RenderPath::Prepass, false),
    ] {
        let mut scene = base.clone();
        scene.render.path = path;
        scene.render.stencil_volumes = stencil;
        let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, 96, 54).unwrap();
        let before = &fresh;
        let mut changed = Vec::new();
        r.render_inspected(&scene.camera, &mut |pass| {
            let after = snapshot(gl);
            for (b, a) in before.iter().zip(&after) {
                if b != a {
                    changed.push(format!(
                        "{} left {} = {} (was {})",
                        pass.name, a.0, a.1, b.1
                    ));
                }
            }
        })
        .unwrap();
        assert!(
            changed.is_empty(),
            "{path:?} (stencil {stencil}):\n  {}",
            changed.join("\n  ")
        );
    }
}

#[test]
fn the_state_check_can_fail() {
    let ctx = common::context(common::backend());
    let before = snapshot(&ctx.gl);
    unsafe { ctx.gl.enable(glow::BLEND) };
    assert_ne!(before, snapshot(&ctx.gl));
}

#[test]
fn sampling_a_texture_the_pass_draws_into_is_reported() {
    // A feedback loop (GL 3.3 §4.4.3): draw into a framebuffer while its
    // colour texture is bound for sampling. llvmpipe renders something; the
    // draw-time check must still report it.
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let fb = Framebuffer::new(gl, "loop", 8, 8, &[glow::RGBA8], None).unwrap();
    let program = Program::new(
        gl,
        &Sources::Embedded,
        &[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "deferred/composite.frag"),
        ],
        &[],
    )
    .unwrap();
    let mesh = Mesh::upload(gl, &gloss::geometry::fullscreen_triangle()).unwrap();
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
        gl.viewport(0, 0, 8, 8);
        program.use_program();
        program.set_i32("u_light", 4);
        gl.active_texture(glow::TEXTURE4);
        gl.bind_texture(glow::TEXTURE_2D, Some(fb.colors[0].id));
        gl.active_texture(glow::TEXTURE0);
    }
    mesh.draw();
    let err = ctx
        .debug
        .check(gl, "a deliberate feedback loop")
        .unwrap_err();
    assert!(format!("{err}").contains("feedback loop"), "{err}");
    assert!(format!("{err}").contains("texture unit 4"), "{err}");
}

#[test]
fn debug_output_catches_a_gl_error() {
    // The zero-GL-error checks are only worth something if they can fail.
    use glow::HasContext;
    let ctx = common::context(common::backend());
    unsafe { ctx.gl.enable(0xDEAD) };
    let err = ctx.debug.check(&ctx.gl, "a deliberate error").unwrap_err();
    assert!(format!("{err}").contains("GL_INVALID_ENUM"), "{err}");
}
