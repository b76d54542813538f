//! The G-buffer (notes 01 §8.6 "Deferred Rendering", §8.6.2 step 1; notes 02
//! "G-Buffers"): screen-sized textures holding what lighting needs.
//!
//! | attachment | format       | holds                                  |
//! |------------|--------------|----------------------------------------|
//! | 0          | RGBA16F      | world normal (unit) and shininess      |
//! | 1          | SRGB8_ALPHA8 | diffuse albedo (stored sRGB, read linear) |
//! | 2          | SRGB8_ALPHA8 | specular colour                        |
//! | depth      | DEPTH24_STENCIL8 | depth (position is rebuilt from it) and the stencil the light volumes may use |
//!
//! Notes 03 stores `(normal + 1) / 2` in 8 bits; a 16-bit float keeps the
//! normal to about 1e-3 instead of 4e-3, which is what keeps deferred within
//! one 8-bit step of forward. The notes 03 alpha/eta/k_s triple would go in a
//! fourth RGBA8 attachment (with its "convert" flags in alpha) when a
//! material model needs it; the Phong model does not, so no frame pays for it.
//! docs/gbuffer.md works through the precision of each choice.

use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::{Program, Sources};
use crate::renderer::{DrawList, FrameUniforms};
use crate::scene::RenderSettings;
use anyhow::Result;
use glow::HasContext;

pub const NORMAL_FORMAT: u32 = glow::RGBA16F;
pub const ALBEDO_FORMAT: u32 = glow::SRGB8_ALPHA8;
pub const SPECULAR_FORMAT: u32 = glow::SRGB8_ALPHA8;
pub const DEPTH_FORMAT: u32 = glow::DEPTH24_STENCIL8;

pub struct GBuffer {
    pub fbo: Framebuffer,
    program: Program,
}

impl GBuffer {
    /// `thin`: only normal + shininess and depth (the light pre-pass needs no
    /// material in its G-buffer; the fragment shader's other outputs are dropped).
    pub fn new(gl: &Gl, sources: &Sources, width: i32, height: i32, thin: bool) -> Result<GBuffer> {
        let program = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "gbuffer.vert"),
                (glow::FRAGMENT_SHADER, "gbuffer.frag"),
            ],
            &[],
        )?;
        Ok(GBuffer {
            fbo: Self::make_fbo(gl, width, height, thin)?,
            program,
        })
    }

    pub fn make_fbo(gl: &Gl, width: i32, height: i32, thin: bool) -> Result<Framebuffer> {
        let colors: &[u32] = if thin {
            &[NORMAL_FORMAT]
        } else {
            &[NORMAL_FORMAT, ALBEDO_FORMAT, SPECULAR_FORMAT]
        };
        Framebuffer::new(gl, "gbuffer", width, height, colors, Some(DEPTH_FORMAT))
    }

    pub fn depth(&self) -> &crate::gl::texture::Texture {
        self.fbo
            .depth_stencil
            .as_ref()
            .expect("the G-buffer has depth")
    }

    /// Fill the G-buffer: like a forward pass, but writing surface data.
    pub fn draw(
        &self,
        gl: &glow::Context,
        settings: &RenderSettings,
        frame: &FrameUniforms,
        draws: &DrawList,
    ) {
        let p = &self.program;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.fbo.id));
            gl.viewport(0, 0, self.fbo.width, self.fbo.height);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(settings.depth_func);
            gl.depth_mask(true);
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT);
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            // Linear albedo and specular are encoded to sRGB as they are stored.
            gl.enable(glow::FRAMEBUFFER_SRGB);

            p.use_program();
            p.set_mat4("u_view_projection", &frame.view_projection);
            p.set_i32("u_diffuse_texture", 0);
            draws.draw_objects(gl, p);

            gl.disable(glow::FRAMEBUFFER_SRGB);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }

    /// Bind the attachments on texture units 0-3 for a lighting pass and set
    /// the sampler uniforms of `p` (which must be in use).
    pub fn bind_for_lighting(&self, gl: &glow::Context, p: &Program, frame: &FrameUniforms) {
        let c = &self.fbo.colors;
        let units = [
            ("u_gbuffer_normal", Some(c[0].id)),
            ("u_gbuffer_albedo", c.get(1).map(|t| t.id)),
            ("u_gbuffer_specular", c.get(2).map(|t| t.id)),
            ("u_gbuffer_depth", Some(self.depth().id)),
        ];
        unsafe {
            for (i, (name, tex)) in units.into_iter().enumerate() {
                gl.active_texture(glow::TEXTURE0 + i as u32);
                gl.bind_texture(glow::TEXTURE_2D, tex);
                p.set_i32(name, i as i32);
            }
            gl.active_texture(glow::TEXTURE0);
        }
        p.set_mat4("u_inverse_view_projection", &frame.inverse_view_projection);
        p.set_vec3("u_eye", frame.eye);
    }

    /// Unbind texture units 0..n.
    pub fn unbind_textures(gl: &glow::Context, n: u32) {
        unsafe {
            for i in 0..n {
                gl.active_texture(glow::TEXTURE0 + i);
                gl.bind_texture(glow::TEXTURE_2D, None);
            }
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
