//! The composite pass (notes 01 §8.6.2 step 3 "Generate Final Image"): one
//! screen-sized triangle that adds the ambient term (ambient x albedo from
//! the G-buffer) to the light the lighting pass accumulated, and encodes the
//! result for the output. Background pixels (depth 1) get the background
//! colour. Ends deferred shading and light volumes; the light pre-pass has
//! its own combine pass (deferred_lighting.rs).
//!
//! It also copies the G-buffer's depth into the output (gl_FragDepth), so
//! that what draws after it can test against the scene. For a view drawn
//! into a mirror (stencil/mirror.rs) it writes only inside the mirror's
//! stencil region, and only where nothing nearer is there already.
//!
//! Where the output allows (an 8-bit output with no post chain,
//! `render.hardware_srgb`: src/frame/plan.rs `hardware_srgb`), the output
//! is SRGB8_ALPHA8 and GL_FRAMEBUFFER_SRGB is on while the composite draws:
//! the shader writes linear light and GL encodes it, instead of pow() per
//! pixel. Elsewhere (a post chain's linear HDR target, the RGBA32F output of
//! error measurements, `render.hardware_srgb = false`) the shader encodes.
//!
//! GL state: with a depth buffer in the output, depth test GL_ALWAYS (one
//! triangle covers every pixel exactly once, notes 02), or GL_LEQUAL and the
//! stencil test for a reflected view; without one (nothing after the
//! composite tests depth, `gloss plan` shows it), no depth test and a
//! shader that writes colour only;
//! textures on the G-buffer units and unit::LIGHT, unbound after (and, with
//! render.ibl, image-based lighting's maps with GL_TEXTURE_CUBE_MAP_SEAMLESS
//! on); GL_FRAMEBUFFER_SRGB on an SRGB8_ALPHA8 output; restores no depth or
//! stencil test, GL_LESS, no seamless filtering, no GL_FRAMEBUFFER_SRGB.

use crate::frame::gbuffer;
use crate::frame::image_based_lighting;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::plan_programs::CompositeNeeds;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::{LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::technique::LaterPrograms;
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;
use std::cell::OnceCell;

pub const COMPOSITE: Technique = Technique {
    name: "composite",
    notes: "notes 01 §8.6.2 step 3, Generate Final Image",
    file: file!(),
    shaders: &["common/fullscreen.vert", "deferred/composite.frag"],
    scene: "scenes/deferred-shading.toml",
    docs: "docs/deferred/composite.md",
    knobs: &[&knobs::AMBIENT, &knobs::BACKGROUND, &knobs::HARDWARE_SRGB],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    // What it reads: the G-buffer, the accumulated light, the ambient occlusion.
    let reads: Vec<&'static str> = [Some(gbuffer::NAME), Some(LIGHT_ACCUMULATION)]
        .into_iter()
        .chain([super::ambient_light::result_target(scene)])
        .flatten()
        .collect();
    match scene.render.path {
        RenderPath::Deferred | RenderPath::Volumes | RenderPath::Tiled => vec![
            Pass::new(
                "composite",
                world_target(scene),
                format!(
                    "1 full-screen triangle ({}, {})",
                    match super::ambient_light::result_target(scene) {
                        Some(_) => "ambient x albedo x AO + light",
                        None => "ambient x albedo + light",
                    },
                    if crate::frame::plan::hardware_srgb(scene) {
                        "sRGB encode by GL_FRAMEBUFFER_SRGB"
                    } else if scene.post.is_empty() {
                        "sRGB encode"
                    } else {
                        "linear: a post chain follows"
                    }
                ),
                file!(),
            )
            .without_depth()
            .reading(&reads)
            .with_composite(scene_needs(scene, image_based_lighting::wanted(scene))),
        ],
        RenderPath::Forward | RenderPath::Prepass => vec![],
    }
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

/// The composite's shaders.
const STAGES: [(u32, &str); 2] = [
    (glow::VERTEX_SHADER, "common/fullscreen.vert"),
    (glow::FRAGMENT_SHADER, "deferred/composite.frag"),
];

struct Composite {
    build: LaterPrograms,
    /// The programs, by `CompositeNeeds::index`, each built the first frame that needs
    /// it (a scene's frames need one or two of the eight): writing the
    /// G-buffer's depth into the output (gl_FragDepth, for the passes that
    /// draw after it) or colour only (the output has no depth buffer:
    /// nothing after the composite tests depth; a shader that writes
    /// gl_FragDepth costs more per pixel even when its depth goes nowhere);
    /// tinting each pixel by its cascade (shadow.cascade_colors) or not;
    /// writing linear light for GL to encode (HARDWARE_SRGB) or encoding
    /// in the shader.
    /// And with or without the image-based lighting, ambient occlusion and
    /// emission code (NO_IBL, NO_AMBIENT_OCCLUSION, NO_EMISSION where the
    /// frame has none: 8 x 8 programs).
    programs: [OnceCell<Program>; 64],
}

/// The composite's needs in `scene` but its target's (which the plan and
/// the frame each complete with `CompositeNeeds::at_output`): cascade
/// tints, and the ambient term's parts (all of them with render.specialize
/// off); `ibl`: the frame has image-based lighting's maps.
fn scene_needs(scene: &Scene, ibl: bool) -> CompositeNeeds {
    let general = !scene.render.specialize;
    CompositeNeeds {
        depth: false,
        tints: shadows::cascade_tints(scene),
        hardware: false,
        ibl: general || ibl,
        ambient_occlusion: general || super::ambient_light::result_target(scene).is_some(),
        emission: gbuffer::MaterialVariant::of(scene).emission,
    }
}

/// The variant `f` needs: `scene_needs`, with depth written where its
/// output has a depth buffer and sRGB by GL where the output is sRGB.
fn needs(f: &Frame) -> CompositeNeeds {
    let output = f.targets.get(world_target(f.scene));
    let depth = output.depth_stencil.is_some() || output.shared_depth.is_some();
    let srgb = output.colors[0].internal_format == glow::SRGB8_ALPHA8;
    let ibl = f.draws.environment.ibl.is_some();
    scene_needs(f.scene, ibl).at_output(depth, srgb, f.uniforms.output_srgb)
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Composite {
        build: p.later(),
        programs: std::array::from_fn(|_| OnceCell::new()),
    }))
}

impl Composite {
    /// The program for `n`, built now if no frame has needed it yet.
    fn program(&self, n: CompositeNeeds) -> Result<&Program> {
        let i = n.index();
        if let Some(p) = self.programs[i].get() {
            return Ok(p);
        }
        let tints = n.tints;
        let defines = n.defines();
        let program = self.build.build_with(&STAGES, &defines)?;
        if tints {
            program.bind_uniform_block("Cascades", shadows::CASCADES_BINDING);
        }
        Ok(self.programs[i].get_or_init(|| program))
    }
}

impl RunPasses for Composite {
    fn prepare(&self, _: &Pass, f: &Frame) -> Result<()> {
        self.program(needs(f)).map(|_| ())
    }

    fn run(&self, _: &Pass, f: &Frame) {
        let output = f.targets.get(world_target(f.scene));
        let n = needs(f);
        let (depth, tints, hardware) = (n.depth, n.tints, n.hardware);
        let (gl, u) = (f.gl, f.uniforms);
        // Built by `prepare`, which the renderer calls first.
        let p = match self.program(n) {
            Ok(p) => p,
            Err(e) => return eprintln!("warning: the composite did not run: {e:#}"),
        };
        // A frame with no lights has no lighting pass and no light to add.
        let light = f.targets.find(LIGHT_ACCUMULATION);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);
            if depth {
                gl.enable(glow::DEPTH_TEST);
                gl.depth_mask(true);
                if f.view.clears {
                    gl.depth_func(glow::ALWAYS);
                } else {
                    gl.depth_func(glow::LEQUAL);
                }
            }
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if hardware {
                gl.enable(glow::FRAMEBUFFER_SRGB);
            }
            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            gl.active_texture(glow::TEXTURE0 + unit::LIGHT);
            gl.bind_texture(glow::TEXTURE_2D, light.map(|t| t.colors[0].id));
            gl.active_texture(glow::TEXTURE0);
            p.set_i32("u_light", unit::LIGHT as i32);
            p.set_bool("u_has_light", light.is_some());
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_vec3("u_ambient", f.scene.render.ambient);
            super::ambient_light::bind_result(f, p);
            // Image-based lighting's maps: the ambient term with render.ibl.
            let ibl = f.draws.environment.ibl.as_ref();
            if ibl.is_some() {
                gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            }
            image_based_lighting::bind(gl, p, ibl);
            p.set_vec3("u_background", f.scene.render.background);
            p.set_bool("u_output_srgb", u.output_srgb && !hardware);
            if tints {
                f.shadows.bind_cascade_block(gl, true);
            }
            f.meshes.fullscreen.draw();

            if tints {
                f.shadows.bind_cascade_block(gl, false);
            }
            super::ambient_light::unbind_result(gl);
            image_based_lighting::unbind(gl, ibl);
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            gl.active_texture(glow::TEXTURE0 + unit::LIGHT);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gbuffer::unbind(gl);
            gl.use_program(None);
            gl.disable(glow::FRAMEBUFFER_SRGB);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
