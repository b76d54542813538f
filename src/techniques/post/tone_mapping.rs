//! Tone mapping, a stage of the post chain (notes 01 §9): the HDR light the
//! world left in the chain (0 to 65504 in RGBA16F) brought into the 0..1 a
//! display shows, by one of four operators after an exposure scale. Without
//! it the gamma pass clamps, and everything brighter than 1 is flat white.
//! The same curves on the CPU are `lighting::tonemap`.
//!
//! GL state: none besides the chain's (src/frame/post.rs `run_step`).

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::{self, entries, step_pass};
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::post::PostPass;
use anyhow::Result;

pub const TONE_MAPPING: Technique = Technique {
    name: "tone_mapping",
    notes: "notes 01 §9, Post processing (a stage of the chain)",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/tone_mapping.frag"],
    scene: "scenes/post-effects.toml",
    docs: "docs/post/tone_mapping.md",
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
            PostPass::Tonemap { operator, exposure } => {
                let what = format!("{}, exposure {exposure}", operator.name());
                Some(step_pass(scene, "tone mapping", &what, i, step, file!()))
            }
            _ => None,
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ToneMapping {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(ToneMapping {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "post/tone_mapping.frag"),
        ])?,
    }))
}

impl RunPasses for ToneMapping {
    fn run(&self, pass: &Pass, f: &Frame) {
        let PostPass::Tonemap { operator, exposure } = f.scene.post[pass.item] else {
            unreachable!("the plan gives tone mapping its own entries")
        };
        post::run_step(f, &self.program, pass.value as usize, |p| {
            p.set_i32("u_operator", operator.code());
            p.set_f32("u_exposure", exposure);
        });
    }
}
