//! Deferred shading (notes 01 §8.6; notes 02 "Deferred shading"; notes 04
//! "Our current deferred shader"):
//!
//! ```text
//! for every fragment in the G-buffer (the size of the screen)
//!     for every light: calculate shading
//! ```
//!
//! One full-screen triangle per light, added together with glBlendFunc(GL_ONE,
//! GL_ONE) into a black HDR target; then the composite pass (notes 01 §8.6.2
//! step 3) adds the ambient term and writes the final image. Each pixel is
//! shaded once per light whether the light reaches it or not: light_volumes.rs
//! removes that waste.

use crate::gbuffer::GBuffer;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::renderer::FrameUniforms;
use crate::scene::Scene;
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub struct DeferredShading {
    light: Program,
}

impl DeferredShading {
    pub fn new(gl: &Gl, sources: &Sources, defines: &[(&str, String)]) -> Result<DeferredShading> {
        let light = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "fullscreen.vert"),
                (glow::FRAGMENT_SHADER, "deferred_shading.frag"),
            ],
            defines,
        )?;
        light.bind_uniform_block("Lights", 0);
        Ok(DeferredShading { light })
    }

    /// The lighting pass: one full-screen triangle per light, additive.
    pub fn lighting(
        &self,
        gl: &glow::Context,
        frame: &FrameUniforms,
        gbuffer: &GBuffer,
        accumulation: &Framebuffer,
        fullscreen: &Mesh,
    ) {
        let p = &self.light;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(accumulation.id));
            gl.viewport(0, 0, accumulation.width, accumulation.height);
            // "It's super important that our background clear colour is black."
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_mask(false);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::ONE, glow::ONE);

            p.use_program();
            gbuffer.bind_for_lighting(gl, p, frame);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, Some(frame.lights_ubo));
            for i in 0..frame.light_count {
                p.set_i32("u_light_id", i);
                fullscreen.draw();
            }

            gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, None);
            GBuffer::unbind_textures(gl, 4);
            gl.use_program(None);
            gl.disable(glow::BLEND);
            gl.depth_mask(true);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

/// The composite pass: ambient x albedo + accumulated light, sRGB-encoded.
pub struct Composite {
    program: Program,
}

impl Composite {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<Composite> {
        Ok(Composite {
            program: Program::new(
                gl,
                sources,
                &[
                    (glow::VERTEX_SHADER, "fullscreen.vert"),
                    (glow::FRAGMENT_SHADER, "deferred_composite.frag"),
                ],
                &[],
            )?,
        })
    }

    #[allow(clippy::too_many_arguments)]
    pub fn draw(
        &self,
        gl: &glow::Context,
        scene: &Scene,
        frame: &FrameUniforms,
        gbuffer: &GBuffer,
        light: &Framebuffer,
        output: &Framebuffer,
        fullscreen: &Mesh,
    ) {
        let p = &self.program;
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            gl.viewport(0, 0, output.width, output.height);
            // One triangle covers every pixel exactly once: no depth test needed (notes 02).
            gl.disable(glow::DEPTH_TEST);
            p.use_program();
            gbuffer.bind_for_lighting(gl, p, frame);
            gl.active_texture(glow::TEXTURE4);
            gl.bind_texture(glow::TEXTURE_2D, Some(light.colors[0].id));
            gl.active_texture(glow::TEXTURE0);
            p.set_i32("u_light", 4);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_vec3("u_ambient", scene.render.ambient);
            p.set_vec3("u_background", scene.render.background);
            p.set_bool("u_output_srgb", frame.output_srgb);
            fullscreen.draw();

            GBuffer::unbind_textures(gl, 5);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
