//! Forward rendering (notes 04, "Forward rendering"; notes 01 §8.2 and §8.3).
//!
//! ```text
//! for every object in the scene
//!     for every fragment of that object
//!         for every light: calculate shading
//! ```
//!
//! Three shading modes from notes 01 §8.2: flat (one colour per triangle,
//! lit in a geometry shader), Gouraud (lit per vertex) and Phong (lit per
//! fragment). This is the reference every deferred path is compared against.

use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::{Program, Sources};
use crate::renderer::{DrawList, FrameUniforms};
use crate::scene::{RenderSettings, Shading};
use anyhow::Result;
use glow::HasContext;

pub struct Forward {
    phong: Program,
    gouraud: Program,
    flat: Program,
}

impl Forward {
    pub fn new(gl: &Gl, sources: &Sources, defines: &[(&str, String)]) -> Result<Forward> {
        let phong = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "forward.vert"),
                (glow::FRAGMENT_SHADER, "forward.frag"),
            ],
            defines,
        )?;
        let gouraud = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "forward_gouraud.vert"),
                (glow::FRAGMENT_SHADER, "forward_gouraud.frag"),
            ],
            defines,
        )?;
        let flat = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "forward_flat.vert"),
                (glow::GEOMETRY_SHADER, "forward_flat.geom"),
                (glow::FRAGMENT_SHADER, "forward_flat.frag"),
            ],
            defines,
        )?;
        for p in [&phong, &gouraud, &flat] {
            p.bind_uniform_block("Lights", 0);
        }
        Ok(Forward {
            phong,
            gouraud,
            flat,
        })
    }

    /// The forward pass: clear, depth test, back-face culling, one draw per object.
    pub fn draw(
        &self,
        gl: &glow::Context,
        settings: &RenderSettings,
        frame: &FrameUniforms,
        draws: &DrawList,
        target: &Framebuffer,
    ) {
        let program = match settings.shading {
            Shading::Phong => &self.phong,
            Shading::Gouraud => &self.gouraud,
            Shading::Flat => &self.flat,
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            gl.viewport(0, 0, target.width, target.height);
            let bg = frame.clear_color;
            gl.clear_color(bg.x, bg.y, bg.z, 1.0);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(settings.depth_func);
            gl.depth_mask(true);
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);

            program.use_program();
            program.set_mat4("u_view_projection", &frame.view_projection);
            program.set_vec3("u_eye", frame.eye);
            program.set_vec3("u_ambient", settings.ambient);
            program.set_i32("u_light_count", frame.light_count);
            program.set_bool("u_output_srgb", frame.output_srgb);
            program.set_i32("u_diffuse_texture", 0);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, Some(frame.lights_ubo));
            draws.draw_objects(gl, program);

            // Restore the state this pass changed.
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, None);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
