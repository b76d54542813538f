//! Deferred shading (notes 01 §8.6 "Deferred Rendering" and §8.6.2 step 2
//! "Lighting Calculations"; notes 02 "Deferred shading"; notes 04 "Our
//! current deferred shader"):
//!
//! ```text
//! for every fragment in the G-buffer (the size of the screen)
//!     for every light: calculate shading
//! ```
//!
//! One full-screen triangle per light, added together with glBlendFunc(GL_ONE,
//! GL_ONE) into a black HDR target (the light accumulation target, which
//! this file describes for every deferred lighting pass); composite.rs then
//! adds the ambient term and writes the final image. Each pixel is shaded
//! once per light whether the light reaches it or not: light_volumes.rs
//! removes that waste.
//!
//! GL state: no depth test, depth writes off, additive blending; restores
//! depth writes and no blending.

use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::shadows;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::uniforms::LIGHTS_BINDING;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const DEFERRED_SHADING: Technique = Technique {
    name: "deferred_shading",
    notes: "notes 01 §8.6; notes 02, Deferred shading; notes 04, our current deferred shader",
    file: file!(),
    shaders: &["common/fullscreen.vert", "deferred/deferred_shading.frag"],
    scene: "scenes/deferred-shading.toml",
    docs: "docs/deferred/deferred_shading.md",
    knobs: &[&knobs::ACCUMULATION],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if scene.render.path != RenderPath::Deferred || lights.is_empty() {
        return vec![];
    }
    let draws = format!(
        "{} full-screen triangles, one per light, additive",
        lights.len()
    );
    vec![Pass::new("lighting", LIGHT_ACCUMULATION, draws, file!())]
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if scene.render.path != RenderPath::Deferred || lights.is_empty() {
        return vec![];
    }
    vec![accumulation_target(scene, Depth::None)]
}

/// The light accumulation target: one HDR colour attachment (RGBA16F unless
/// the scene asks for RGBA32F). Full-screen lights need no depth; light
/// volumes give it a depth-stencil of its own, a copy of the G-buffer's, to
/// test the volumes against the scene (testing against the G-buffer's own
/// depth texture while the shader samples it would be a feedback loop).
pub fn accumulation_target(scene: &Scene, depth: Depth) -> TargetDesc {
    TargetDesc {
        name: LIGHT_ACCUMULATION,
        samples: 1,
        colors: vec![("light", scene.render.accumulation.gl())],
        depth,
        ping_pong: false,
        mips: None,
    }
}

struct DeferredShading {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "deferred/deferred_shading.frag"),
    ])?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    Ok(Box::new(DeferredShading { program }))
}

impl RunPasses for DeferredShading {
    /// The lighting pass: one full-screen triangle per light, additive.
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, p, u) = (f.gl, &self.program, f.uniforms);
        let target = f.targets.get(LIGHT_ACCUMULATION);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            // "It's super important that our background clear colour is black."
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_mask(false);
            gl.enable(glow::BLEND);
            gl.blend_func(glow::ONE, glow::ONE);

            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            for i in 0..u.light_count {
                p.set_i32("u_light_id", i);
                f.meshes.fullscreen.draw();
            }

            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            f.shadows.unbind(gl);
            gbuffer::unbind(gl);
            gl.use_program(None);
            gl.blend_func(glow::ONE, glow::ZERO);
            gl.disable(glow::BLEND);
            gl.depth_mask(true);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
