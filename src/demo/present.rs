//! Showing a frame: the renderer's framebuffer blitted to the window.

use crate::gl::framebuffer::Framebuffer;
use crate::gl::window::WindowContext;
use anyhow::Result;
use glow::HasContext;

/// Copy the renderer's colour attachment 0 to the window's back buffer.
///
/// The output already holds sRGB-encoded bytes, so GL_FRAMEBUFFER_SRGB stays
/// off (no second encoding); the scissor test would clip the blit, so it is off too.
pub(super) fn present(
    ctx: &WindowContext,
    output: &Framebuffer,
    width: i32,
    height: i32,
) -> Result<()> {
    let gl = &ctx.gl;
    unsafe {
        gl.disable(glow::FRAMEBUFFER_SRGB);
        gl.disable(glow::SCISSOR_TEST);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(output.id));
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
        if (output.width, output.height) != (width, height) {
            // A resize is on its way; avoid showing stale pixels at the edges.
            gl.clear_color(0.0, 0.0, 0.0, 1.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
        }
        gl.blit_framebuffer(
            0,
            0,
            output.width,
            output.height,
            0,
            0,
            width,
            height,
            glow::COLOR_BUFFER_BIT,
            glow::NEAREST,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    ctx.debug.check(gl, "presenting the frame")
}
