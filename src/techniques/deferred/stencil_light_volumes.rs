//! Light volumes with the two-sided stencil test (notes 05 "Stencil Buffer",
//! "Stencil Tests" and "Stencil Operations", applied to notes 04's light
//! volumes; `render.stencil_volumes = true`).
//!
//! Plain light volumes (light_volumes.rs) shade every back-face fragment in
//! front of which the scene lies, and leave the shader to discard surfaces
//! in front of the volume. The stencil marks exactly the pixels whose
//! surface is inside the volume first, per light:
//!
//! 1. Mark: colour writes off, both faces drawn, depth tested against the
//!    scene (a copy of the G-buffer's depth). Where the depth test FAILS (the
//!    surface is in front of the face), a back face increments the stencil
//!    (GL_INCR_WRAP) and a front face decrements it (GL_DECR_WRAP). A surface
//!    inside the volume is in front of the back face only: its stencil is 1.
//! 2. Shade: colour on, front faces culled, no depth test, stencil test
//!    GL_NOTEQUAL 0; each shaded pixel's stencil is set back to 0
//!    (GL_ZERO on pass), ready for the next light.
//!
//! Lights without a volume are drawn full screen afterwards, as in
//! light_volumes.rs.
//!
//! GL state: stencil test and ops, colour mask, culling, depth test and
//! function, depth clamp, additive blending; all restored.

use crate::frame::gbuffer;
use crate::frame::lights::{FrameLights, Volume};
use crate::frame::plan::Pass;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{RenderPath, Scene};
use crate::techniques::deferred::deferred_shading::accumulation_target;
use crate::techniques::deferred::light_volumes::{
    self, describe_volumes, volume_pass, volume_program,
};
use anyhow::Result;
use glow::HasContext;

pub const STENCIL_LIGHT_VOLUMES: Technique = Technique {
    name: "stencil_light_volumes",
    notes: "notes 05, Stencil Tests and Stencil Operations; notes 04, Light Volumes",
    file: file!(),
    shaders: &["deferred/light_volumes.vert", "deferred/light_volumes.frag"],
    scene: "scenes/stencil-volumes.toml",
    docs: "docs/deferred/stencil_light_volumes.md",
    knobs: &[
        &knobs::STENCIL_VOLUMES,
        &knobs::CUTOFF,
        &knobs::ACCUMULATION,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn runs(scene: &Scene, lights: &FrameLights) -> bool {
    scene.render.path == RenderPath::Volumes && scene.render.stencil_volumes && !lights.is_empty()
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if !runs(scene, lights) {
        return vec![];
    }
    let draws = format!(
        "{}, stencil-marked then shaded, additive",
        describe_volumes(scene, lights)
    );
    let variant = LightingVariant::of(scene, lights).describe();
    vec![
        Pass::new("lighting", LIGHT_ACCUMULATION, draws, file!())
            .reading(light_volumes::reads(scene))
            .with_variant(variant),
    ]
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene, lights) {
        return vec![];
    }
    vec![accumulation_target(
        scene,
        Depth::Own(gbuffer::depth_format(scene)),
    )]
}

struct StencilLightVolumes {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(StencilLightVolumes {
        program: volume_program(p)?,
    }))
}

impl RunPasses for StencilLightVolumes {
    /// light_volumes.rs's pass (the G-buffer's depth and zero stencil
    /// copied, light added on black), with the stencilled volumes.
    fn run(&self, _: &Pass, f: &Frame) {
        volume_pass(f, &self.program, draw_stencilled_volumes);
    }
}

/// Steps 1 and 2 for every bounded light (program `p` in use, target bound).
fn draw_stencilled_volumes(f: &Frame, p: &Program) {
    let gl = f.gl;
    unsafe {
        gl.enable(glow::STENCIL_TEST);
        gl.depth_mask(false);
        gl.enable(glow::BLEND);
        gl.blend_func(glow::ONE, glow::ONE);
        gl.enable(glow::DEPTH_CLAMP);
        gl.cull_face(glow::FRONT);
        // A reflected view turns the volumes' winding over: which faces
        // are front decides which way the stencil counts.
        gl.front_face(f.view.front_face(false));
    }
    for (i, light) in f.lights.lights.iter().enumerate() {
        let (mesh, model) = match light.volume {
            Volume::Sphere(m) => (&f.meshes.volume_sphere, m),
            Volume::Cone(m) => (&f.meshes.volume_cone, m),
            Volume::FullScreen => continue,
        };
        p.set_i32("u_light_id", i as i32);
        p.set_mat4("u_mvp", &(f.uniforms.view_projection * model));
        unsafe {
            // 1. Mark: both faces, no colour, depth-fail counts.
            gl.color_mask(false, false, false, false);
            gl.disable(glow::CULL_FACE);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.stencil_func(glow::ALWAYS, 0, 0xFF);
            gl.stencil_op_separate(glow::BACK, glow::KEEP, glow::INCR_WRAP, glow::KEEP);
            gl.stencil_op_separate(glow::FRONT, glow::KEEP, glow::DECR_WRAP, glow::KEEP);
            mesh.draw();
            // 2. Shade where stencil != 0, resetting it to 0 as we go.
            gl.color_mask(true, true, true, true);
            gl.enable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.stencil_func(glow::NOTEQUAL, 0, 0xFF);
            gl.stencil_op(glow::KEEP, glow::KEEP, glow::ZERO);
            mesh.draw();
        }
    }
    unsafe {
        gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
        gl.stencil_func(glow::ALWAYS, 0, 0xFF);
        gl.disable(glow::STENCIL_TEST);
        gl.disable(glow::DEPTH_CLAMP);
        gl.depth_func(glow::LESS);
        gl.disable(glow::DEPTH_TEST);
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::BLEND);
        gl.depth_mask(true);
        gl.front_face(glow::CCW);
        gl.cull_face(glow::BACK);
        gl.disable(glow::CULL_FACE);
    }
}
