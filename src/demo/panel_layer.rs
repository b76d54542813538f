//! The panel drawn at the pace of what it shows, not of the frame: egui runs
//! and paints into a texture of its own (`layer`) only when the user gives
//! it input, when it asks to be repainted, or every `PERIOD` (the timings
//! change); every frame lays that texture over the image with one blended
//! full-screen triangle. On llvmpipe, laying egui's meshes out and
//! rasterising its text costs far more than one textured triangle.

use crate::frame::units as unit;
use crate::geometry;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;
use std::time::{Duration, Instant};

/// The longest the panel goes without being drawn again (its timings move).
pub const PERIOD: Duration = Duration::from_millis(500);

pub struct PanelLayer {
    program: Program,
    triangle: Mesh,
    /// egui's output, the window's size (premultiplied RGBA).
    pub layer: Option<Framebuffer>,
    /// When it was last drawn.
    pub drawn: Option<Instant>,
    /// Something happened that the panel must show: draw it this frame.
    pub stale: bool,
    /// Where egui drew (x, y, width, height in GL pixels, y up): only that
    /// is laid over the frame. None: nothing shown.
    area: Option<(i32, i32, i32, i32)>,
}

impl PanelLayer {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<PanelLayer> {
        Ok(PanelLayer {
            program: Program::new(
                gl,
                sources,
                &[
                    (glow::VERTEX_SHADER, "common/fullscreen.vert"),
                    (glow::FRAGMENT_SHADER, "demo/panel_layer.frag"),
                ],
                &[],
            )?,
            triangle: Mesh::upload(gl, &geometry::fullscreen_triangle())?,
            layer: None,
            drawn: None,
            stale: true,
            area: None,
        })
    }

    /// Does the panel need drawing again this frame (at `w` x `h`)?
    pub fn due(&self, w: i32, h: i32) -> bool {
        self.stale
            || self.drawn.is_none_or(|t| t.elapsed() >= PERIOD)
            || self.layer.as_ref().map(|l| (l.width, l.height)) != Some((w, h))
    }

    /// Bind the layer (made at `w` x `h` when needed), cleared to
    /// transparent, for egui to paint into.
    pub fn begin(&mut self, gl: &Gl, w: i32, h: i32) -> Result<()> {
        if self.layer.as_ref().map(|l| (l.width, l.height)) != Some((w, h)) {
            self.layer = None;
            self.layer = Some(Framebuffer::new(gl, "panel", w, h, &[glow::RGBA8], None)?);
        }
        let layer = self.layer.as_ref().expect("made above");
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(layer.id));
            gl.viewport(0, 0, w, h);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
        }
        self.drawn = Some(Instant::now());
        self.stale = false;
        Ok(())
    }

    /// Where egui drew this time: `used`, in points (`pixels_per_point`),
    /// in a window `height` pixels high.
    pub fn set_area(&mut self, used: egui::Rect, pixels_per_point: f32, height: i32) {
        self.area = used.is_positive().then(|| {
            let px = |v: f32| (v * pixels_per_point) as i32;
            let (x0, x1) = (px(used.min.x).max(0), px(used.max.x.ceil()) + 1);
            let (top, bottom) = (px(used.min.y).max(0), px(used.max.y.ceil()) + 1);
            (x0, height - bottom, x1 - x0, bottom - top)
        });
    }

    /// Lay the layer over the window's back buffer, where egui drew: the
    /// scissor test keeps the blend to that rectangle.
    pub fn composite(&self, gl: &glow::Context, w: i32, h: i32) {
        let (Some(layer), Some((x, y, aw, ah))) = (&self.layer, self.area) else {
            return;
        };
        let p = &self.program;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.viewport(0, 0, w, h);
            gl.enable(glow::SCISSOR_TEST);
            gl.scissor(x, y, aw, ah);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::ONE, glow::ONE_MINUS_SRC_ALPHA);
            p.use_program();
            gl.active_texture(glow::TEXTURE0 + unit::DEMO_VIEW);
            gl.bind_texture(glow::TEXTURE_2D, Some(layer.colors[0].id));
            p.set_i32("u_layer", unit::DEMO_VIEW as i32);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            self.triangle.draw();
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.blend_func(glow::ONE, glow::ZERO);
            gl.disable(glow::BLEND);
            gl.disable(glow::SCISSOR_TEST);
        }
    }
}
