//! The stencil light volumes made watchable (notes 05, "Stencil
//! Operations"): their step 1, the marking, replayed for every light into
//! the inspector's own depth-stencil buffer. The technique
//! (src/techniques/deferred/stencil_light_volumes.rs) marks one light,
//! shades where the mark is not 0 and resets it to 0, so at the end of its
//! pass the stencil is all 0 again. Here the G-buffer's depth is copied,
//! the stencil cleared, and every bounded light's volume drawn with the
//! technique's marking state (both faces, colour off, depth-fail: back
//! faces GL_INCR_WRAP, front faces GL_DECR_WRAP) without the reset: each
//! surface's stencil ends as the number of volumes it lies inside, the
//! pixels the shading step would light, counted.

use super::volume_views::VolumeViews;
use crate::gl::Gl;
use crate::gl::framebuffer::{Framebuffer, read_stencil_top_down};
use crate::renderer::Renderer;
use anyhow::Result;
use glam::{Mat4, Vec4};
use glow::HasContext;

impl VolumeViews {
    /// Mark every light's volume against the G-buffer's depth (with view
    /// projection `vp`) and return the stencil, one value per pixel, top
    /// row first; None when the frame has no G-buffer depth-stencil.
    pub fn marks(&mut self, gl: &Gl, renderer: &Renderer, vp: Mat4) -> Result<Option<Vec<u8>>> {
        let Some(gbuffer) = renderer.targets().find(crate::frame::gbuffer::NAME) else {
            return Ok(None);
        };
        if gbuffer.depth_stencil.as_ref().map(|t| t.internal_format) != Some(glow::DEPTH24_STENCIL8)
        {
            return Ok(None);
        }
        let (w, h) = (gbuffer.width, gbuffer.height);
        if self.mark_fb.as_ref().map(|f| (f.width, f.height)) != Some((w, h)) {
            self.mark_fb = None;
            self.mark_fb = Some(Framebuffer::new(
                gl,
                "stencil marks",
                w,
                h,
                &[glow::RGBA8],
                Some(glow::DEPTH24_STENCIL8),
            )?);
        }
        let fb = self.mark_fb.as_ref().expect("made above");
        unsafe {
            // The scene's depth, as the technique's target copies it.
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(gbuffer.id));
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(fb.id));
            gl.blit_framebuffer(
                0,
                0,
                w,
                h,
                0,
                0,
                w,
                h,
                glow::DEPTH_BUFFER_BIT,
                glow::NEAREST,
            );
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb.id));
            gl.viewport(0, 0, w, h);
            gl.clear_stencil(0);
            gl.clear(glow::STENCIL_BUFFER_BIT);
            // 1. Mark: both faces, no colour, depth-fail counts.
            gl.enable(glow::STENCIL_TEST);
            gl.color_mask(false, false, false, false);
            gl.depth_mask(false);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.enable(glow::DEPTH_CLAMP);
            gl.stencil_func(glow::ALWAYS, 0, 0xFF);
            gl.stencil_op_separate(glow::BACK, glow::KEEP, glow::INCR_WRAP, glow::KEEP);
            gl.stencil_op_separate(glow::FRONT, glow::KEEP, glow::DECR_WRAP, glow::KEEP);
        }
        self.volumes(gl, renderer, vp, |_| Vec4::ZERO);
        unsafe {
            gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            gl.disable(glow::STENCIL_TEST);
            gl.color_mask(true, true, true, true);
            gl.depth_mask(true);
            gl.disable(glow::DEPTH_TEST);
            gl.disable(glow::DEPTH_CLAMP);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
        Ok(Some(read_stencil_top_down(gl, fb.id, w, h)))
    }
}
