//! The G-buffer's layout (notes 01 §8.6 "Deferred Rendering"; notes 02
//! "G-Buffers"): what each attachment holds, its format, and the texture
//! unit a lighting pass reads it from. techniques/deferred/gbuffer.rs writes
//! it; every lighting pass reads it through glsl/common/gbuffer_read.glsl.
//!
//! | attachment | format           | holds                                   |
//! |------------|------------------|-----------------------------------------|
//! | 0          | RGBA16F          | world normal (unit) and shininess       |
//! | 1          | SRGB8_ALPHA8     | diffuse albedo (stored sRGB, read linear) |
//! | 2          | SRGB8_ALPHA8     | specular colour                         |
//! | depth      | DEPTH_COMPONENT24 | depth (position is rebuilt from it); DEPTH24_STENCIL8 when the stencil light volumes use its stencil |
//!
//! Notes 03 stores `(normal + 1) / 2` in 8 bits; a 16-bit float keeps the
//! normal to about 1e-3 instead of 4e-3, which is what keeps deferred within
//! one 8-bit step of forward (docs/deferred/gbuffer.md works through it).
//! The light pre-pass needs no material: its "thin" G-buffer has only
//! attachment 0 and depth.

use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::uniforms::{FrameUniforms, unit};
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Program;
use glow::HasContext;

pub const NORMAL: (&str, u32) = ("normal_shininess", glow::RGBA16F);
pub const ALBEDO: (&str, u32) = ("albedo", glow::SRGB8_ALPHA8);
pub const SPECULAR: (&str, u32) = ("specular", glow::SRGB8_ALPHA8);

/// The G-buffer's depth format: with a stencil only when something needs
/// it, otherwise it would be a stencil allocated and cleared every frame for
/// nothing. The two-sided stencil light volumes (notes 05) mark pixels in it;
/// the light pre-pass copies its depth into the output, which has a stencil
/// (a blit copies only between equal depth formats, GL 3.3 §4.3.2). The
/// light accumulation target that copies this depth (light_volumes.rs
/// `copy_depth`) uses the same format for the same reason.
pub fn depth_format(scene: &crate::scene::Scene) -> u32 {
    use crate::scene::RenderPath;
    let stencil_volumes = scene.render.path == RenderPath::Volumes && scene.render.stencil_volumes;
    if stencil_volumes || scene.render.path == RenderPath::Prepass {
        glow::DEPTH24_STENCIL8
    } else {
        glow::DEPTH_COMPONENT24
    }
}

/// Whether a depth format has a stencil.
pub fn has_stencil(format: u32) -> bool {
    matches!(format, glow::DEPTH24_STENCIL8 | glow::DEPTH32F_STENCIL8)
}

/// The target name every deferred pass finds the G-buffer by.
pub const NAME: &str = "gbuffer";

/// The full G-buffer, or the thin one of the light pre-pass, with depth in
/// `depth` (`depth_format`).
pub fn target(thin: bool, depth: u32) -> TargetDesc {
    TargetDesc {
        name: NAME,
        samples: 1,
        colors: if thin {
            vec![NORMAL]
        } else {
            vec![NORMAL, ALBEDO, SPECULAR]
        },
        depth: Depth::Own(depth),
        ping_pong: false,
        mips: None,
        downscale: 1,
    }
}

/// Bind the G-buffer's attachments on their texture units and point the
/// samplers of `p` (in use) at them; also the matrices that rebuild a
/// position from depth. A thin G-buffer leaves albedo and specular unbound.
/// `unbind` undoes the texture bindings.
pub fn bind_for_reading(
    gl: &glow::Context,
    p: &Program,
    gbuffer: &Framebuffer,
    frame: &FrameUniforms,
) {
    let c = &gbuffer.colors;
    let depth = gbuffer.depth_stencil.as_ref().map(|t| t.id);
    let units = [
        (
            "u_gbuffer_normal",
            unit::GBUFFER_NORMAL,
            c.first().map(|t| t.id),
        ),
        (
            "u_gbuffer_albedo",
            unit::GBUFFER_ALBEDO,
            c.get(1).map(|t| t.id),
        ),
        (
            "u_gbuffer_specular",
            unit::GBUFFER_SPECULAR,
            c.get(2).map(|t| t.id),
        ),
        ("u_gbuffer_depth", unit::GBUFFER_DEPTH, depth),
    ];
    unsafe {
        for (name, u, tex) in units {
            gl.active_texture(glow::TEXTURE0 + u);
            gl.bind_texture(glow::TEXTURE_2D, tex);
            p.set_i32(name, u as i32);
        }
        gl.active_texture(glow::TEXTURE0);
    }
    p.set_mat4("u_inverse_view_projection", &frame.inverse_view_projection);
    p.set_vec4("u_viewport", glam::IVec4::from(frame.viewport).as_vec4());
    p.set_vec3("u_eye", frame.eye);
}

/// Unbind the G-buffer's texture units.
pub fn unbind(gl: &glow::Context) {
    unsafe {
        for u in [
            unit::GBUFFER_NORMAL,
            unit::GBUFFER_ALBEDO,
            unit::GBUFFER_SPECULAR,
            unit::GBUFFER_DEPTH,
        ] {
            gl.active_texture(glow::TEXTURE0 + u);
            gl.bind_texture(glow::TEXTURE_2D, None);
        }
        gl.active_texture(glow::TEXTURE0);
    }
}
