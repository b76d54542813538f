//! Every pass of every path restores the GL state it changed (the default
//! state of a fresh context, snapshotted after each pass), no pass samples a
//! texture attached to the framebuffer it draws into (the draw-time check in
//! src/gl/debug.rs), and both checks can fail.

use crate::common;
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::mesh::Mesh;
use gloss::gl::program::{Program, Sources};
use gloss::scene::RenderPath;
use glow::HasContext;

#[test]
fn every_pass_restores_the_gl_state_it_changed() {
    let ctx = common::context(common::backend());
    let base = common::scene("mixed-lights.toml");
    // Every pass must leave the state of a fresh context.
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
        let changed = common::state_left_changed(&ctx, &scene, 96, 54);
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
    let before = common::gl_state(&ctx.gl);
    unsafe { ctx.gl.enable(glow::BLEND) };
    assert_ne!(before, common::gl_state(&ctx.gl));
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
