//! The pass inspector: any attachment of the frame plan's render targets
//! (the views of src/demo/inspect_views.rs), drawn over the window so that
//! it can be seen (normals as colours, depth linearised, light with an
//! exposure), by a full-screen pass with glsl/demo/inspect.frag; each
//! casting light's shadow map by src/demo/shadow_views.rs. A view may show
//! one mip level of its texture.

pub use super::inspect_views::{Mode, View, follow, views};
use crate::frame::targets::Targets;
use crate::frame::units as unit;
use crate::geometry;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::scene::{Camera, Projection};
use anyhow::{Result, anyhow};
use glam::Mat4;
use glow::HasContext;

pub struct Inspector {
    gl: Gl,
    program: Program,
    fullscreen: Mesh,
    /// For a mip level above 0: GL_NEAREST_MIPMAP_NEAREST, clamped (a
    /// render target's own filter, GL_NEAREST, reads only level 0). Bound
    /// on the unit while it draws, so the texture's settings stay as they are.
    levels: glow::Sampler,
}

impl Inspector {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<Inspector> {
        let levels = unsafe {
            let s = gl
                .create_sampler()
                .map_err(|e| anyhow!("glGenSamplers: {e}"))?;
            for (p, v) in [
                (glow::TEXTURE_MIN_FILTER, glow::NEAREST_MIPMAP_NEAREST),
                (glow::TEXTURE_MAG_FILTER, glow::NEAREST),
                (glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE),
                (glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE),
            ] {
                gl.sampler_parameter_i32(s, p, v as i32);
            }
            s
        };
        Ok(Inspector {
            gl: gl.clone(),
            levels,
            program: Program::new(
                gl,
                sources,
                &[
                    (glow::VERTEX_SHADER, "common/fullscreen.vert"),
                    (glow::FRAGMENT_SHADER, "demo/inspect.frag"),
                ],
                &[],
            )?,
            fullscreen: Mesh::upload(gl, &geometry::fullscreen_triangle())?,
        })
    }

    /// Draw `view` (an attachment) into `into` (its own framebuffer, never
    /// one of the renderer's targets), full size.
    pub fn draw(
        &self,
        gl: &glow::Context,
        view: &View,
        targets: &Targets,
        camera: &Camera,
        exposure: f32,
        into: &Framebuffer,
    ) {
        // A target with mip levels (src/gl/mip_target.rs) has one texture
        // whose GL_TEXTURE_BASE_LEVEL is its first level; textureLod counts
        // from the base level.
        let (texture, lod, mipmapped) = if let Some(m) = targets.mip(view.target) {
            let first = m.levels.first().map_or(0, |l| l.level);
            (Some(m.texture.id), view.level.saturating_sub(first), true)
        } else {
            let Some(fb) = targets.find(view.target) else {
                return;
            };
            let texture = match view.color_index {
                Some(i) => fb.colors.get(i).map(|t| t.id),
                None => fb.depth_stencil.as_ref().map(|t| t.id),
            };
            (texture, view.level, view.level > 0)
        };
        let shown = Shown {
            mode: view.mode,
            level: lod,
            mipmapped,
            exposure,
        };
        self.draw_level(gl, texture, shown, camera, into);
    }

    /// Draw `texture` made visible by `mode` into `into`, full size.
    pub fn draw_texture(
        &self,
        gl: &glow::Context,
        texture: Option<glow::Texture>,
        mode: Mode,
        camera: &Camera,
        exposure: f32,
        into: &Framebuffer,
    ) {
        let shown = Shown {
            mode,
            level: 0,
            mipmapped: false,
            exposure,
        };
        self.draw_level(gl, texture, shown, camera, into);
    }

    /// Draw mip level `shown.level` of `texture` made visible by
    /// `shown.mode` into `into`, stretched to its full size (textureLod in
    /// glsl/demo/inspect.frag), texel by texel. Above level 0 (or when
    /// `shown.mipmapped`) the texture must be mipmap complete up to its
    /// GL_TEXTURE_MAX_LEVEL, as glGenerateMipmap or a mip target leaves it.
    pub fn draw_level(
        &self,
        gl: &glow::Context,
        texture: Option<glow::Texture>,
        shown: Shown,
        camera: &Camera,
        into: &Framebuffer,
    ) {
        let Shown {
            mode,
            level,
            mipmapped,
            exposure,
        } = shown;
        let p = &self.program;
        let (index, encode, scale) = match mode {
            Mode::Color { encode } => (0, encode, 1.0),
            Mode::Normal => (1, false, 1.0),
            Mode::Shininess => (2, false, 1.0),
            Mode::Light => (3, false, 1.0),
            Mode::Depth => (4, false, 1.0),
            Mode::Count { scale } => (5, false, scale),
            Mode::Grey => (6, false, 1.0),
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(into.id));
            gl.viewport(0, 0, into.width, into.height);
            gl.disable(glow::DEPTH_TEST);
            p.use_program();
            gl.active_texture(glow::TEXTURE0 + unit::DEMO_VIEW);
            gl.bind_texture(glow::TEXTURE_2D, texture);
            if level > 0 || mipmapped {
                gl.bind_sampler(unit::DEMO_VIEW, Some(self.levels));
            }
            p.set_i32("u_texture", unit::DEMO_VIEW as i32);
            p.set_f32("u_level", level as f32);
            p.set_i32("u_mode", index);
            p.set_bool("u_encode", encode);
            p.set_f32("u_exposure", exposure);
            p.set_f32("u_scale", scale);
            p.set_f32("u_near", camera.near);
            p.set_f32("u_far", camera.far);
            p.set_bool(
                "u_orthographic",
                matches!(camera.projection, Projection::Orthographic { .. }),
            );
            p.set_vec2(
                "u_viewport",
                glam::Vec2::new(into.width as f32, into.height as f32),
            );
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            self.fullscreen.draw();
            gl.bind_sampler(unit::DEMO_VIEW, None);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

/// How `Inspector::draw_level` shows a texture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shown {
    pub mode: Mode,
    /// The mip level, counted from the texture's base level.
    pub level: u32,
    /// The texture has levels: read through the nearest-level sampler even
    /// at its base level (a mip target filters linearly for its blurs'
    /// taps). Always so above level 0.
    pub mipmapped: bool,
    /// Multiplies HDR light (`Mode::Light`).
    pub exposure: f32,
}

impl Drop for Inspector {
    fn drop(&mut self) {
        unsafe { self.gl.delete_sampler(self.levels) };
    }
}

/// The least and greatest value of a one-channel view's channel (R) over
/// the whole attachment, read back (glReadPixels on its colour attachment):
/// the grey picture maps 0 to black and 1 to white, the range says what the
/// target really holds. None for other views.
pub fn grey_range(targets: &Targets, view: &View) -> Option<(f32, f32)> {
    let plain = view.volumes.is_none() && view.shadow.is_none() && !view.stencil;
    if view.mode != Mode::Grey || !plain || view.level > 0 {
        return None;
    }
    let fb = targets.find(view.target)?;
    let index = view.color_index?;
    if fb.colors.get(index).is_none_or(|t| t.samples > 1) {
        return None;
    }
    let data = fb.read_rgba_f32(index as u32);
    let red = data.iter().step_by(4).copied().filter(|v| v.is_finite());
    red.fold(None, |r, v| match r {
        None => Some((v, v)),
        Some((lo, hi)) => Some((f32::min(lo, v), f32::max(hi, v))),
    })
}
