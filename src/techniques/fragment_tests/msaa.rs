//! Multisample anti-aliasing, MSAA (notes 01 §4 "Fragment Operations",
//! whose reference is per-sample processing; notes 01 §8.6: "may need to
//! perform anti-aliasing on final scene to remove jaggedness from edges").
//!
//! Why this chapter: MSAA is a matter of the fragment tests. A pixel of a
//! multisampled target holds N samples, each with its own colour, depth and
//! stencil. The rasterizer decides coverage per sample; the fragment shader
//! runs once per pixel and its colour is written to the covered samples that
//! pass the depth and stencil tests, which run *per sample*. So an edge
//! pixel ends up with the right fraction of its samples from each side, and
//! only the tests and the coverage cost N times more, not the shading.
//!
//! With `render.msaa = N` (N > 1) on the forward path:
//!
//! 1. The world's passes (forward, mirrors, split views, billboards,
//!    transparency) draw into `msaa`, a twin of the world image with N
//!    samples per pixel: GL_TEXTURE_2D_MULTISAMPLE colour and depth-stencil
//!    (src/frame/multisample.rs; `post::world_target` names it).
//! 2. This pass, once after every view and before anything samples the
//!    world, resolves it: glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa),
//!    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, world image),
//!    glBlitFramebuffer(whole frame, GL_COLOR_BUFFER_BIT |
//!    GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST): each pixel's
//!    colour becomes the mean of its samples; depth and stencil take one
//!    sample's (depth and stencil cannot be averaged, hence GL_NEAREST).
//!
//! It is the first of the passes that run after the views: the plan orders
//! those by post entry (`Pass::item`), stably, and this technique is
//! registered before the chain's, with item 0.
//!
//! Only on the forward path: a G-buffer would have to be multisampled and
//! lit once per differing sample (docs/fragment_tests/msaa.md).
//!
//! GL state: binds the read and draw framebuffers, unbinds both after.

use crate::frame::lights::FrameLights;
use crate::frame::multisample::{self, MSAA};
use crate::frame::plan::Pass;
use crate::frame::post::world_image;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glow::HasContext;

pub const MSAA_RESOLVE: Technique = Technique {
    name: "msaa",
    notes: "notes 01 §4, Fragment Operations (per-sample processing); notes 01 §8.6",
    file: file!(),
    shaders: &[],
    scene: "scenes/antialiasing.toml",
    docs: "docs/fragment_tests/msaa.md",
    knobs: &[&knobs::MSAA],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::AfterViews,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !multisample::active(scene) {
        return vec![];
    }
    let to = world_image(scene);
    let draws = format!(
        "glBlitFramebuffer {MSAA} ({} samples) -> {to}: colour (mean of the samples), depth and stencil (GL_NEAREST)",
        multisample::samples(scene)
    );
    vec![Pass::new("msaa resolve", to, draws, file!())]
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    multisample::target(scene).into_iter().collect()
}

struct Resolve;

fn create(_: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Resolve))
}

impl RunPasses for Resolve {
    fn run(&self, pass: &Pass, f: &Frame) {
        let gl = f.gl;
        let from = f.targets.get(MSAA);
        let to = f.targets.get(pass.target);
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(from.id));
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(to.id));
            gl.blit_framebuffer(
                0,
                0,
                from.width,
                from.height,
                0,
                0,
                to.width,
                to.height,
                glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT,
                glow::NEAREST,
            );
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
        }
    }
}
