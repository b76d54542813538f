//! Area lights with linearly transformed cosines on the G-buffer paths
//! (Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//! with Linearly Transformed Cosines", §5 polygonal-light shading; the
//! forward pass's half is src/techniques/lighting/ltc_area_lights.rs).
//!
//! A deferred lighting pass: after the lighting pass, before the pass that
//! makes the final image, one full-screen triangle reads each pixel's
//! surface back from the G-buffer (position from depth, normal, and the
//! material: Phong shininess or the microfacet triple, either normal
//! encoding) and adds what the area lights give it to the light the
//! lighting pass accumulated, with the paper's steps as forward runs them
//! (glsl/lighting/ltc_area_lights.glsl, included by
//! glsl/deferred/ltc_area_lights_deferred.frag):
//!
//! ```text
//! 1. M^-1 from the table at (sqrt(alpha), sqrt(1 - N.V))
//! 2. the corners into the frame (T1, T2, N), clipped to the horizon
//! 3. through M^-1, clipped to the cosine's horizon
//! 4. Lambert's formula: the form factor
//! 5. times the BRDF's magnitude and Fresnel
//! ```
//!
//! Deferred shading, light volumes (stencil or not) and tiled shading: the
//! shaded light, kd D + ks S, into the light accumulation target that the
//! composite reads. The light pre-pass keeps light and material apart: the
//! pass runs between its light pre-pass and its combine
//! (deferred_lighting.rs calls `prepass_pass` and `LightPrepass`), adds
//! the diffuse light D and the specular light S to its two targets, and the
//! combine applies kd and ks as it does to every light's. D and S need only
//! the thin G-buffer: the form factors depend on N, V and the lobe's width,
//! the scale on eta, all stored there. A frame without point lights has no
//! lighting pass: this pass then makes the target and clears it. The
//! lights' rectangles are drawn after the final image, into its depth
//! (lighting/ltc_area_lights.rs).
//!
//! GL state: blending on, glBlendFunc(GL_ONE, GL_ONE), no depth test (the
//! default), the G-buffer on its units and the two LTC tables on units 25
//! and 26 (frame::ltc_area_lights::bind); restores no blending,
//! (GL_ONE, GL_ZERO), nothing bound.

use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::ltc_area_lights::{self, wanted};
use crate::frame::plan::Pass;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::{RenderPath, Scene, knobs};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const LTC_AREA_LIGHTS_DEFERRED: Technique = Technique {
    name: "ltc_area_lights_deferred",
    notes: "beyond the notes: Heitz, Dupuy, Hill and Neubelt 2016, Real-Time Polygonal-Light Shading with Linearly Transformed Cosines",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "deferred/ltc_area_lights_deferred.frag",
        "lighting/ltc_area_lights.glsl",
    ],
    scene: "scenes/area-lights-deferred.toml",
    docs: "docs/deferred/ltc_area_lights_deferred.md",
    knobs: &[&knobs::AREA_LIGHTS],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The paths whose composite reads the light accumulation target.
fn composited(scene: &Scene) -> bool {
    matches!(
        scene.render.path,
        RenderPath::Deferred | RenderPath::Volumes | RenderPath::Tiled
    )
}

const NAME: &str = "area lights (LTC)";

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if !wanted(scene) || !composited(scene) {
        return vec![];
    }
    let draws = format!(
        "1 full-screen triangle, additive: kd D + ks S of {} area lights from the G-buffer",
        scene.area_lights.len()
    );
    vec![
        Pass::new(NAME, LIGHT_ACCUMULATION, draws, file!())
            .without_depth()
            .reading(&[gbuffer::NAME]),
    ]
}

/// The light pre-pass's step (deferred_lighting.rs puts it between its
/// light pre-pass and its combine), or None.
pub fn prepass_pass(scene: &Scene) -> Option<Pass> {
    if !wanted(scene) || scene.render.path != RenderPath::Prepass {
        return None;
    }
    let draws = format!(
        "1 full-screen triangle, additive: the diffuse and the specular light of {} area lights from the thin G-buffer",
        scene.area_lights.len()
    );
    Some(
        Pass::new(NAME, LIGHT_ACCUMULATION, draws, file!())
            .without_depth()
            .reading(&[gbuffer::NAME]),
    )
}

/// With no lights no lighting pass makes the accumulation target: this
/// pass does, as deferred_shading.rs describes it, without depth (the
/// light pre-pass's makes deferred_lighting.rs).
fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if !wanted(scene) || !composited(scene) || !lights.is_empty() {
        return vec![];
    }
    vec![super::deferred_shading::accumulation_target(
        scene,
        Depth::None,
    )]
}

struct LtcAreaLightsDeferred {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(LtcAreaLightsDeferred {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (
                glow::FRAGMENT_SHADER,
                "deferred/ltc_area_lights_deferred.frag",
            ),
        ])?,
    }))
}

impl RunPasses for LtcAreaLightsDeferred {
    fn run(&self, _: &Pass, f: &Frame) {
        add_area_lights(&self.program, f);
    }
}

/// The pass in the light pre-pass: the same shader writing D and S apart.
pub struct LightPrepass {
    program: Program,
}

impl LightPrepass {
    pub fn create(p: &Programs) -> Result<LightPrepass> {
        let stages = [
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (
                glow::FRAGMENT_SHADER,
                "deferred/ltc_area_lights_deferred.frag",
            ),
        ];
        Ok(LightPrepass {
            program: p.build_with(&stages, &[("LIGHT_PREPASS", "1".into())])?,
        })
    }

    pub fn run(&self, f: &Frame) {
        add_area_lights(&self.program, f);
    }
}

/// The pass: the area lights' light added to the accumulation target.
fn add_area_lights(p: &Program, f: &Frame) {
    let (gl, u) = (f.gl, f.uniforms);
    let target = f.targets.get(LIGHT_ACCUMULATION);
    let tables = f.draws.ltc.as_ref();
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
        let (x, y, w, h) = f.view.rect(target.width, target.height);
        gl.viewport(x, y, w, h);
        // No lighting pass cleared it: the area lights are all the light.
        if f.lights.is_empty() {
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear(glow::COLOR_BUFFER_BIT);
        }
        // Added to the light the lighting passes accumulated.
        gl.enable(glow::BLEND);
        gl.blend_func(glow::ONE, glow::ONE);

        p.use_program();
        gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
        p.set_mat4("u_mvp", &Mat4::IDENTITY);
        ltc_area_lights::bind(gl, p, f.scene, tables);
        f.meshes.fullscreen.draw();

        // Restore the state this pass changed.
        ltc_area_lights::unbind(gl, tables);
        gbuffer::unbind(gl);
        gl.use_program(None);
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::BLEND);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}
