//! Light volumes (notes 04 "Light Volumes"; notes 01 §8.6.1).
//!
//! Deferred shading still shades every pixel for every light, although the
//! attenuation makes most lights negligible at most pixels. Rasterisation is
//! the conditional: draw, per light, a mesh that encloses the region the light
//! reaches, and shade only the pixels it covers.
//!
//! 1. The radius: where the attenuated light falls to `cutoff` (5/256) of the
//!    light's brightest channel (src/frame/lights.rs, once per light, with
//!    the stable root of src/lighting/attenuation.rs).
//! 2. A point light draws a sphere scaled to that radius; a spot light a cone
//!    turned to its direction and scaled to its range and outer angle.
//! 3. uv = gl_FragCoord.xy / textureSize (glsl/common/gbuffer_read.glsl).
//! 4. glCullFace(GL_FRONT): draw the back faces, so the volume still lights
//!    when the camera is inside it.
//! 5. glDepthMask(GL_FALSE); glEnable(GL_BLEND); glBlendFunc(GL_ONE, GL_ONE)
//!    on a black clear, into an RGBA16F target so many lights do not saturate.
//! 6. Only surfaces inside the volume are shaded: the back faces are depth
//!    tested with GL_GEQUAL against the scene's depth (the surface is in front
//!    of the back face), and the shader discards what lies beyond the radius
//!    (surfaces in front of the volume). GL_DEPTH_CLAMP keeps back faces that
//!    reach past the far plane. The scene's depth is a copy of the G-buffer's
//!    (glBlitFramebuffer), because the shader samples the G-buffer's own.
//! 7. Then the lights with no volume: a directional light (or one whose
//!    attenuation never reaches the cutoff) is a full-screen triangle with
//!    an identity MVP ("mvp is simple identity pass through").
//!
//! The two-sided stencil variant is stencil_light_volumes.rs (notes 05).
//!
//! GL state: front-face culling, depth writes off, GL_GEQUAL, depth clamp,
//! additive blending; each step restores what it set.

use crate::frame::gbuffer;
use crate::frame::lights::{FrameLights, Volume};
use crate::frame::plan::Pass;
use crate::frame::shadows;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::uniforms::LIGHTS_BINDING;
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{LightKind, RenderPath, Scene};
use crate::techniques::deferred::deferred_shading::accumulation_target;
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const LIGHT_VOLUMES: Technique = Technique {
    name: "light_volumes",
    notes: "notes 04, Light Volumes; notes 01 §8.6.1",
    file: file!(),
    shaders: &["deferred/light_volumes.vert", "deferred/light_volumes.frag"],
    scene: "scenes/mixed-lights.toml",
    docs: "docs/deferred/light_volumes.md",
    knobs: &[
        &knobs::CUTOFF,
        &knobs::STENCIL_VOLUMES,
        &knobs::ACCUMULATION,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn runs(scene: &Scene, lights: &FrameLights) -> bool {
    scene.render.path == RenderPath::Volumes && !scene.render.stencil_volumes && !lights.is_empty()
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if !runs(scene, lights) {
        return vec![];
    }
    let draws = format!(
        "{}, front faces culled, additive",
        describe_volumes(scene, lights)
    );
    let variant = LightingVariant::of(scene, lights).describe();
    vec![
        Pass::new("lighting", LIGHT_ACCUMULATION, draws, file!())
            .reading(reads(scene))
            .with_variant(variant),
    ]
}

/// What the volumes' shader samples: the G-buffer, and the shadow maps
/// when a light casts.
pub fn reads(scene: &Scene) -> &'static [&'static str] {
    if scene.lights.iter().any(|l| l.shadow.is_some()) {
        &[gbuffer::NAME, "shadow map"]
    } else {
        &[gbuffer::NAME]
    }
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene, lights) {
        return vec![];
    }
    vec![accumulation_target(
        scene,
        Depth::Own(gbuffer::depth_format(scene)),
    )]
}

/// "2 spheres + 3 cones + 1 full-screen triangles (1 with no finite radius)".
pub fn describe_volumes(scene: &Scene, lights: &FrameLights) -> String {
    let (spheres, cones, full) = lights.count_volumes();
    let unbounded = scene
        .lights
        .iter()
        .zip(&lights.lights)
        .filter(|(l, f)| l.kind != LightKind::Directional && f.volume == Volume::FullScreen)
        .count();
    let mut parts = Vec::new();
    if spheres > 0 {
        parts.push(format!("{spheres} spheres"));
    }
    if cones > 0 {
        parts.push(format!("{cones} cones"));
    }
    if full > 0 {
        parts.push(format!("{full} full-screen triangles"));
    }
    if unbounded > 0 {
        parts.push(format!("({unbounded} with no finite radius)"));
    }
    parts.join(" + ")
}

struct LightVolumes {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(LightVolumes {
        program: volume_program(p)?,
    }))
}

/// The light-volume shading program (also the stencil variant's),
/// specialised to the frame (src/frame/variant.rs).
pub fn volume_program(p: &Programs) -> Result<Program> {
    let program = p.build_variant(&[
        (glow::VERTEX_SHADER, "deferred/light_volumes.vert"),
        (glow::FRAGMENT_SHADER, "deferred/light_volumes.frag"),
    ])?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    Ok(program)
}

impl RunPasses for LightVolumes {
    fn run(&self, _: &Pass, f: &Frame) {
        volume_pass(f, &self.program, draw_bounded_volumes);
    }
}

/// The lighting pass with program `p`: the bounded lights' volumes drawn by
/// `draw_volumes`, additive, into the light accumulation target; then the
/// lights that have no volume. The stencil variant passes its own
/// `draw_volumes`; the light pre-pass (deferred_lighting.rs) its own shader.
pub fn volume_pass(f: &Frame, p: &Program, draw_volumes: fn(&Frame, &Program)) {
    let gl = f.gl;
    let gbuf = f.targets.get(gbuffer::NAME);
    let target = f.targets.get(LIGHT_ACCUMULATION);
    copy_depth(gl, gbuf, target);
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
        let (x, y, w, h) = f.view.rect(target.width, target.height);
        gl.viewport(x, y, w, h);
        // Light adds up on black.
        gl.clear_color(0.0, 0.0, 0.0, 0.0);
        gl.clear(glow::COLOR_BUFFER_BIT);
        p.use_program();
        gbuffer::bind_for_reading(gl, p, gbuf, f.uniforms);
        gl.bind_buffer_base(
            glow::UNIFORM_BUFFER,
            LIGHTS_BINDING,
            Some(f.uniforms.lights_ubo),
        );
        f.shadows.bind(gl);
    }
    draw_volumes(f, p);
    draw_full_screen_lights(f, p);
    unsafe {
        gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
        f.shadows.unbind(gl);
        gbuffer::unbind(gl);
        gl.use_program(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}

/// Copy the G-buffer's depth (and its stencil, cleared to 0 by the G-buffer
/// pass, when it has one) into `target`'s own depth buffer: the volumes are
/// tested against the copy while the shader reads the original.
pub fn copy_depth(gl: &glow::Context, gbuf: &Framebuffer, target: &Framebuffer) {
    let (w, h) = (gbuf.width, gbuf.height);
    let format = gbuf.depth_stencil.as_ref().map(|d| d.internal_format);
    let mask = if format.is_some_and(gbuffer::has_stencil) {
        glow::DEPTH_BUFFER_BIT | glow::STENCIL_BUFFER_BIT
    } else {
        glow::DEPTH_BUFFER_BIT
    };
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(gbuf.id));
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(target.id));
        gl.blit_framebuffer(0, 0, w, h, 0, 0, w, h, mask, glow::NEAREST);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
    }
}

/// Steps 2-6: each bounded light's sphere or cone, back faces only, where
/// the scene lies in front of the back face (program `p` in use, its target
/// bound). Leaves the state as it found it.
pub fn draw_bounded_volumes(f: &Frame, p: &Program) {
    let gl = f.gl;
    unsafe {
        gl.enable(glow::CULL_FACE);
        gl.cull_face(glow::FRONT);
        // A reflected view turns the volumes' winding over.
        gl.front_face(f.view.front_face(false));
        gl.depth_mask(false);
        gl.enable(glow::BLEND);
        gl.blend_func(glow::ONE, glow::ONE);
        gl.enable(glow::DEPTH_TEST);
        gl.depth_func(glow::GEQUAL);
        gl.enable(glow::DEPTH_CLAMP);
    }
    for (i, light) in f.lights.lights.iter().enumerate() {
        let (mesh, model) = match light.volume {
            Volume::Sphere(m) => (&f.meshes.volume_sphere, m),
            Volume::Cone(m) => (&f.meshes.volume_cone, m),
            Volume::FullScreen => continue,
        };
        p.set_i32("u_light_id", i as i32);
        p.set_mat4("u_mvp", &(f.uniforms.view_projection * model));
        mesh.draw();
    }
    unsafe {
        gl.disable(glow::DEPTH_CLAMP);
        gl.depth_func(glow::LESS);
        gl.disable(glow::DEPTH_TEST);
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::BLEND);
        gl.depth_mask(true);
        gl.front_face(glow::CCW);
        gl.cull_face(glow::BACK);
        gl.disable(glow::CULL_FACE);
    }
}

/// Step 7: each light without a volume as one full-screen triangle, no depth
/// test, additive (program `p` in use, its target bound).
pub fn draw_full_screen_lights(f: &Frame, p: &Program) {
    let gl = f.gl;
    unsafe {
        gl.enable(glow::BLEND);
        gl.blend_func(glow::ONE, glow::ONE);
    }
    // "mvp is simple identity pass through".
    p.set_mat4("u_mvp", &Mat4::IDENTITY);
    for (i, light) in f.lights.lights.iter().enumerate() {
        if light.volume == Volume::FullScreen {
            p.set_i32("u_light_id", i as i32);
            f.meshes.fullscreen.draw();
        }
    }
    unsafe {
        gl.blend_func(glow::ONE, glow::ZERO);
        gl.disable(glow::BLEND);
    }
}
