//! The skybox drawn first (notes 03, Implementation: the comparison behind
//! "to optimize the performance, the depth value z for a pixel is always set
//! to w"). With `render.sky_first = true` the skybox pass's triangle is
//! drawn before the opaque world, with the depth test off, over every pixel;
//! the forward pass then clears only the depth and draws the world over it.
//! Every pixel an object covers is shaded twice, which is what drawing the
//! sky last at z = w with GL_LEQUAL (skybox.rs) saves: `gloss bench SCENE
//! --vary render.sky_first=false,true` measures it (docs/sky/skybox.md).
//!
//! The forward path only: a deferred path's last pass (the composite, the
//! light pre-pass's combine) writes every pixel after it, so there the
//! skybox is drawn last whatever the knob says (`Scene::warnings` says so).
//!
//! GL state: no depth test (the default), GL_TEXTURE_CUBE_MAP_SEAMLESS on
//! and the cube map on unit::ENVIRONMENT while it draws (and a mirror view's
//! stencil test); restores no seamless filtering, no cube map, no stencil test.

use super::skybox;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glow::HasContext;

pub const SKY_FIRST: Technique = Technique {
    name: "sky_first",
    notes: "notes 03, Implementation (the skybox drawn first, for comparison)",
    file: file!(),
    shaders: &["sky/skybox.vert", "sky/skybox.frag"],
    scene: "scenes/skybox-first.toml",
    docs: "docs/sky/skybox.md",
    knobs: &[&knobs::SKY_FIRST],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !scene.sky_first() {
        return vec![];
    }
    let draws = format!(
        "1 full-screen triangle, depth test off, before the world: {} over every pixel",
        skybox::describe(scene)
    );
    vec![Pass::new("sky first", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct SkyFirst {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(SkyFirst {
        program: skybox::program(p)?,
    }))
}

impl RunPasses for SkyFirst {
    fn run(&self, _: &Pass, f: &Frame) {
        let gl = f.gl;
        let output = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);
            // Every pixel: the depth test stays off.
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            skybox::draw(&self.program, f);

            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
