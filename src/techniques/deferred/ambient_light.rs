//! The ambient light pass (notes 03, "Ambient Light": "the program
//! calculates the ambient occlusion effect by sampling random points within
//! a hemisphere on top of the fragment. If a point is within the geometry,
//! it will be counted as ambient occlusion"): screen-space ambient
//! occlusion, SSAO, on every path with a G-buffer.
//!
//! 1. Ambient occlusion: one full-screen triangle. For each pixel, the
//!    surface point P and normal N from the G-buffer; `samples` directions
//!    of the hemisphere above N (a cosine-weighted kernel,
//!    src/lighting/ambient_occlusion.rs, turned about N by the pixel's entry
//!    of a 4x4 tile of rotations, a texture repeated over the screen); along
//!    each, points at r/4 .. r. A point is inside the geometry when it lies
//!    more than `bias` behind the surface the depth buffer shows at its
//!    pixel, and that surface is within r of it (the range check). AO = the
//!    fraction of directions none of whose points is inside, into an R16F
//!    target (glsl/deferred/ambient_light.frag).
//! 2. Blur (with `blur`): the AO averaged over 4x4 pixels, the tile's size,
//!    only across surfaces alike (glsl/deferred/ambient_light_blur.frag):
//!    the rotation pattern is gone.
//! 3. The ambient term, render.ambient x diffuse albedo, times the AO: the
//!    composite (composite.rs) and the light pre-pass's combine
//!    (deferred_lighting.rs) add it where they always added the ambient
//!    term, reading the AO through `bind_result`. The ambient term is added
//!    once, occluded; without [ambient_occlusion] they add it as before.
//!
//! The forward path has no G-buffer: there is no pass, and the scene's
//! warnings say that [ambient_occlusion] has no effect.
//!
//! GL state: none beyond the framebuffer and the textures (no depth test,
//! no blending: one triangle writes every pixel of the view once); the
//! G-buffer's units and unit::AMBIENT_OCCLUSION are unbound after.

use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::uniforms::unit;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::gl::texture::{Sampling, Texture};
use crate::lighting::ambient_occlusion::{TILE, kernel};
use crate::scene::ambient_occlusion::{self as knobs, AmbientOcclusion, MAX_SAMPLES};
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glam::{Mat4, Vec4};
use glow::HasContext;

pub const AMBIENT_LIGHT: Technique = Technique {
    name: "ambient_light",
    notes: "notes 03, Ambient Light (SSAO)",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "deferred/ambient_light.frag",
        "deferred/ambient_light_blur.frag",
    ],
    scene: "scenes/ambient-occlusion.toml",
    docs: "docs/deferred/ambient_light.md",
    knobs: &[&knobs::SAMPLES, &knobs::RADIUS, &knobs::BIAS, &knobs::BLUR],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The AO estimate, one value a pixel.
pub const AMBIENT_OCCLUSION: &str = "ambient_occlusion";
/// The AO blurred over the rotation tile.
pub const AMBIENT_OCCLUSION_BLURRED: &str = "ambient_occlusion_blurred";

/// The steps of this technique's passes.
const ESTIMATE: u32 = 0;
const BLUR: u32 = 1;

/// The scene's SSAO, where its path has a G-buffer to run it on.
pub fn settings(scene: &Scene) -> Option<AmbientOcclusion> {
    let ao = scene.render.ambient_occlusion?;
    (scene.render.path != RenderPath::Forward).then_some(ao)
}

/// The target the ambient term reads its AO from (None: no AO this frame).
pub fn result_target(scene: &Scene) -> Option<&'static str> {
    settings(scene).map(|ao| {
        if ao.blur {
            AMBIENT_OCCLUSION_BLURRED
        } else {
            AMBIENT_OCCLUSION
        }
    })
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let Some(ao) = settings(scene) else {
        return vec![];
    };
    let draws = format!(
        "1 full-screen triangle: SSAO, {} directions x 4 points within r = {} (bias {}), turned by a 4x4 tile",
        ao.samples, ao.radius, ao.bias
    );
    let mut v = vec![
        Pass::new("ambient light", AMBIENT_OCCLUSION, draws, file!())
            .step(ESTIMATE)
            .reading(&[gbuffer::NAME]),
    ];
    if ao.blur {
        let draws =
            "1 full-screen triangle: 4x4 depth-aware box blur of the AO (the tile's pattern)";
        v.push(
            Pass::new(
                "ambient blur",
                AMBIENT_OCCLUSION_BLURRED,
                draws.into(),
                file!(),
            )
            .step(BLUR)
            .reading(&[AMBIENT_OCCLUSION, gbuffer::NAME]),
        );
    }
    v
}

fn target(name: &'static str) -> TargetDesc {
    TargetDesc {
        name,
        samples: 1,
        colors: vec![("ao", glow::R16F)],
        depth: Depth::None,
        ping_pong: false,
        mips: None,
        downscale: 1,
    }
}

fn targets(scene: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    match settings(scene) {
        None => vec![],
        Some(ao) if ao.blur => vec![target(AMBIENT_OCCLUSION), target(AMBIENT_OCCLUSION_BLURRED)],
        Some(_) => vec![target(AMBIENT_OCCLUSION)],
    }
}

/// Bind the AO the ambient term reads on unit::AMBIENT_OCCLUSION for the
/// program `p` in use (`u_ambient_occlusion`, `u_has_ambient_occlusion`);
/// the composite and the combine call it, and `unbind_result` after.
pub fn bind_result(f: &Frame, p: &Program) {
    let ao = result_target(f.scene).map(|name| f.targets.get(name).colors[0].id);
    unsafe {
        f.gl.active_texture(glow::TEXTURE0 + unit::AMBIENT_OCCLUSION);
        f.gl.bind_texture(glow::TEXTURE_2D, ao);
        f.gl.active_texture(glow::TEXTURE0);
    }
    p.set_i32("u_ambient_occlusion", unit::AMBIENT_OCCLUSION as i32);
    p.set_bool("u_has_ambient_occlusion", ao.is_some());
}

/// Undo `bind_result`'s texture binding.
pub fn unbind_result(gl: &glow::Context) {
    unsafe {
        gl.active_texture(glow::TEXTURE0 + unit::AMBIENT_OCCLUSION);
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.active_texture(glow::TEXTURE0);
    }
}

struct AmbientLight {
    estimate: Program,
    blur: Program,
    /// The 4x4 tile of rotations: texel (x, y) holds (cos, sin) * 0.5 + 0.5
    /// of `TILE[4 y + x]` sixteenths of a turn.
    rotations: Texture,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let estimate = p.build_with(
        &[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "deferred/ambient_light.frag"),
        ],
        &[("MAX_AO_SAMPLES", MAX_SAMPLES.to_string())],
    )?;
    let blur = p.build(&[
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "deferred/ambient_light_blur.frag"),
    ])?;
    let texels: Vec<u8> = TILE
        .iter()
        .flat_map(|&k| {
            let (s, c) = (std::f32::consts::TAU * f32::from(k) / 16.0).sin_cos();
            let byte = |x: f32| ((x * 0.5 + 0.5) * 255.0).round() as u8;
            [byte(c), byte(s), 0, 255]
        })
        .collect();
    let rotations = Texture::from_rgba8(p.gl, 4, 4, &texels, false, Sampling::NEAREST_CLAMP)?;
    Ok(Box::new(AmbientLight {
        estimate,
        blur,
        rotations,
    }))
}

impl RunPasses for AmbientLight {
    fn run(&self, pass: &Pass, f: &Frame) {
        let Some(ao) = settings(f.scene) else { return };
        let (gl, u) = (f.gl, f.uniforms);
        let (p, target, input) = match pass.step {
            ESTIMATE => (&self.estimate, AMBIENT_OCCLUSION, self.rotations.id),
            _ => (
                &self.blur,
                AMBIENT_OCCLUSION_BLURRED,
                f.targets.get(AMBIENT_OCCLUSION).colors[0].id,
            ),
        };
        let output = f.targets.get(target);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);

            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            gl.active_texture(glow::TEXTURE0 + unit::AMBIENT_OCCLUSION);
            gl.bind_texture(glow::TEXTURE_2D, Some(input));
            gl.active_texture(glow::TEXTURE0);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            p.set_f32("u_radius", ao.radius);
            if pass.step == ESTIMATE {
                p.set_i32("u_rotations", unit::AMBIENT_OCCLUSION as i32);
                // The inverse of the matrix the G-buffer's positions are
                // rebuilt with, so that a point projects back to its pixel.
                p.set_mat4("u_view_projection", &u.inverse_view_projection.inverse());
                let k: Vec<Vec4> = (kernel(ao.samples as usize).into_iter())
                    .map(|k| k.extend(0.0))
                    .collect();
                p.set_vec4_array("u_kernel", &k);
                p.set_i32("u_samples", ao.samples as i32);
                p.set_f32("u_bias", ao.bias);
            } else {
                p.set_i32("u_ambient_occlusion", unit::AMBIENT_OCCLUSION as i32);
            }
            f.meshes.fullscreen.draw();

            // Restore what this pass bound.
            gl.active_texture(glow::TEXTURE0 + unit::AMBIENT_OCCLUSION);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gbuffer::unbind(gl);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
