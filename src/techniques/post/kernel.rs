//! A 3x3 convolution, a stage of the post chain (notes 01 §9: "as the scene
//! render pass is available as a texture effects that depend on multiple
//! fragments ... are now possible"): each pixel becomes the weighted sum of
//! itself and its eight neighbours, with the weights from the scene file
//! (`kernel = "sharpen" | "edge" | "emboss"` or nine numbers, row by row
//! from the top). Neighbours past the edge repeat the edge pixel.
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

pub const KERNEL: Technique = Technique {
    name: "kernel",
    notes: "notes 01 §9, Post processing (effects that depend on multiple fragments)",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/kernel.frag"],
    scene: "scenes/post-effects.toml",
    docs: "docs/post/kernel.md",
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
            PostPass::Kernel(k) => {
                let name = k.preset.unwrap_or("custom");
                let what = format!("3x3 {name}");
                Some(step_pass(scene, "kernel", &what, i, step, file!()))
            }
            _ => None,
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Kernel {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Kernel {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "post/kernel.frag"),
        ])?,
    }))
}

impl RunPasses for Kernel {
    fn run(&self, pass: &Pass, f: &Frame) {
        let PostPass::Kernel(k) = &f.scene.post[pass.item] else {
            unreachable!("the plan gives the kernel pass its own entries")
        };
        post::run_step(f, &self.program, pass.value as usize, |p| {
            p.set_f32_array("u_kernel[0]", &k.weights);
        });
    }
}
