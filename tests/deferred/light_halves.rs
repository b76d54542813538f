//! The lights as packed halves (`render.light_data = "halves"` or
//! `"halves_float_position"`, src/frame/light_halves.rs), read by tiled
//! shading and the far field:
//!
//! * glsl/common/half.glsl's decode against the `half` crate's, run on the
//!   GPU by transform feedback over hard values (0, -0, the smallest and
//!   largest subnormal, the smallest normal, 65504, 1/3, every power of two,
//!   infinities, and a sweep of bit patterns): the same float, bit for bit;
//! * tiled shading (with and without the far field) draws the shipped
//!   many-lights scenes with each halves form within HALF_BOUND of the float
//!   form, and no further from forward than the float form but for
//!   HALF_BOUND;
//! * `gloss plan` names the form; light_block and a halves form together are
//!   refused with both keys named.

use crate::common;
use gloss::frame::lights::FrameLights;
use gloss::frame::variant::LightingVariant;
use gloss::image_compare::{compare_rgba8, flip::flip};
use gloss::renderer::Output;
use gloss::scene::{LightData, RenderPath, Scene};
use glow::HasContext;
use half::f16;

const VERT: &str = "#version 330 core
#include \"common/half.glsl\"
layout(location = 0) in uint a_word;
out vec2 t_value;
void main() {
    t_value = unpack_half2(a_word);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
";

/// Run glsl/common/half.glsl's `unpack_half2` on `words`, by transform feedback.
fn on_the_gpu(ctx: &gloss::gl::Headless, words: &[u32]) -> Vec<[f32; 2]> {
    let gl = &ctx.gl;
    let p = common::feedback_program(gl, "half.glsl", VERT, &["t_value"]);
    let f = unsafe {
        let vao = gl.create_vertex_array().unwrap();
        gl.bind_vertex_array(Some(vao));
        let vbo = gl.create_buffer().unwrap();
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        let raw: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &raw, glow::STATIC_DRAW);
        gl.enable_vertex_attrib_array(0);
        gl.vertex_attrib_pointer_i32(0, 1, glow::UNSIGNED_INT, 4, 0);
        let f = common::capture_feedback(
            gl,
            &p,
            glow::POINTS,
            words.len() * 8,
            |_| {},
            |gl| gl.draw_arrays(glow::POINTS, 0, words.len() as i32),
        );
        gl.bind_buffer(glow::ARRAY_BUFFER, None);
        gl.bind_vertex_array(None);
        gl.delete_buffer(vbo);
        gl.delete_vertex_array(vao);
        f
    };
    (0..words.len()).map(|i| [f[2 * i], f[2 * i + 1]]).collect()
}

/// Half bit patterns that exercise each branch of the decode.
fn hard_halves() -> Vec<u16> {
    let mut h: Vec<u16> = vec![
        0x0000, // 0
        0x8000, // -0
        0x0001, // smallest subnormal, 2^-24
        0x8001,
        0x0200, // 2^-15, a subnormal
        0x03ff, // largest subnormal
        0x0400, // smallest normal, 2^-14
        0x7bff, // 65504, the largest half
        0xfbff, // -65504
        0x7c00, // infinity
        0xfc00, // -infinity
        f16::from_f32(1.0 / 3.0).to_bits(),
        f16::from_f32(-1.0 / 3.0).to_bits(),
        f16::from_f32(0.9659258).to_bits(), // cos 15°, a spot's cone
        f16::from_f32(-1.0).to_bits(),      // no radius
    ];
    // Every power of two a half holds, 2^-24 to 2^15, either sign.
    h.extend((-24..=15).map(|e| f16::from_f32(2f32.powi(e)).to_bits()));
    h.extend((-24..=15).map(|e| f16::from_f32(-(2f32.powi(e))).to_bits()));
    // A sweep of the other patterns (NaNs left out: checked apart).
    h.extend((0..=0xffffu32).step_by(97).map(|b| b as u16));
    h.retain(|&b| !f16::from_bits(b).is_nan());
    h
}

#[test]
fn the_glsl_decodes_halves_as_the_half_crate() {
    let ctx = common::context(common::backend());
    let halves = hard_halves();
    // Each half in the low 16 bits beside the next in the high 16 bits.
    let words: Vec<u32> = (0..halves.len())
        .map(|i| u32::from(halves[i]) | (u32::from(halves[(i + 1) % halves.len()]) << 16))
        .collect();
    let got = on_the_gpu(&ctx, &words);
    for (i, v) in got.iter().enumerate() {
        for (k, h) in [halves[i], halves[(i + 1) % halves.len()]]
            .iter()
            .enumerate()
        {
            let want = f16::from_bits(*h).to_f32();
            assert_eq!(
                v[k].to_bits(),
                want.to_bits(),
                "half {h:#06x} ({} of word {:#010x}): GLSL {:e}, the half crate {want:e}",
                ["low", "high"][k],
                words[i],
                v[k]
            );
        }
    }
    // The NaNs decode to NaNs.
    let nan = on_the_gpu(&ctx, &[0x7e00 | (0xfc01 << 16)]);
    assert!(nan[0][0].is_nan() && nan[0][1].is_nan(), "{nan:?}");
}

/// `name` at `size` on the tiled path with light data `form`.
fn tiled(name: &str, form: LightData) -> Scene {
    let mut s = crate::with_path(&common::scene(name), RenderPath::Tiled);
    s.render.size = (320, 180);
    s.render.light_data = form;
    s
}

/// What the halves cost against the float form, in 8-bit sRGB steps, where
/// no light is cut off (the far field; the mixed lights, whose radii reach
/// past the view): the largest change of a pixel measured was 1/255; one
/// step more is the bound.
const HALF_BOUND: f64 = 2.0 / 255.0;

/// With a cutoff (many-lights.toml on the tiled path, 5/256), a light's
/// contribution jumps at its radius, and a position or radius rounded to a
/// half moves that edge by up to 2^-11 of the radius: a pixel on the edge
/// flips by the jump (measured: 0.13% of the pixels over 1/255 with every
/// value a half, 0.06% with float positions, at most 12/255). The bound is
/// on how many pixels change and on the error against forward, which must
/// stay that of the floats.
const EDGE_FRACTION: f64 = 0.003;

#[test]
fn tiled_shading_and_the_far_field_draw_the_halves_as_the_floats() {
    let ctx = common::context(common::backend());
    for (name, cut) in [
        ("many-lights.toml", true),
        ("far-field.toml", false),
        ("mixed-lights.toml", false),
    ] {
        let float = tiled(name, LightData::Texture);
        let mut forward = float.clone();
        forward.render.path = RenderPath::Forward;
        let forward = common::render_with(&ctx, &forward, Output::Srgb8).image;
        let float = common::render_with(&ctx, &float, Output::Srgb8).image;
        let f = compare_rgba8(&float, &forward, 1.0 / 255.0).unwrap();
        for form in [LightData::Halves, LightData::HalvesFloatPosition] {
            let s = tiled(name, form);
            let v = LightingVariant::of(&s, &FrameLights::new(&s));
            assert_ne!(v.light_halves, 0, "{name} {form}: the variant reads floats");
            let image = common::render_with(&ctx, &s, Output::Srgb8).image;
            let d = compare_rgba8(&image, &float, 1.0 / 255.0).unwrap();
            let h = compare_rgba8(&image, &forward, 1.0 / 255.0).unwrap();
            let flip_d = flip(&image, &float).unwrap().mean;
            eprintln!(
                "{name} {form}: against the floats max {:.0}/255 ({:.3}% > 1/255, FLIP {flip_d:.4}); \
                 against forward max {:.0}/255, RMSE {:.3}/255 (floats {:.0}/255, {:.3}/255)",
                d.max_abs * 255.0,
                d.frac_over * 100.0,
                h.max_abs * 255.0,
                h.rmse * 255.0,
                f.max_abs * 255.0,
                f.rmse * 255.0
            );
            if cut {
                assert!(d.frac_over <= EDGE_FRACTION, "{name} {form}: {d:?}");
            } else {
                assert!(d.max_abs <= HALF_BOUND, "{name} {form}: {d:?}");
            }
            assert!(
                h.max_abs <= f.max_abs + HALF_BOUND && h.rmse <= f.rmse + 0.1 / 255.0,
                "{name} {form} vs forward {h:?}, floats {f:?}"
            );
        }
    }
}

#[test]
fn the_plan_names_the_form_and_light_block_with_halves_is_refused() {
    let s = tiled("many-lights.toml", LightData::Halves);
    let plan = gloss::techniques::plan(&s).to_string();
    assert!(
        plan.contains("lights as halves (2 texels a light)"),
        "{plan}"
    );
    let s = tiled("many-lights.toml", LightData::HalvesFloatPosition);
    let plan = gloss::techniques::plan(&s).to_string();
    assert!(
        plan.contains("positions float (3 texels a light)"),
        "{plan}"
    );
    // Forward reads the block: no halves there.
    let s = crate::with_path(&s, RenderPath::Forward);
    assert_eq!(
        LightingVariant::of(&s, &FrameLights::new(&s)).light_halves,
        0
    );
    let text = std::fs::read_to_string(common::root().join("scenes/many-lights.toml")).unwrap();
    let text = text.replacen(
        "[render]\n",
        "[render]\nlight_block = true\nlight_data = \"halves\"\n",
        1,
    );
    let dir = std::env::temp_dir().join(format!("gloss-halves-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("both.toml");
    std::fs::write(&path, text).unwrap();
    let e = format!("{:#}", Scene::load(&path).unwrap_err());
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        e.contains("render.light_block = true") && e.contains("render.light_data = \"halves\""),
        "{e}"
    );
}
