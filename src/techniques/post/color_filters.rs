//! Per-pixel colour filters, stages of the post chain (notes 01 §9): each
//! pixel from its own value only. `grayscale` keeps the luminance (the
//! Rec. 709 weights of linear light: 0.2126 R + 0.7152 G + 0.0722 B);
//! `invert` gives 1 - c of the colour clamped to 0..1 (put it after tone
//! mapping: HDR light above 1 has no inverse on a display).
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

pub const COLOR_FILTERS: Technique = Technique {
    name: "color_filters",
    notes: "notes 01 §9, Post processing (a stage of the chain)",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/color_filters.frag"],
    scene: "scenes/post-filters.toml",
    docs: "docs/post/color_filters.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::AfterViews,
};

/// The filter glsl/post/color_filters.frag applies.
fn mode(p: &PostPass) -> Option<(&'static str, i32)> {
    match p {
        PostPass::Grayscale => Some(("grayscale", 0)),
        PostPass::Invert => Some(("invert", 1)),
        _ => None,
    }
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    (entries(scene))
        .filter_map(|(i, step, p)| {
            let (name, _) = mode(p)?;
            Some(step_pass(scene, name, "", i, step, file!()))
        })
        .collect()
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ColorFilters {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(ColorFilters {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "post/color_filters.frag"),
        ])?,
    }))
}

impl RunPasses for ColorFilters {
    fn run(&self, pass: &Pass, f: &Frame) {
        let (_, mode) = mode(&f.scene.post[pass.item]).expect("a colour filter's entry");
        post::run_step(f, &self.program, pass.value as usize, |p| {
            p.set_i32("u_mode", mode);
        });
    }
}
