//! Weighted blended order-independent transparency: McGuire and Bavoil 2013,
//! "Weighted Blended Order-Independent Transparency", Journal of Computer
//! Graphics Techniques 2(2). Chosen with `render.transparency =
//! "weighted_blended"` in place of the sorted pass (transparency.rs).
//!
//! The paper's steps (its §4 and its GL listing), in GL 3.3:
//!
//! 1. Draw the opaque world as usual (the paths' own passes, before this).
//! 2. Accumulate. Clear the accumulation target: colour to (0, 0, 0, 1)
//!    (sum 0, revealage 1), the weight to 0. Draw every transparent
//!    fragment, in any order, with depth writes off and tested against the
//!    opaque depth (the shader reads it: the target has no depth of its
//!    own), blended with glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO,
//!    GL_ONE_MINUS_SRC_ALPHA):
//!    accum.rgb += C alpha w(z, alpha), accum.a *= (1 - alpha), weight += alpha w.
//!    The paper blends its two targets with glBlendFunci, which is GL 4.0;
//!    in 3.3 one blend function serves both, so the sum of weights goes to a
//!    second target's red channel and the revealage to the first's alpha.
//! 3. Composite: a full-screen triangle over the opaque image,
//!    glBlendFunc(GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA) with
//!    (sum / weights, revealage): C = avg x (1 - revealage) + C_dest x revealage.
//!
//! Exact for one layer; for several, the colour is a weighted average, not
//! the over operator: right when the layers are alike, wrong by how much
//! the weights misjudge which layer is in front
//! (docs/blending/order_independent_transparency.md gives the measured error).
//!
//! GL state: blending, depth writes and culling as above, the colour mask
//! (the image stays opaque); restores all.

use super::transparent_draws::{
    self as draws, begin_composite, bind, end_composite, opaque_depth, transparent_items, unbind,
};
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Transparency;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const WEIGHTED_BLENDED: Technique = Technique {
    name: "weighted_blended",
    notes: "McGuire and Bavoil 2013, Weighted Blended Order-Independent Transparency (beyond the notes; notes 01 §6.1 sorts)",
    file: file!(),
    shaders: &[
        "blending/transparency.vert",
        "blending/weighted_blended.frag",
        "blending/weighted_blended_composite.frag",
    ],
    scene: "scenes/oit.toml",
    docs: "docs/blending/order_independent_transparency.md",
    knobs: &[&knobs::TRANSPARENCY, &knobs::AMBIENT],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The accumulation target: sum and revealage, and the sum of weights.
pub const OIT_ACCUMULATION: &str = "oit_accumulation";

fn runs(scene: &Scene) -> bool {
    scene.render.transparency == Transparency::WeightedBlended
        && scene.objects.len() > scene.opaque_objects()
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !runs(scene) {
        return vec![];
    }
    let n = scene.objects.len() - scene.opaque_objects();
    let world = world_target(scene);
    vec![
        Pass::new(
            "oit_accumulate",
            OIT_ACCUMULATION,
            format!(
                "{n} transparent objects in any order, GL_ONE, GL_ONE / GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, depth writes off"
            ),
            file!(),
        )
        .reading(&[world])
        .without_depth(),
        Pass::new(
            "oit_composite",
            world,
            "full-screen triangle, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA".into(),
            file!(),
        )
        .reading(&[OIT_ACCUMULATION])
        .step(1),
    ]
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene) {
        return vec![];
    }
    // 32-bit floats: 64 layers of weights up to 3e3 pass half floats' 65504.
    vec![TargetDesc {
        name: OIT_ACCUMULATION,
        samples: 1,
        colors: vec![("accum", glow::RGBA32F), ("weight", glow::R32F)],
        depth: Depth::None,
        ping_pong: false,
        mips: None,
        downscale: 1,
    }]
}

struct WeightedBlended {
    accumulate: Program,
    composite: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let accumulate = p.build(&[
        (glow::VERTEX_SHADER, "blending/transparency.vert"),
        (glow::FRAGMENT_SHADER, "blending/weighted_blended.frag"),
    ])?;
    accumulate.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&accumulate);
    let composite = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (
            glow::FRAGMENT_SHADER,
            "blending/weighted_blended_composite.frag",
        ),
    ])?;
    Ok(Box::new(WeightedBlended {
        accumulate,
        composite,
    }))
}

impl RunPasses for WeightedBlended {
    fn run(&self, pass: &Pass, f: &Frame) {
        match pass.step {
            0 => self.accumulate(f),
            _ => self.composite(f),
        }
    }
}

impl WeightedBlended {
    /// Step 2: every transparent fragment into the sums.
    fn accumulate(&self, f: &Frame) {
        let (gl, p) = (f.gl, &self.accumulate);
        let target = f.targets.get(OIT_ACCUMULATION);
        let items = transparent_items(f);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.clear_buffer_f32_slice(glow::COLOR, 0, &[0.0, 0.0, 0.0, 1.0]);
            gl.clear_buffer_f32_slice(glow::COLOR, 1, &[0.0, 0.0, 0.0, 0.0]);
            gl.depth_mask(false);
            gl.enable(glow::BLEND);
            gl.blend_func_separate(glow::ONE, glow::ONE, glow::ZERO, glow::ONE_MINUS_SRC_ALPHA);
            draws::set_up(f, p);
            bind(
                f,
                p,
                "u_opaque_depth",
                unit::OIT_OPAQUE_DEPTH,
                opaque_depth(f),
            );
            draws::draw(f, p, &items);
            unbind(f, unit::OIT_OPAQUE_DEPTH);
            draws::restore(f);
            gl.blend_func(glow::ONE, glow::ZERO);
            gl.disable(glow::BLEND);
            gl.depth_mask(true);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }

    /// Step 3: the weighted average over the opaque image.
    fn composite(&self, f: &Frame) {
        let (gl, p) = (f.gl, &self.composite);
        let sums = f.targets.get(OIT_ACCUMULATION);
        unsafe {
            begin_composite(f, glow::ONE_MINUS_SRC_ALPHA, glow::SRC_ALPHA);
            p.use_program();
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            bind(f, p, "u_accum", unit::OIT_FIRST, Some(sums.colors[0].id));
            bind(f, p, "u_weight", unit::OIT_SECOND, Some(sums.colors[1].id));
            f.meshes.fullscreen.draw();
            unbind(f, unit::OIT_FIRST);
            unbind(f, unit::OIT_SECOND);
            gl.use_program(None);
            end_composite(gl);
        }
    }
}
