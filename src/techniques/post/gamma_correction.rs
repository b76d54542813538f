//! The gamma correction pass (notes 03, "Gamma Correction Pass": it "reads
//! from the merge buffer, performs the gamma correction, and renders the
//! image to screen"): the last step of every post chain, into the output.
//!
//! The 8-bit output stores encoded values, so that its 256 steps are spread
//! the way the eye sees light: `pow(c, 1 / gamma)` with the scene's gamma
//! (2.2 unless it says otherwise), or, with `srgb = true`, the exact sRGB
//! curve (IEC 61966-2-1: a linear toe, then a 2.4 power) applied by the
//! hardware: the output is SRGB8_ALPHA8 and GL_FRAMEBUFFER_SRGB is on while
//! the pass draws, so the shader writes linear light and GL encodes it.
//! Into an RGBA32F output (error measurements) nothing is encoded.
//!
//! GL state: GL_FRAMEBUFFER_SRGB for `srgb = true`, off again after.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::{self, entries, step_pass};
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::post::PostPass;
use anyhow::Result;
use glow::HasContext;

pub const GAMMA_CORRECTION: Technique = Technique {
    name: "gamma_correction",
    notes: "notes 03, Gamma Correction Pass",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/gamma_correction.frag"],
    scene: "scenes/post-effects.toml",
    docs: "docs/post/gamma_correction.md",
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
            PostPass::Gamma { gamma, srgb } => {
                let curve = if *srgb {
                    "exact sRGB (GL_FRAMEBUFFER_SRGB)".to_string()
                } else {
                    format!("gamma {gamma}")
                };
                Some(step_pass(
                    scene,
                    "gamma correction",
                    &curve,
                    i,
                    step,
                    file!(),
                ))
            }
            _ => None,
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct GammaCorrection {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(GammaCorrection {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "post/gamma_correction.frag"),
        ])?,
    }))
}

impl RunPasses for GammaCorrection {
    fn run(&self, pass: &Pass, f: &Frame) {
        let PostPass::Gamma { gamma, srgb } = f.scene.post[pass.item] else {
            unreachable!("the plan gives gamma correction its own entries")
        };
        let gl = f.gl;
        unsafe {
            if srgb {
                gl.enable(glow::FRAMEBUFFER_SRGB);
            }
            post::run_step(f, &self.program, pass.value as usize, |p| {
                p.set_f32("u_gamma", gamma);
                p.set_bool("u_encode", f.uniforms.output_encoded && !srgb);
            });
            if srgb {
                gl.disable(glow::FRAMEBUFFER_SRGB);
            }
        }
    }
}
