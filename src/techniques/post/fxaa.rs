//! FXAA, a stage of the post chain (notes 01 §8.6: "may need to perform
//! anti-aliasing on final scene to remove jaggedness from edges"; notes 01
//! §9: an effect that depends on multiple fragments). FXAA 3.11's quality
//! version: Timothy Lottes, "FXAA", NVIDIA whitepaper (2009), and the FXAA
//! 3.11 source (NVIDIA, 2011), step for step in glsl/post/fxaa.frag:
//!
//! 1. Local contrast: the luma of the pixel and its four neighbours; a
//!    pixel whose range is below max(edge_threshold_min, edge_threshold x
//!    the brightest) is no edge and is written back unchanged.
//! 2. Sub-pixel aliasing: how far the pixel stands out of the 3x3 lowpass,
//!    relative to the range, through a smoothstep, squared, x subpix.
//! 3. Edge direction: horizontal or vertical, by the larger sum of second
//!    differences across the 3x3; then the side of the pixel the edge lies
//!    on (the neighbour with the steeper gradient).
//! 4. Search: from half a texel toward that side, bilinear luma fetches
//!    step along the edge both ways (the preset's steps) until the luma
//!    leaves the edge's average by a quarter of its gradient.
//! 5. Blend: the nearer end gives how far along the edge the pixel lies;
//!    the larger of that offset and the sub-pixel one moves one bilinear
//!    fetch across the edge: the pixel's new colour.
//!
//! Where it sits: after `tonemap` and before `gamma` (src/scene/post.rs
//! refuses it before a tonemap). Its thresholds are for luma in 0..1, which
//! HDR light is not, and FXAA wants luma "in a perceptual space": the image
//! here is tone-mapped *linear* colour, so the luma is the FXAA source's own
//! formula for linear colour, sqrt(dot(rgb, (0.299, 0.587, 0.114))) (gamma
//! 2.0), computed at each fetch. The blend itself mixes linear colour, as
//! FXAA does into an sRGB target.
//!
//! GL state: a sampler object on unit::POST_INPUT while it draws (linear
//! filtering, clamp to edge: FXAA reads between texels on purpose; the
//! textures stay GL_NEAREST), unbound after; otherwise the chain's
//! (src/frame/post.rs `run_step`).

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::{self, entries, step_pass};
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::fxaa::MAX_STEPS;
use crate::scene::post::PostPass;
use anyhow::{Result, anyhow};
use glow::HasContext;

pub const FXAA: Technique = Technique {
    name: "fxaa",
    notes: "notes 01 §8.6, Deferred Rendering (anti-aliasing the final scene); notes 01 §9",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/fxaa.frag"],
    scene: "scenes/antialiasing.toml",
    docs: "docs/post/fxaa.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::AfterViews,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    (entries(scene))
        .filter_map(|(i, step, p)| match p {
            PostPass::Fxaa(x) => {
                let what = format!(
                    "FXAA 3.11 quality {} ({} search steps), subpix {}, edge {} (min {})",
                    x.quality,
                    x.steps().len(),
                    x.subpix,
                    x.edge_threshold,
                    x.edge_threshold_min,
                );
                Some(step_pass(scene, "fxaa", &what, i, step, file!()))
            }
            _ => None,
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Fxaa {
    program: Program,
    /// Linear filtering and clamp to edge, whatever the texture's own settings.
    sampler: glow::Sampler,
    gl: crate::gl::Gl,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "post/fxaa.frag"),
    ])?;
    let gl = p.gl;
    let sampler = unsafe {
        let s = gl
            .create_sampler()
            .map_err(|e| anyhow!("glGenSamplers: {e}"))?;
        gl.sampler_parameter_i32(s, glow::TEXTURE_MIN_FILTER, glow::LINEAR as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_MAG_FILTER, glow::LINEAR as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE as i32);
        s
    };
    Ok(Box::new(Fxaa {
        program,
        sampler,
        gl: gl.clone(),
    }))
}

impl Drop for Fxaa {
    fn drop(&mut self) {
        unsafe { self.gl.delete_sampler(self.sampler) }
    }
}

impl RunPasses for Fxaa {
    fn run(&self, pass: &Pass, f: &Frame) {
        let PostPass::Fxaa(x) = f.scene.post[pass.item] else {
            unreachable!("the plan gives FXAA its own entries")
        };
        let mut steps = [0.0f32; MAX_STEPS];
        let n = x.steps().len().min(MAX_STEPS);
        steps[..n].copy_from_slice(&x.steps()[..n]);
        let gl = f.gl;
        unsafe {
            gl.bind_sampler(unit::POST_INPUT, Some(self.sampler));
            post::run_step(f, &self.program, pass.value as usize, |p| {
                p.set_f32("u_subpix", x.subpix);
                p.set_f32("u_edge_threshold", x.edge_threshold);
                p.set_f32("u_edge_threshold_min", x.edge_threshold_min);
                p.set_i32("u_steps", n as i32);
                p.set_f32_array("u_step[0]", &steps);
            });
            gl.bind_sampler(unit::POST_INPUT, None);
        }
    }
}
