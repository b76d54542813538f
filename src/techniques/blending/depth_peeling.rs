//! Depth peeling: Everitt 2001, "Interactive Order-Independent
//! Transparency" (NVIDIA). Chosen with `render.transparency =
//! "depth_peeling"` and `render.peel_layers` = n in place of the sorted pass
//! (transparency.rs); the exact per-fragment reference the others are
//! measured against.
//!
//! Everitt's steps, for layer k = 0, 1, .., n-1:
//!
//! 1. Peel: draw every transparent object with an ordinary depth test
//!    (GL_LESS, depth writes on, cleared to the far plane), so the nearest
//!    fragment wins, plus a second depth test against the layer before:
//!    only fragments behind layer k-1's depth pass. Everitt makes that
//!    second test with a shadow-map comparison; GL 3.3 lets the fragment
//!    shader read layer k-1's depth (an R32F texture, the exact float) and
//!    discard. The opaque world's depth hides what lies behind it the same
//!    way. Two peel targets take turns: one is read while the other is drawn.
//! 2. Blend the layer. Everitt stores the layers and blends them back to
//!    front; gloss blends each layer as it is peeled, front to back, under
//!    the layers before it (premultiplied colour,
//!    glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_ONE)), which gives the same over
//!    operator with one layer texture instead of n.
//!
//! 3. Composite the accumulated layers over the opaque image:
//!    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA).
//!
//! Exact when n covers the deepest pixel's fragments; fragments past layer
//! n are dropped. Each layer is one draw of every transparent object: the
//! cost grows with n.
//!
//! GL state: depth test and writes, blending, the colour mask; restores all.

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
use crate::scene::{Scene, Transparency, knobs};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const DEPTH_PEELING: Technique = Technique {
    name: "depth_peeling",
    notes: "Everitt 2001, Interactive Order-Independent Transparency (beyond the notes; notes 01 §6.1 sorts)",
    file: file!(),
    shaders: &[
        "blending/transparency.vert",
        "blending/depth_peeling.frag",
        "blending/depth_peeling_composite.frag",
    ],
    scene: "scenes/oit-depth-peeling.toml",
    docs: "docs/blending/order_independent_transparency.md",
    knobs: &[&knobs::TRANSPARENCY, &knobs::PEEL_LAYERS, &knobs::AMBIENT],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The two peel targets (a layer's colour and depth), taking turns.
pub const PEEL: [&str; 2] = ["peel_even", "peel_odd"];
/// The layers blended so far, front to back.
pub const PEELED_LAYERS: &str = "peeled_layers";

fn runs(scene: &Scene) -> bool {
    scene.render.transparency == Transparency::DepthPeeling
        && scene.objects.len() > scene.opaque_objects()
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !runs(scene) {
        return vec![];
    }
    let n = scene.objects.len() - scene.opaque_objects();
    let layers = scene.render.peel_layers;
    let world = world_target(scene);
    vec![
        Pass::new(
            "peel_layers",
            PEELED_LAYERS,
            format!(
                "{layers} layers x {n} transparent objects, GL_LESS + the previous layer's depth; each layer under the others (GL_ONE_MINUS_DST_ALPHA, GL_ONE)"
            ),
            file!(),
        )
        .reading(&[world])
        .without_depth(),
        Pass::new(
            "peel_composite",
            world,
            "full-screen triangle, GL_ONE, GL_ONE_MINUS_SRC_ALPHA".into(),
            file!(),
        )
        .reading(&[PEELED_LAYERS])
        .step(1),
    ]
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene) {
        return vec![];
    }
    let target = |name, colors, depth| TargetDesc {
        name,
        samples: 1,
        colors,
        depth,
        ping_pong: false,
        mips: None,
        downscale: 1,
    };
    // Float colour so that blending n layers rounds once, at the end; a
    // 32-bit float depth so that a layer's depth compares exactly.
    let peel = |name| {
        target(
            name,
            vec![("layer", glow::RGBA32F), ("depth", glow::R32F)],
            Depth::Own(glow::DEPTH32F_STENCIL8),
        )
    };
    vec![
        peel(PEEL[0]),
        peel(PEEL[1]),
        target(PEELED_LAYERS, vec![("color", glow::RGBA32F)], Depth::None),
    ]
}

struct DepthPeeling {
    peel: Program,
    blend: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let peel = p.build(&[
        (glow::VERTEX_SHADER, "blending/transparency.vert"),
        (glow::FRAGMENT_SHADER, "blending/depth_peeling.frag"),
    ])?;
    peel.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&peel);
    let blend = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (
            glow::FRAGMENT_SHADER,
            "blending/depth_peeling_composite.frag",
        ),
    ])?;
    Ok(Box::new(DepthPeeling { peel, blend }))
}

impl RunPasses for DepthPeeling {
    fn run(&self, pass: &Pass, f: &Frame) {
        match pass.step {
            0 => self.peel_layers(f),
            _ => self.composite(f),
        }
    }
}

impl DepthPeeling {
    fn peel_layers(&self, f: &Frame) {
        let gl = f.gl;
        let items = transparent_items(f);
        let layers = f.targets.get(PEELED_LAYERS);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(layers.id));
            gl.clear_buffer_f32_slice(glow::COLOR, 0, &[0.0; 4]);
            for k in 0..f.scene.render.peel_layers as usize {
                let (this, before) = (f.targets.get(PEEL[k % 2]), f.targets.get(PEEL[1 - k % 2]));
                // 1. Peel layer k.
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(this.id));
                let (x, y, w, h) = f.view.rect(this.width, this.height);
                gl.viewport(x, y, w, h);
                gl.clear_buffer_f32_slice(glow::COLOR, 0, &[0.0; 4]);
                // No fragment in this layer: nothing lies behind it either.
                gl.clear_buffer_f32_slice(glow::COLOR, 1, &[1.0, 0.0, 0.0, 0.0]);
                gl.clear_buffer_f32_slice(glow::DEPTH, 0, &[1.0]);
                gl.enable(glow::DEPTH_TEST);
                gl.depth_func(glow::LESS);
                gl.depth_mask(true);
                let p = &self.peel;
                draws::set_up(f, p);
                bind(
                    f,
                    p,
                    "u_opaque_depth",
                    unit::OIT_OPAQUE_DEPTH,
                    opaque_depth(f),
                );
                bind(
                    f,
                    p,
                    "u_previous_depth",
                    unit::OIT_SECOND,
                    Some(before.colors[1].id),
                );
                p.set_bool("u_first_layer", k == 0);
                draws::draw(f, p, &items);
                unbind(f, unit::OIT_OPAQUE_DEPTH);
                unbind(f, unit::OIT_SECOND);
                draws::restore(f);
                gl.disable(glow::DEPTH_TEST);
                // 2. Blend it under the layers before it.
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(layers.id));
                gl.enable(glow::BLEND);
                gl.blend_func(glow::ONE_MINUS_DST_ALPHA, glow::ONE);
                self.draw_layer(f, this.colors[0].id);
                gl.blend_func(glow::ONE, glow::ZERO);
                gl.disable(glow::BLEND);
            }
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }

    /// A full-screen triangle that reads `layer`.
    fn draw_layer(&self, f: &Frame, layer: glow::Texture) {
        let p = &self.blend;
        p.use_program();
        p.set_mat4("u_mvp", &Mat4::IDENTITY);
        unsafe {
            bind(f, p, "u_layer", unit::OIT_FIRST, Some(layer));
            f.meshes.fullscreen.draw();
            unbind(f, unit::OIT_FIRST);
            f.gl.use_program(None);
        }
    }

    /// 3. The peeled layers over the opaque image.
    fn composite(&self, f: &Frame) {
        let layers = f.targets.get(PEELED_LAYERS);
        unsafe {
            // Premultiplied "over": the layers' colour plus the world's
            // behind them by one minus their alpha.
            begin_composite(f, glow::ONE, glow::ONE_MINUS_SRC_ALPHA);
            self.draw_layer(f, layers.colors[0].id);
            end_composite(f.gl);
        }
    }
}
