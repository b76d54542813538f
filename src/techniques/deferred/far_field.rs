//! The far field of tiled shading: beyond the notes. Notes 04 ("Calculating
//! radius") stops each light where its brightest channel falls to a cutoff
//! (5/256). Every light's tail beyond that is dropped, and where twenty
//! lights overlap a pixel the dropped tails add up to 108/255
//! (docs/many-lights.md). Lowering the cutoff makes every light reach
//! every pixel, and tiled shading then costs what a single full-screen pass
//! costs.
//!
//! The far field keeps the tails and makes them cheap. Each light with a
//! radius `r` is split by a weight `w(d)`: 1 up to `r/2`, a smoothstep down
//! to 0 at `r`.
//!
//! - Near part, `w(d) x light`: tiled shading shades it per pixel from its
//!   cluster lists, as before.
//! - Far part, `(1 - w(d)) x light`: smooth across a surface, since every
//!   light in it is at least `r/2` away. This pass sums it once per k x k
//!   pixels (`render.far_field = k`): each fragment of a target 1/k of the
//!   frame each way reads the G-buffer at the centre of its block and sums
//!   every light's far part there, diffuse and specular apart
//!   (glsl/deferred/far_field.frag).
//! - Tiled shading interpolates the samples bilinearly and multiplies by
//!   each pixel's own material (glsl/common/far_field.glsl). This needs
//!   all four samples around a pixel to lie on its surface: on its tangent
//!   plane, normals within a fraction of a degree, the same shininess, within `reach`.
//!   Otherwise (edges, curved surfaces, the background) the pixel sums the
//!   far part itself, exactly.
//!
//! The two parts add up to each light's whole contribution, so no light is
//! cut off. The only approximation is the interpolation on smooth surfaces.
//! With k = 1 every sample is the pixel itself and the image is forward
//! rendering's (tests/deferred/far_field.rs).
//!
//! GL state: no depth test, depth writes off, two colour attachments;
//! restores depth writes.

use crate::frame::gbuffer;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::shadows;
use crate::frame::targets::{Depth, TargetDesc, scaled_size};
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::{RenderPath, Scene};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

pub const FAR_FIELD: Technique = Technique {
    name: "far_field",
    notes: "beyond the notes: the lights' tails past notes 04's cutoff radius, summed at low resolution",
    file: file!(),
    shaders: &[
        "common/fullscreen.vert",
        "deferred/far_field.frag",
        "common/far_field.glsl",
        "common/far_field_sh.glsl",
    ],
    scene: "scenes/far-field.toml",
    docs: "docs/deferred/far_field.md",
    knobs: &[
        &knobs::FAR_FIELD,
        &knobs::FAR_FIELD_SH,
        &knobs::NEAR_RADIUS,
        &knobs::FAR_RADIUS,
        &knobs::CUTOFF,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The far field's target: two RGBA16F colour attachments (diffuse and
/// specular light), 1/k of the frame each way.
pub const TARGET: &str = "far_field";

/// The near weight is 1 up to this fraction of a light's radius
/// (NEAR_INNER in glsl/common/far_field.glsl).
pub const NEAR_INNER: f32 = 0.5;

/// Whether the far field runs: on the tiled path, asked for, and with a
/// light that has a radius (the others are shaded whole everywhere).
pub fn runs(scene: &Scene, lights: &FrameLights) -> bool {
    scene.render.path == RenderPath::Tiled
        && scene.render.far_field > 0
        && lights.lights.iter().any(|l| l.radius.is_some())
}

/// Whether the far lists run (far_lists.rs): the far field runs,
/// `render.far_radius` is set, and the diffuse far light is not stored as
/// order-2 harmonics (which has a fallback of its own).
pub fn lists_on(scene: &Scene, lights: &FrameLights) -> bool {
    runs(scene, lights) && scene.render.far_radius > 0 && !scene.render.far_field_sh
}

/// How far a sample's surface point may be from the pixel it stands for:
/// half the smallest near part's inner radius (`NEAR_INNER x near_radius x
/// r`), the shortest distance over which a far part changes much. 0 (every
/// pixel sums its own far part) when no light has a positive radius.
pub fn reach(scene: &Scene, lights: &FrameLights) -> f32 {
    let r = (lights.lights.iter())
        .filter_map(|l| l.radius)
        .filter(|&r| r > 0.0)
        .fold(f32::INFINITY, f32::min);
    if r.is_finite() {
        0.5 * NEAR_INNER * scene.render.near_radius * r
    } else {
        0.0
    }
}

/// The far field's attachments: diffuse and specular light; with
/// `render.far_field_sh`, the harmonics' 27 floats around the specular
/// light (glsl/common/far_field_sh.glsl says where each float goes).
fn attachments(scene: &Scene) -> Vec<(&'static str, u32)> {
    let names: &[&'static str] = if scene.render.far_field_sh {
        &[
            "harmonics 0-3",
            "specular",
            "harmonics 4-7",
            "harmonics 8-11",
            "harmonics 12-15",
            "harmonics 16-19",
            "harmonics 20-23",
            "harmonics 24-26",
        ]
    } else if scene.render.far_radius > 0 {
        // Far lists (far_lists.rs): the coarse part's order-1 harmonics
        // (12 floats), then its specular light and C.
        &[
            "diffuse",
            "specular",
            "coarse harmonics 0-3",
            "coarse harmonics 4-7",
            "coarse harmonics 8-11",
            "coarse specular",
        ]
    } else {
        &["diffuse", "specular"]
    };
    names.iter().map(|&n| (n, glow::RGBA16F)).collect()
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if !runs(scene, lights) {
        return vec![];
    }
    let k = scene.render.far_field;
    let (w, h) = scene.render.size;
    let (sw, sh) = scaled_size(w as i32, h as i32, k);
    let n = (lights.lights.iter())
        .filter(|l| l.radius.is_some())
        .count();
    let mut draws = format!(
        "1 full-screen triangle at {sw}x{sh} (one sample per {k}x{k} pixels): the far part of {n} lights, "
    );
    draws.push_str(if scene.render.far_field_sh {
        "diffuse as order-2 spherical harmonics"
    } else {
        "diffuse at the sample's normal"
    });
    if scene.render.far_radius > 0 && !scene.render.far_field_sh {
        draws.push_str(&format!(
            "; the coarse part (beyond {} x the cutoff radius) as order-1 harmonics",
            scene.render.far_radius
        ));
    }
    if scene.render.near_radius < 1.0 {
        draws.push_str(&format!(
            "; near part to {} x the cutoff radius",
            scene.render.near_radius
        ));
    }
    let variant = LightingVariant::of(scene, lights).describe();
    vec![Pass::new("far field", TARGET, draws, file!()).with_variant(variant)]
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    if !runs(scene, lights) {
        return vec![];
    }
    vec![TargetDesc {
        name: TARGET,
        samples: 1,
        colors: attachments(scene),
        depth: Depth::None,
        ping_pong: false,
        mips: None,
        downscale: scene.render.far_field,
    }]
}

struct FarField {
    program: Program,
    /// Writes each sample's error-bound terms instead (render.far_field_bound).
    bound: Program,
    /// The same two with the diffuse part as harmonics (render.far_field_sh).
    harmonics: Program,
    harmonics_bound: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let stages = [
        (glow::VERTEX_SHADER, "common/fullscreen.vert"),
        (glow::FRAGMENT_SHADER, "deferred/far_field.frag"),
    ];
    // Specialised to the frame (src/frame/variant.rs), like the pass that reads it.
    let program = p.build_variant(&stages)?;
    let bound = p.build_variant_with(&stages, &[("FAR_FIELD_BOUND", "1".into())])?;
    let harmonics = p.build_variant_with(&stages, &[("FAR_FIELD_SH", "1".into())])?;
    let harmonics_bound = p.build_variant_with(
        &stages,
        &[
            ("FAR_FIELD_SH", "1".into()),
            ("FAR_FIELD_BOUND", "1".into()),
        ],
    )?;
    for program in [&program, &bound, &harmonics, &harmonics_bound] {
        // casts_shadow reads the Shadows block (common/shadow.glsl).
        program.bind_uniform_block("Lights", LIGHTS_BINDING);
        shadows::setup_program(program);
    }
    Ok(Box::new(FarField {
        program,
        bound,
        harmonics,
        harmonics_bound,
    }))
}

/// Bind the far field's textures for tiled shading's pass and set the
/// uniforms glsl/common/far_field.glsl reads; `unbind_textures` undoes it.
pub fn bind_for_reading(f: &Frame, p: &Program) {
    let target = f.targets.get(TARGET);
    let gl = f.gl;
    unsafe {
        for (i, (name, u)) in reading_units().into_iter().enumerate() {
            let Some(texture) = target.colors.get(i) else {
                break;
            };
            gl.active_texture(glow::TEXTURE0 + u);
            gl.bind_texture(glow::TEXTURE_2D, Some(texture.id));
            p.set_i32(name, u as i32);
        }
        gl.active_texture(glow::TEXTURE0);
    }
    set_uniforms(f, p);
}

/// Each attachment's sampler and unit in the pass that reads them, in the
/// attachments' order.
fn reading_units() -> [(&'static str, u32); 8] {
    let sh = unit::FAR_SH;
    [
        ("u_far_diffuse", unit::FAR_DIFFUSE),
        ("u_far_specular", unit::FAR_SPECULAR),
        ("u_far_sh1", sh[0]),
        ("u_far_sh2", sh[1]),
        ("u_far_sh3", sh[2]),
        ("u_far_sh4", sh[3]),
        ("u_far_sh5", sh[4]),
        ("u_far_sh6", sh[5]),
    ]
}

/// The uniforms glsl/common/far_field.glsl reads in both passes.
fn set_uniforms(f: &Frame, p: &Program) {
    p.set_i32("u_far_scale", f.scene.render.far_field as i32);
    p.set_i32("u_light_count", f.lights.len() as i32);
    p.set_f32("u_far_reach", reach(f.scene, f.lights));
    p.set_f32("u_near_scale", f.scene.render.near_radius);
    let lists = lists_on(f.scene, f.lights);
    let a = if lists {
        f.scene.render.far_radius as f32
    } else {
        0.0
    };
    p.set_f32("u_far_radius", a);
    p.set_f32("u_coarse_reach", coarse_reach(f.lights, a));
    p.set_f32("u_coarse_tolerance", f.scene.render.far_coarse_tolerance);
}

/// How far a sample's surface point may be from a pixel that takes its
/// coarse part (far_lists.rs): half the smallest coarse inner radius, `a
/// r_min / 2`. 0 without far lists or positive radii.
pub fn coarse_reach(lights: &FrameLights, a: f32) -> f32 {
    let r = (lights.lights.iter())
        .filter_map(|l| l.radius)
        .filter(|&r| r > 0.0)
        .fold(f32::INFINITY, f32::min);
    if r.is_finite() { 0.5 * a * r } else { 0.0 }
}

pub fn unbind_textures(f: &Frame) {
    let gl = f.gl;
    let n = f.targets.get(TARGET).colors.len();
    unsafe {
        for (_, u) in reading_units().into_iter().take(n) {
            gl.active_texture(glow::TEXTURE0 + u);
            gl.bind_texture(glow::TEXTURE_2D, None);
        }
        gl.active_texture(glow::TEXTURE0);
    }
}

impl RunPasses for FarField {
    fn run(&self, _: &Pass, f: &Frame) {
        let r = &f.scene.render;
        let p = match (r.far_field_sh, r.far_field_bound) {
            (false, false) => &self.program,
            (false, true) => &self.bound,
            (true, false) => &self.harmonics,
            (true, true) => &self.harmonics_bound,
        };
        let (gl, u) = (f.gl, f.uniforms);
        let target = f.targets.get(TARGET);
        let k = f.scene.render.far_field as i32;
        // The view's rectangle at 1/k: a split view's corner at x / k.
        let (x, y, w, h) = f.view.rect(target.width * k, target.height * k);
        let (sw, sh) = scaled_size(w, h, k as u32);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            gl.viewport(x / k, y / k, sw, sh);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_mask(false);

            p.use_program();
            gbuffer::bind_for_reading(gl, p, f.targets.get(gbuffer::NAME), u);
            gl.active_texture(glow::TEXTURE0 + unit::TILED_LIGHTS);
            gl.bind_texture(glow::TEXTURE_BUFFER, Some(u.lights_texture));
            gl.active_texture(glow::TEXTURE0);
            p.set_i32("u_light_data", unit::TILED_LIGHTS as i32);
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            set_uniforms(f, p);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            f.meshes.fullscreen.draw();

            f.shadows.unbind(gl);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            gl.active_texture(glow::TEXTURE0 + unit::TILED_LIGHTS);
            gl.bind_texture(glow::TEXTURE_BUFFER, None);
            gl.active_texture(glow::TEXTURE0);
            gbuffer::unbind(gl);
            gl.use_program(None);
            gl.depth_mask(true);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
