//! The separable blur, a stage of the post chain (notes 01 §9: "effects that
//! depend on multiple fragments (e.g. blur) are now possible"; notes 03,
//! "Blur Pass": "a horizon blur pass and a vertical blur pass"). A 2D
//! Gaussian is the product of two 1D ones, so a blur of radius r costs
//! 2 (2r + 1) reads a pixel instead of (2r + 1)²: step 1 blurs the rows into
//! one image, step 2 the columns of that image into the next.
//!
//! The weights are `math::gaussian::Kernel` (f64, normalised to sum 1), or
//! equal for the box blur kept for comparison. With `taps = "linear"` one
//! bilinear fetch between two texels reads both with their two weights
//! (`math::gaussian::linear_taps`): r + 1 fetches instead of 2r + 1.
//!
//! GL state: a sampler object on unit::POST_INPUT while it draws (clamp to
//! edge; GL_LINEAR for linear taps, GL_NEAREST for direct ones, which then
//! cost one texel read each), unbound after; otherwise the chain's
//! (src/frame/post.rs `run_step`).

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::{self, entries, step_pass};
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::math::gaussian::{Kernel, direct_taps, linear_taps};
use crate::scene::Scene;
use crate::scene::post::{MAX_BLUR_RADIUS, PostPass, Taps};
use anyhow::{Result, anyhow};
use glow::HasContext;

pub const BLUR: Technique = Technique {
    name: "blur",
    notes: "notes 01 §9, Post processing; notes 03, Blur Pass",
    file: file!(),
    shaders: &["common/fullscreen.vert", "post/blur.frag"],
    scene: "scenes/post-blur.toml",
    docs: "docs/post/blur.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::AfterViews,
};

/// The most taps on one side (the centre included) glsl/post/blur.frag takes.
pub const MAX_TAPS: usize = MAX_BLUR_RADIUS as usize + 1;

/// An entry's kernel and how it is read: (kernel, taps, name).
fn kernel(p: &PostPass) -> Option<(Kernel, Taps, String)> {
    match *p {
        PostPass::Blur {
            sigma,
            radius,
            taps,
        } => Some((
            Kernel::gaussian(sigma.into(), radius),
            taps,
            format!(
                "Gaussian sigma {sigma} radius {radius}, {} taps",
                taps.name()
            ),
        )),
        PostPass::Box { radius } => Some((
            Kernel::box_(radius),
            Taps::Direct,
            format!("box radius {radius}"),
        )),
        _ => None,
    }
}

/// The one-sided taps the shader reads: (offset in texels, weight).
pub fn taps(k: &Kernel, taps: Taps) -> Vec<(f32, f32)> {
    let t = match taps {
        Taps::Direct => direct_taps(k),
        Taps::Linear => linear_taps(k),
    };
    t.into_iter().map(|(o, w)| (o as f32, w as f32)).collect()
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let mut v = Vec::new();
    for (i, first, p) in entries(scene) {
        let Some((_, _, name)) = kernel(p) else {
            continue;
        };
        for (step, direction) in [(0, "horizontal"), (1, "vertical")] {
            let s = first + step;
            let what = format!("{name}, {direction}");
            v.push(step_pass(scene, "blur", &what, i, s, file!()).step(step as u32));
        }
    }
    v
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Blur {
    program: Program,
    /// Clamp to edge, whatever the texture's own settings; GL_NEAREST for
    /// direct taps (one texel each, no filtering work), GL_LINEAR for
    /// linear taps.
    nearest: glow::Sampler,
    linear: glow::Sampler,
    gl: crate::gl::Gl,
}

/// A sampler object reading with `filter` and clamping to the edge.
fn sampler(gl: &glow::Context, filter: u32) -> Result<glow::Sampler> {
    unsafe {
        let s = gl
            .create_sampler()
            .map_err(|e| anyhow!("glGenSamplers: {e}"))?;
        gl.sampler_parameter_i32(s, glow::TEXTURE_MIN_FILTER, filter as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_MAG_FILTER, filter as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_WRAP_S, glow::CLAMP_TO_EDGE as i32);
        gl.sampler_parameter_i32(s, glow::TEXTURE_WRAP_T, glow::CLAMP_TO_EDGE as i32);
        Ok(s)
    }
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "post/blur.frag"),
    ])?;
    let gl = p.gl;
    Ok(Box::new(Blur {
        program,
        nearest: sampler(gl, glow::NEAREST)?,
        linear: sampler(gl, glow::LINEAR)?,
        gl: gl.clone(),
    }))
}

impl Drop for Blur {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_sampler(self.nearest);
            self.gl.delete_sampler(self.linear);
        }
    }
}

impl RunPasses for Blur {
    fn run(&self, pass: &Pass, f: &Frame) {
        let (k, how, _) = kernel(&f.scene.post[pass.item]).expect("a blur's entry");
        let taps = taps(&k, how);
        let offsets: Vec<f32> = taps.iter().map(|t| t.0).collect();
        let weights: Vec<f32> = taps.iter().map(|t| t.1).collect();
        let gl = f.gl;
        unsafe {
            let sampler = match how {
                Taps::Direct => self.nearest,
                Taps::Linear => self.linear,
            };
            gl.bind_sampler(unit::POST_INPUT, Some(sampler));
            post::run_step(f, &self.program, pass.value as usize, |p| {
                // Step 0 blurs along the rows, step 1 along the columns.
                let direction = if pass.step == 0 {
                    (1.0, 0.0)
                } else {
                    (0.0, 1.0)
                };
                p.set_vec2("u_direction", direction.into());
                p.set_i32("u_taps", taps.len() as i32);
                p.set_f32_array("u_offset[0]", &offsets);
                p.set_f32_array("u_weight[0]", &weights);
            });
            gl.bind_sampler(unit::POST_INPUT, None);
        }
    }
}
