//! Showing a frame: the renderer's framebuffer blitted to the window.

use crate::gl::framebuffer::Framebuffer;
use crate::gl::window::WindowContext;
use anyhow::Result;
use glow::HasContext;

/// Copy the renderer's colour attachment 0 into the 3D view's rectangle
/// `[x, y, width, height]` (from the top left) of a window `window_height`
/// pixels high: scaled up when the frame is rendered at a fraction of the
/// view (each rendered pixel a block, NEAREST).
///
/// The output already holds sRGB-encoded bytes, so GL_FRAMEBUFFER_SRGB stays
/// off (no second encoding); the scissor test would clip the blit, so it is off too.
pub(super) fn present(
    ctx: &WindowContext,
    output: &Framebuffer,
    [x, y, width, height]: [i32; 4],
    window_height: i32,
) -> Result<()> {
    let gl = &ctx.gl;
    let bottom = window_height - y - height;
    unsafe {
        gl.disable(glow::FRAMEBUFFER_SRGB);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(output.id));
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
        if x > 0 {
            // The strip under the panel: cleared, so no old frame shows
            // through where the panel is narrower than it was.
            gl.enable(glow::SCISSOR_TEST);
            gl.scissor(0, 0, x, window_height);
            gl.clear_color(0.0, 0.0, 0.0, 1.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
        }
        gl.disable(glow::SCISSOR_TEST);
        gl.blit_framebuffer(
            0,
            0,
            output.width,
            output.height,
            x,
            bottom,
            x + width,
            bottom + height,
            glow::COLOR_BUFFER_BIT,
            glow::NEAREST,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
    ctx.debug.check(gl, "presenting the frame")
}

/// egui_glow leaves its state behind (scissor test and blending on, its
/// program, buffers and texture bound): put back the defaults every pass of
/// the renderer starts from (tests/frame checks each pass leaves them so).
pub fn restore_after_egui(gl: &glow::Context) {
    unsafe {
        gl.disable(glow::SCISSOR_TEST);
        gl.disable(glow::BLEND);
        gl.blend_equation(glow::FUNC_ADD);
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::FRAMEBUFFER_SRGB);
        gl.disable(glow::CULL_FACE);
        gl.disable(glow::DEPTH_TEST);
        gl.color_mask(true, true, true, true);
        gl.use_program(None);
        gl.bind_vertex_array(None);
        gl.bind_buffer(glow::ARRAY_BUFFER, None);
        gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, None);
        gl.active_texture(glow::TEXTURE0);
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}
