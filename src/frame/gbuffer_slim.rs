//! A G-buffer without the attachments the scene's materials make constant
//! (notes 02 "G-Buffers": store only what varies per pixel). The specular
//! attachment (src/frame/gbuffer.rs, attachment 2) holds each pixel's
//! specular colour and reflectivity; when every opaque material has the same
//! colour, no specular map, no microfacet lobe (whose pixels keep their
//! emission there) and no reflectivity (which the skybox reflection reads
//! from its alpha), every covered pixel would store the same value. The
//! frame then leaves the attachment out: the geometry pass writes one
//! attachment fewer (4 bytes a pixel less to write, clear and read), and
//! the lighting passes read the colour from `u_gbuffer_specular_value`
//! instead (glsl/common/gbuffer_read.glsl; a variant define where the
//! lighting is specialised, src/frame/variant.rs).
//!
//! The constant is the value the full G-buffer would give back: the colour
//! encoded to 8-bit sRGB as GL_FRAMEBUFFER_SRGB stores it, decoded as the
//! sampler reads it. The standard's formulas give it (`as_stored`), but a
//! driver may round a hair differently, so the renderer measures it on its
//! GL once per scene (`read_back`) and the slim frame draws the full one's
//! image. `render.gbuffer_slim = false` forces the full G-buffer (to
//! compare the two in one `gloss bench` run).

use crate::scene::{RenderPath, Scene};
use glam::Vec3;

/// The specular colour every opaque material shares, as the lighting
/// passes read it (`as_stored`), when the frame's G-buffer leaves its
/// attachment out; None when it keeps it.
pub fn stored_specular(scene: &Scene) -> Option<Vec3> {
    constant_specular(scene).map(|c| c.map(as_stored))
}

/// The specular colour every opaque material shares (as the scene gives
/// it) when the frame's G-buffer leaves its attachment out; None when the
/// frame keeps it (`kept_by` says why) or has no full G-buffer (forward, or
/// the light pre-pass's thin one).
pub fn constant_specular(scene: &Scene) -> Option<Vec3> {
    let full = matches!(
        scene.render.path,
        RenderPath::Deferred | RenderPath::Volumes | RenderPath::Tiled
    );
    if !full || !scene.render.gbuffer_slim {
        return None;
    }
    shared_specular(scene).ok()
}

/// Why a full G-buffer keeps its specular attachment, in words for `gloss
/// plan`; None when it leaves it out, or the knob is off.
pub fn kept_by(scene: &Scene) -> Option<String> {
    if !scene.render.gbuffer_slim {
        return None;
    }
    shared_specular(scene).err()
}

/// The one specular colour of the opaque materials (the G-buffer pass
/// draws the opaque objects; a mirror's too, to be safe), or why there is
/// not one.
fn shared_specular(scene: &Scene) -> Result<Vec3, String> {
    let mut shared: Option<Vec3> = None;
    let opaque = (scene.objects.iter())
        .map(|o| &scene.materials[o.material])
        .filter(|m| !m.is_transparent());
    for m in opaque {
        let name = &m.name;
        if m.microfacet.is_some() {
            return Err(format!("material {name} is microfacet"));
        }
        if m.specular_map.is_some() {
            return Err(format!("material {name} has a specular map"));
        }
        if m.pbr.metallic_roughness.is_some() || m.pbr.emissive_map.is_some() {
            return Err(format!("material {name} has glTF maps"));
        }
        if m.reflectivity != 0.0 {
            return Err(format!("material {name} is reflective"));
        }
        match shared {
            None => shared = Some(m.specular),
            Some(c) if c == m.specular => {}
            Some(c) => {
                let s = m.specular;
                return Err(format!(
                    "two specular colours ({:.2}, {:.2}, {:.2}) and ({:.2}, {:.2}, {:.2})",
                    c.x, c.y, c.z, s.x, s.y, s.z
                ));
            }
        }
    }
    // No opaque object: every pixel is background, the value unread.
    Ok(shared.unwrap_or(Vec3::ZERO))
}

/// One linear channel as an SRGB8_ALPHA8 attachment stores it and a
/// sampler reads it back: encoded, rounded to 8 bits, decoded (in f64, as
/// Mesa's table of the 256 decoded values is made, then to f32).
pub fn as_stored(c: f32) -> f32 {
    let c = f64::from(c.clamp(0.0, 1.0));
    let encoded = if c < 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    let v = (encoded * 255.0).round() / 255.0;
    let linear = if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    };
    linear as f32
}

const PROBE_VERT: &str = "#version 330 core
void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }
";
const PROBE_FRAG: &str = "#version 330 core
uniform bool u_read;
uniform sampler2D u_stored;
uniform vec3 u_value;
out vec4 c;
void main() { c = u_read ? texelFetch(u_stored, ivec2(0), 0) : vec4(u_value, 0.0); }
";

/// What this GL's lighting passes would read from a specular attachment
/// that `colour` was written into: one pixel written with
/// GL_FRAMEBUFFER_SRGB on into an SRGB8_ALPHA8 texture, as the geometry
/// pass writes, then read by a shader into RGBA32F, as a lighting pass
/// reads. `as_stored` is the standard's answer; a driver's encode may round
/// a value within a hair of a half step the other way (llvmpipe stores 0.5
/// as 187, the formula says 187.52 -> 188), and the slim frame must draw
/// the full one's image on the GL it runs on. GL state: the framebuffer,
/// program, vertex array, unit 0's texture, viewport; restored to none and
/// unit 0 active.
pub fn read_back(gl: &glow::Context, colour: Vec3) -> anyhow::Result<Vec3> {
    use anyhow::anyhow;
    use glow::HasContext;
    unsafe {
        let mut viewport = [0i32; 4];
        gl.get_parameter_i32_slice(glow::VIEWPORT, &mut viewport);
        let program = gl.create_program().map_err(|e| anyhow!("{e}"))?;
        let mut shaders = Vec::new();
        for (kind, text) in [
            (glow::VERTEX_SHADER, PROBE_VERT),
            (glow::FRAGMENT_SHADER, PROBE_FRAG),
        ] {
            let s = gl.create_shader(kind).map_err(|e| anyhow!("{e}"))?;
            gl.shader_source(s, text);
            gl.compile_shader(s);
            if !gl.get_shader_compile_status(s) {
                let log = gl.get_shader_info_log(s);
                gl.delete_shader(s);
                gl.delete_program(program);
                anyhow::bail!("the slim G-buffer's probe shader: {log}");
            }
            gl.attach_shader(program, s);
            shaders.push(s);
        }
        gl.link_program(program);
        for s in shaders {
            gl.detach_shader(program, s);
            gl.delete_shader(s);
        }
        if !gl.get_program_link_status(program) {
            let log = gl.get_program_info_log(program);
            gl.delete_program(program);
            anyhow::bail!("the slim G-buffer's probe program: {log}");
        }
        let texture = |format: u32, kind: u32| {
            let t = gl.create_texture().map_err(|e| anyhow!("{e}"))?;
            gl.bind_texture(glow::TEXTURE_2D, Some(t));
            let nearest = glow::NEAREST as i32;
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, nearest);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, nearest);
            let data = glow::PixelUnpackData::Slice(None);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                format as i32,
                1,
                1,
                0,
                glow::RGBA,
                kind,
                data,
            );
            gl.bind_texture(glow::TEXTURE_2D, None);
            anyhow::Ok(t)
        };
        let stored = texture(glow::SRGB8_ALPHA8, glow::UNSIGNED_BYTE)?;
        let read = texture(glow::RGBA32F, glow::FLOAT)?;
        let fbo = gl.create_framebuffer().map_err(|e| anyhow!("{e}"))?;
        let vao = gl.create_vertex_array().map_err(|e| anyhow!("{e}"))?;
        let attach = |t| {
            let c0 = glow::COLOR_ATTACHMENT0;
            gl.framebuffer_texture_2d(glow::FRAMEBUFFER, c0, glow::TEXTURE_2D, Some(t), 0);
        };
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        gl.bind_vertex_array(Some(vao));
        gl.viewport(0, 0, 1, 1);
        gl.use_program(Some(program));
        let at = |name: &str| gl.get_uniform_location(program, name);
        // 1. Written as the geometry pass writes the specular colour.
        attach(stored);
        gl.uniform_1_i32(at("u_read").as_ref(), 0);
        gl.uniform_3_f32(at("u_value").as_ref(), colour.x, colour.y, colour.z);
        gl.enable(glow::FRAMEBUFFER_SRGB);
        gl.draw_arrays(glow::POINTS, 0, 1);
        gl.disable(glow::FRAMEBUFFER_SRGB);
        // 2. Read as a lighting pass reads it, into floats.
        attach(read);
        gl.active_texture(glow::TEXTURE0);
        gl.bind_texture(glow::TEXTURE_2D, Some(stored));
        gl.uniform_1_i32(at("u_read").as_ref(), 1);
        gl.uniform_1_i32(at("u_stored").as_ref(), 0);
        gl.draw_arrays(glow::POINTS, 0, 1);
        let mut out = [0u8; 16];
        let data = glow::PixelPackData::Slice(Some(&mut out));
        gl.read_pixels(0, 0, 1, 1, glow::RGBA, glow::FLOAT, data);
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.use_program(None);
        gl.bind_vertex_array(None);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.viewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        gl.delete_vertex_array(vao);
        gl.delete_framebuffer(fbo);
        gl.delete_texture(stored);
        gl.delete_texture(read);
        gl.delete_program(program);
        let f = |i: usize| f32::from_le_bytes(out[4 * i..4 * i + 4].try_into().unwrap_or([0; 4]));
        Ok(Vec3::new(f(0), f(1), f(2)))
    }
}

/// The slim G-buffer's specular colour on this GL (`read_back` of the
/// shared colour), or 0 when the frame keeps the attachment.
pub fn uniform_value(gl: &glow::Context, scene: &Scene) -> anyhow::Result<Vec3> {
    match constant_specular(scene) {
        Some(c) => read_back(gl, c),
        None => Ok(Vec3::ZERO),
    }
}
