//! Deferred shading (notes 01 §8.6 "Deferred Rendering" and §8.6.2 step 2
//! "Lighting Calculations"; notes 02 "Deferred shading"; notes 04 "Our
//! current deferred shader"):
//!
//! ```text
//! for every fragment in the G-buffer (the size of the screen)
//!     for every light: calculate shading
//! ```
//!
//! Two forms, `render.deferred_lights`:
//!
//! - `per_light` (notes 04): one full-screen triangle per light, added
//!   together with glBlendFunc(GL_ONE, GL_ONE) into a black HDR target;
//! - `single_pass` (notes 01 §8.6.2 as written): one full-screen triangle
//!   whose shader loops over every light (glsl/deferred/deferred_shading_single_pass.frag),
//!   no blending: the sum is made in f32 and written once, so the G-buffer
//!   is read once a pixel, not once a light.
//!
//! Both write the light accumulation target, which this file describes for
//! every deferred lighting pass; composite.rs then adds the ambient term and
//! writes the final image. Each pixel is shaded for every light whether the
//! light reaches it or not: light_volumes.rs removes that waste.
//!
//! Both shaders are compiled for the frame's lighting variant
//! (src/frame/variant.rs): only the light types, falloffs, shadows and
//! reflectance models the scene holds (`render.specialize`).
//!
//! GL state: no depth test, depth writes off, additive blending (per light);
//! restores depth writes and no blending.

use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::plan_programs::PlanProgram;
use crate::frame::shadows;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::uniforms::LIGHTS_BINDING;
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{DeferredLights, RenderPath, Scene};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const DEFERRED_SHADING: Technique = Technique {
    name: "deferred_shading",
    notes: "notes 01 §8.6; notes 02, Deferred shading; notes 04, our current deferred shader",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "deferred/deferred_shading.frag",
        "deferred/deferred_shading_single_pass.frag",
    ],
    scene: "scenes/deferred-shading.toml",
    docs: "docs/deferred/deferred_shading.md",
    knobs: &[&knobs::ACCUMULATION, &knobs::DEFERRED_LIGHTS],
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
    let draws = match scene.render.deferred_lights {
        DeferredLights::PerLight => format!(
            "{} full-screen triangles, one per light, additive",
            lights.len()
        ),
        DeferredLights::SinglePass => format!(
            "1 full-screen triangle, its shader looping over {} lights",
            lights.len()
        ),
    };
    let shadows = scene.lights.iter().any(|l| l.shadow.is_some());
    let reads: &[&str] = if shadows {
        &[gbuffer::NAME, "shadow map"]
    } else {
        &[gbuffer::NAME]
    };
    // Its program, the form's, built with the lighting variant's defines.
    let variant = LightingVariant::of(scene, lights);
    let role = match scene.render.deferred_lights {
        DeferredLights::PerLight => "per light",
        DeferredLights::SinglePass => "single pass",
    };
    vec![
        Pass::new("lighting", LIGHT_ACCUMULATION, draws, file!())
            .reading(reads)
            .with_variant(variant.describe())
            .with_programs(vec![PlanProgram::new(role, variant.defines())]),
    ]
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
        downscale: 1,
    }
}

struct DeferredShading {
    program: Program,
    single_pass: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    // Both programs specialised to the frame's lighting variant
    // (src/frame/variant.rs): the renderer builds them again when it changes.
    let program = p.build_variant(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "deferred/deferred_shading.frag"),
    ])?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    let single_pass = p.build_variant(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (
            glow::FRAGMENT_SHADER,
            "deferred/deferred_shading_single_pass.frag",
        ),
    ])?;
    single_pass.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&single_pass);
    Ok(Box::new(DeferredShading {
        program,
        single_pass,
    }))
}

impl RunPasses for DeferredShading {
    /// The lighting pass: one full-screen triangle per light, additive, or
    /// one for all the lights.
    fn run(&self, _: &Pass, f: &Frame) {
        let single = f.scene.render.deferred_lights == DeferredLights::SinglePass;
        let p = if single {
            &self.single_pass
        } else {
            &self.program
        };
        let (gl, u) = (f.gl, f.uniforms);
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
            if !single {
                gl.enable(glow::BLEND);
                gl.blend_func(glow::ONE, glow::ONE);
            }

            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            if single {
                p.set_i32("u_light_count", u.light_count);
                f.meshes.fullscreen.draw();
            } else {
                for i in 0..u.light_count {
                    p.set_i32("u_light_id", i);
                    f.meshes.fullscreen.draw();
                }
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
