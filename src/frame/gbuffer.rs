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
//! | 3          | RGBA8 or RGBA16F | gAlpha: notes 03's microfacet triple (alpha, eta, k_s), as `render.gbuffer_encoding` says |
//! | 4          | RGBA8            | gConvert: the report's flags (1: stored as its reciprocal), w = 1 for a microfacet pixel |
//!
//! Attachments 3 and 4 exist only when an opaque material is microfacet
//! (`material_attachments`), 4 only for the report's encodings (the plain
//! one has gAlpha.w = 1 for a microfacet pixel). The thin G-buffer puts
//! them at 1 and 2. glsl/common/gbuffer_material.glsl writes and reads them.
//!
//! Notes 03 stores `(normal + 1) / 2` in 8 bits; a 16-bit float keeps the
//! normal to about 1e-3 instead of 4e-3, which is what keeps deferred within
//! one 8-bit step of forward (docs/deferred/gbuffer.md works through it).
//! The light pre-pass needs no material: its "thin" G-buffer has only
//! attachment 0 and depth.
//!
//! The packed G-buffer (`render.gbuffer = "octahedral"`) holds attachment 0
//! in RGBA8 instead (4 bytes a pixel, not 8): rgb the octahedral normal
//! (Cigolle et al. 2014) in 12 + 12 bits (src/math/octahedral.rs), a the
//! index of the pixel's shininess in the scene's table of shininess values
//! (`shininess_table`, at most `SHININESS_TABLE` of them; with more, the
//! frame keeps RGBA16F and `gloss plan` says why).

pub use crate::frame::material_variant::MaterialVariant;
use crate::frame::targets::{Depth, TargetDesc};
use crate::frame::uniforms::{FrameUniforms, unit};
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Program;
use glow::HasContext;

pub const NORMAL: (&str, u32) = ("normal_shininess", glow::RGBA16F);
pub const ALBEDO: (&str, u32) = ("albedo", glow::SRGB8_ALPHA8);
pub const SPECULAR: (&str, u32) = ("specular", glow::SRGB8_ALPHA8);
pub const CONVERT: (&str, u32) = ("convert", glow::RGBA8);
/// Attachment 0 of the packed G-buffer: octahedral normal + shininess index.
pub const OCTAHEDRAL: (&str, u32) = ("normal_octahedral", glow::RGBA8);
/// The most shininess values the packed G-buffer's table holds (16 vec4).
pub const SHININESS_TABLE: usize = 64;

/// Every shininess the scene's materials give the G-buffer, ascending and
/// each once: a microfacet material's is its lobe's Blinn-Phong
/// equivalent, as `DrawList::set_object_uniforms` sets it.
pub fn shininess_table(scene: &crate::scene::Scene) -> Vec<f32> {
    let mut t: Vec<f32> = (scene.materials.iter())
        .map(|m| {
            m.microfacet
                .map_or(m.shininess, |f| f.equivalent_shininess())
        })
        .collect();
    t.sort_by(f32::total_cmp);
    t.dedup();
    t
}

/// The scene's table as the shaders' `u_shininess_table[16]` reads it
/// (unused entries 0).
pub fn shininess_uniform(scene: &crate::scene::Scene) -> [glam::Vec4; SHININESS_TABLE / 4] {
    let mut v = [glam::Vec4::ZERO; SHININESS_TABLE / 4];
    for (i, s) in shininess_table(scene)
        .iter()
        .take(SHININESS_TABLE)
        .enumerate()
    {
        v[i / 4][i % 4] = *s;
    }
    v
}

/// The index the packed G-buffer stores for `shininess`: its place in the
/// table, or the nearest value's.
pub fn shininess_code(table: &[f32], shininess: f32) -> usize {
    (table.iter().enumerate())
        .min_by(|a, b| (a.1 - shininess).abs().total_cmp(&(b.1 - shininess).abs()))
        .map_or(0, |(i, _)| i)
}

/// Whether the frame's G-buffer is the packed one: asked for, the scene's
/// shininess values fit the table, and no far field reads it (`kept_by`).
pub fn octahedral(scene: &crate::scene::Scene) -> bool {
    scene.render.gbuffer == crate::scene::material::GBufferNormals::Octahedral
        && kept_by(scene).is_none()
}

/// Why a frame that asks for the packed G-buffer keeps RGBA16F, in words:
/// more shininess values than the table holds, or tiled shading's far
/// field, whose same-surface test (glsl/common/far_field.glsl) takes a
/// sample's normal within 0.002-0.003 rad of the pixel's: finer than the
/// 12-bit grid's 1.1e-3 rad, so on curved silhouettes it accepted samples
/// it should not (measured: 15/255 against forward on scenes/many-lights.toml
/// at k = 4, where RGBA16F gives 2-4/255).
pub fn kept_by(scene: &crate::scene::Scene) -> Option<String> {
    let n = shininess_table(scene).len();
    if n > SHININESS_TABLE {
        return Some(format!(
            "{n} shininess values, more than the packed table's {SHININESS_TABLE}"
        ));
    }
    let far = scene.render.path == crate::scene::RenderPath::Tiled && scene.render.far_field > 0;
    far.then(|| "the far field compares normals finer than 12 bits".to_string())
}

/// Bytes a pixel of `formats` take (the G-buffer's, for `gloss plan`).
pub fn bytes_per_pixel(formats: &[(&str, u32)], depth: u32) -> u32 {
    let b = |f: u32| match f {
        glow::RGBA16F => 8,
        glow::RGBA32F => 16,
        _ => 4,
    };
    formats.iter().map(|&(_, f)| b(f)).sum::<u32>() + b(depth)
}

/// The attachments that hold the microfacet triple (notes 03, Geometry
/// Pass): none when no opaque material is microfacet, gAlpha alone for the
/// plain encoding, gAlpha and gConvert for the report's.
pub fn material_attachments(scene: &crate::scene::Scene) -> Vec<(&'static str, u32)> {
    use crate::scene::material::GBufferEncoding;
    let microfacet = (scene.objects.iter())
        .map(|o| &scene.materials[o.material])
        .any(|m| m.microfacet.is_some() && !m.is_transparent());
    if !microfacet {
        return vec![];
    }
    match scene.render.gbuffer_encoding {
        GBufferEncoding::ReportRgba8 => vec![("alpha", glow::RGBA8), CONVERT],
        GBufferEncoding::ReportRgba16f => vec![("alpha", glow::RGBA16F), CONVERT],
        GBufferEncoding::PlainRgba16f => vec![("alpha", glow::RGBA16F)],
    }
}

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
/// `depth` (`depth_format`) and the `material_attachments` after the rest;
/// attachment 0 `OCTAHEDRAL` for the packed G-buffer, else `NORMAL`; the
/// full one without `SPECULAR` when `slim` (src/frame/gbuffer_slim.rs: every
/// material's specular colour is the same, and no material attachments).
pub fn target(
    thin: bool,
    octahedral: bool,
    slim: bool,
    depth: u32,
    material: &[(&'static str, u32)],
) -> TargetDesc {
    let normal = if octahedral { OCTAHEDRAL } else { NORMAL };
    TargetDesc {
        name: NAME,
        samples: 1,
        colors: if thin {
            [&[normal][..], material].concat()
        } else if slim {
            [&[normal, ALBEDO][..], material].concat()
        } else {
            [&[normal, ALBEDO, SPECULAR][..], material].concat()
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
    bind_material(gl, p, gbuffer);
    // The packed normal attachment and the shininess its alpha indexes.
    let packed = c.first().is_some_and(|t| t.internal_format == OCTAHEDRAL.1);
    p.set_bool("u_gbuffer_octahedral", packed);
    if packed {
        p.set_vec4_array("u_shininess_table", &frame.shininess_table);
    }
    // The slim G-buffer (src/frame/gbuffer_slim.rs): albedo but no specular
    // attachment; every pixel's specular colour is the uniform.
    let slim = c.len() == 2 && c[1].internal_format == ALBEDO.1;
    p.set_bool("u_gbuffer_specular_constant", slim);
    p.set_vec3("u_gbuffer_specular_value", frame.gbuffer_specular);
    p.set_mat4("u_inverse_view_projection", &frame.inverse_view_projection);
    p.set_vec4("u_viewport", glam::IVec4::from(frame.viewport).as_vec4());
    p.set_vec3("u_eye", frame.eye);
}

/// How the lighting passes decode the material attachments: the values of
/// `u_gbuffer_material` in glsl/common/gbuffer_material.glsl.
pub mod material_code {
    /// No material attachments: every pixel is Phong.
    pub const NONE: i32 = 0;
    /// gAlpha holds reciprocals where gConvert says so.
    pub const REPORT: i32 = 1;
    /// gAlpha holds the values as they are.
    pub const PLAIN: i32 = 2;
}

/// The material attachments of `gbuffer` (whose layout `target` made): their
/// first index, and the `material_code`.
pub fn material_layout(gbuffer: &Framebuffer) -> (usize, i32) {
    let c = &gbuffer.colors;
    let thin = c.get(1).is_none_or(|t| t.internal_format != ALBEDO.1);
    let first = if thin { 1 } else { 3 };
    let code = match c.len().saturating_sub(first) {
        0 => material_code::NONE,
        1 => material_code::PLAIN,
        _ => material_code::REPORT,
    };
    (first, code)
}

/// Bind gAlpha and gConvert, when the G-buffer has them, on units
/// GBUFFER_ALPHA and GBUFFER_CONVERT (16 and 17: tiled shading with shadows
/// takes all 16 that GL 3.3 promises, so a microfacet scene on a deferred
/// path needs a GL with 18, `check_units`).
fn bind_material(gl: &glow::Context, p: &Program, gbuffer: &Framebuffer) {
    let (first, code) = material_layout(gbuffer);
    p.set_i32("u_gbuffer_material", code);
    if code == material_code::NONE {
        return;
    }
    let c = &gbuffer.colors;
    unsafe {
        gl.active_texture(glow::TEXTURE0 + unit::GBUFFER_ALPHA);
        gl.bind_texture(glow::TEXTURE_2D, Some(c[first].id));
        p.set_i32("u_gbuffer_alpha", unit::GBUFFER_ALPHA as i32);
        if code == material_code::REPORT {
            gl.active_texture(glow::TEXTURE0 + unit::GBUFFER_CONVERT);
            gl.bind_texture(glow::TEXTURE_2D, Some(c[first + 1].id));
            p.set_i32("u_gbuffer_convert", unit::GBUFFER_CONVERT as i32);
        }
        gl.active_texture(glow::TEXTURE0);
    }
}

/// The texture units a G-buffer with material attachments needs
/// (GBUFFER_CONVERT + 1), against what this GL has: an error that says so.
pub fn check_units(gl: &glow::Context, scene: &crate::scene::Scene) -> anyhow::Result<()> {
    let deferred = scene.render.path != crate::scene::RenderPath::Forward;
    if !deferred || material_attachments(scene).is_empty() {
        return Ok(());
    }
    let key = format!(
        "render.path = \"{}\" with a microfacet material",
        scene.render.path
    );
    let need = crate::frame::unit_check::UnitsNeeded {
        key: &key,
        reads: "its G-buffer triple",
        units: &[unit::GBUFFER_ALPHA, unit::GBUFFER_CONVERT],
        instead: "use render.path = \"forward\"",
    };
    crate::frame::unit_check::check_units(gl, &scene.path, &need)
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
        // The material's units, where this GL has them.
        let units = gl.get_parameter_i32(glow::MAX_COMBINED_TEXTURE_IMAGE_UNITS);
        if units > unit::GBUFFER_CONVERT as i32 {
            for u in [unit::GBUFFER_ALPHA, unit::GBUFFER_CONVERT] {
                gl.active_texture(glow::TEXTURE0 + u);
                gl.bind_texture(glow::TEXTURE_2D, None);
            }
        }
        gl.active_texture(glow::TEXTURE0);
    }
}
