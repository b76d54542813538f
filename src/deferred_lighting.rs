//! Deferred lighting, the light pre-pass (notes 02 "Deferred lighting is like
//! deferred shading, but computes specular and diffuse shading separately,
//! then combines those in a final pass").
//!
//! 1. A thin G-buffer: normal + shininess and depth only (gbuffer.rs, thin).
//! 2. Per light, its volume (light_volumes.rs, the same state and meshes),
//!    accumulating *diffuse* light and *specular* light into two HDR targets.
//! 3. The scene drawn again (the same vertex shader, gl_Position invariant)
//!    with glDepthFunc(GL_LEQUAL) against the G-buffer's depth, copied into the
//!    output with glBlitFramebuffer, and no depth writes; each fragment reads
//!    its light and applies its own material at full precision:
//!    kd (ambient + D) + ks S.

use crate::gbuffer::GBuffer;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::{Program, Sources};
use crate::light_volumes::{VolumeMeshes, volume_pass};
use crate::renderer::{DrawList, FrameUniforms};
use crate::scene::Scene;
use anyhow::Result;
use glow::HasContext;

pub struct DeferredLighting {
    light: Program,
    combine: Program,
}

impl DeferredLighting {
    pub fn new(gl: &Gl, sources: &Sources, defines: &[(&str, String)]) -> Result<DeferredLighting> {
        let light = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "light_volumes.vert"),
                (glow::FRAGMENT_SHADER, "deferred_lighting.frag"),
            ],
            defines,
        )?;
        light.bind_uniform_block("Lights", 0);
        let combine = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "gbuffer.vert"),
                (glow::FRAGMENT_SHADER, "deferred_lighting_combine.frag"),
            ],
            &[],
        )?;
        Ok(DeferredLighting { light, combine })
    }

    /// Step 2: diffuse and specular light, per light volume, additive.
    pub fn lighting(
        &self,
        gl: &glow::Context,
        scene: &Scene,
        frame: &FrameUniforms,
        gbuffer: &GBuffer,
        accumulation: &Framebuffer,
        meshes: &VolumeMeshes,
    ) {
        volume_pass(gl, &self.light, scene, frame, gbuffer, accumulation, meshes);
    }

    /// Step 3: draw the scene again, combining light and material.
    #[allow(clippy::too_many_arguments)]
    pub fn combine(
        &self,
        gl: &glow::Context,
        scene: &Scene,
        frame: &FrameUniforms,
        draws: &DrawList,
        gbuffer: &GBuffer,
        light: &Framebuffer,
        output: &Framebuffer,
    ) {
        let p = &self.combine;
        let (w, h) = (output.width, output.height);
        unsafe {
            // The G-buffer's depth becomes the output's depth.
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(gbuffer.fbo.id));
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(output.id));
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
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            gl.viewport(0, 0, w, h);
            let bg = frame.clear_color;
            gl.clear_color(bg.x, bg.y, bg.z, 1.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LEQUAL);
            gl.depth_mask(false);
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);

            p.use_program();
            p.set_mat4("u_view_projection", &frame.view_projection);
            p.set_vec3("u_ambient", scene.render.ambient);
            p.set_bool("u_output_srgb", frame.output_srgb);
            p.set_i32("u_diffuse_texture", 0);
            p.set_i32("u_diffuse_light", 4);
            p.set_i32("u_specular_light", 5);
            gl.active_texture(glow::TEXTURE4);
            gl.bind_texture(glow::TEXTURE_2D, Some(light.colors[0].id));
            gl.active_texture(glow::TEXTURE5);
            gl.bind_texture(glow::TEXTURE_2D, Some(light.colors[1].id));
            draws.draw_objects(gl, p);

            GBuffer::unbind_textures(gl, 6);
            gl.use_program(None);
            gl.disable(glow::CULL_FACE);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
