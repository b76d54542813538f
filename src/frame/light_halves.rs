//! The lights as packed half floats (`render.light_data = "halves"` or
//! `"halves_float_position"`), for the passes that read many lights a pixel:
//! tiled shading and the far field (glsl/common/light_buffer.glsl).
//!
//! The float form is the std140 `Light` of glsl/common/lighting.glsl, 16
//! floats a light in four RGBA32F texels (src/frame/lights.rs `pack`). Here
//! the same 16 values, in the same order, are IEEE binary16 halves (encoded
//! by the `half` crate, round to nearest even), two to a 32-bit word, the
//! first in the low 16 bits, in RGBA32UI texels:
//!
//! * `HALVES`: all 16 as halves, 8 words, two texels a light;
//! * `FLOAT_POSITION`: the position as three float words, then the other
//!   13 values as halves, 10 words in three texels (two words spare): a
//!   half's 11-bit significand puts a light at 16 units from the origin on
//!   a grid of 1/64, which moves the lit spot of a light close to a surface.
//!
//! GLSL 3.30 has no `unpackHalf2x16`: glsl/common/half.glsl decodes by hand
//! (subnormals included). A value a half cannot hold (over 65504) is an
//! error that names the light and the field, never a silent infinity.

use crate::gl::Gl;
use crate::gl::texture_buffer::TextureBuffer;
use crate::scene::{LightData, RenderPath, Scene};
use half::f16;

/// `VARIANT_LIGHT_HALVES` in glsl/common/light_buffer.glsl.
pub mod code {
    /// The floats (buffer texture or block).
    pub const NONE: i32 = 0;
    /// Every value a half: two RGBA32UI texels a light.
    pub const HALVES: i32 = 1;
    /// Position in floats, the rest halves: three RGBA32UI texels a light.
    pub const FLOAT_POSITION: i32 = 2;
}

/// The std140 `Light`'s 16 values, named as a scene writes them.
const FIELDS: [&str; 16] = [
    "position.x",
    "position.y",
    "position.z",
    "type",
    "direction.x",
    "direction.y",
    "direction.z",
    "radius (from attenuation and render.cutoff)",
    "colour x intensity (red)",
    "colour x intensity (green)",
    "colour x intensity (blue)",
    "cos(outer_angle)",
    "attenuation kc",
    "attenuation kl",
    "attenuation kq",
    "cos(inner_angle)",
];

/// Which packed form `scene`'s frame reads: none unless the shaders are
/// specialised and the path is tiled (tiled shading and its far field are
/// the passes that read the buffer texture).
pub fn code(scene: &Scene) -> i32 {
    if !scene.render.specialize || scene.render.path != RenderPath::Tiled {
        return code::NONE;
    }
    match scene.render.light_data {
        LightData::Halves => code::HALVES,
        LightData::HalvesFloatPosition => code::FLOAT_POSITION,
        LightData::Texture | LightData::Block => code::NONE,
    }
}

/// RGBA32UI texels a light in form `code`.
pub fn texels_per_light(code: i32) -> usize {
    match code {
        code::HALVES => 2,
        code::FLOAT_POSITION => 3,
        _ => 4,
    }
}

/// Two halves in one word, `lo` in the low 16 bits (as GLSL's
/// packHalf2x16 would, in GL 4.2).
pub fn pack2(lo: f32, hi: f32) -> u32 {
    u32::from(f16::from_f32(lo).to_bits()) | (u32::from(f16::from_f32(hi).to_bits()) << 16)
}

/// Pack the float form `floats` (16 a light, `FrameLights::pack`'s order)
/// into form `code`'s words, 4 a texel. `Err` names the first light and
/// field a half cannot hold; `file` names the scene for the message.
pub fn pack(floats: &[f32], code: i32, file: &str) -> anyhow::Result<Vec<u32>> {
    let first_half = if code == code::FLOAT_POSITION { 3 } else { 0 };
    let per_light = 4 * texels_per_light(code);
    let mut out = Vec::with_capacity(floats.len() / 16 * per_light);
    for (i, l) in floats.chunks_exact(16).enumerate() {
        for (k, &v) in l.iter().enumerate().skip(first_half) {
            if !f16::from_f32(v).is_finite() {
                anyhow::bail!(
                    "{file}: render.light_data = \"{}\": light {i}'s {} is {v}, more than a half float holds (65504); use \"texture\"",
                    if code == code::HALVES {
                        "halves"
                    } else {
                        "halves_float_position"
                    },
                    FIELDS[k]
                );
            }
        }
        let start = out.len();
        if code == code::FLOAT_POSITION {
            out.extend(l[..3].iter().map(|p| p.to_bits()));
        }
        let rest = &l[first_half..];
        for pair in rest.chunks(2) {
            out.push(pack2(pair[0], pair.get(1).copied().unwrap_or(0.0)));
        }
        out.resize(start + per_light, 0);
    }
    Ok(out)
}

/// `scene`'s lights as its frame's packed form reads them (`code(scene)`),
/// from the float form's bytes; empty for the float form.
pub fn pack_scene(scene: &Scene, float_bytes: &[u8]) -> anyhow::Result<Vec<u32>> {
    let c = code(scene);
    if c == code::NONE {
        return Ok(Vec::new());
    }
    let floats: Vec<f32> = (float_bytes.chunks_exact(4))
        .map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    pack(&floats, c, &scene.path.display().to_string())
}

/// The buffer textures the lights go in: RGBA32F for the floats, RGBA32UI
/// for the halves (a `usamplerBuffer` reads only integer texels), made the
/// first time a frame reads halves.
pub struct LightTextures {
    gl: Gl,
    floats: TextureBuffer,
    halves: Option<TextureBuffer>,
}

impl LightTextures {
    pub fn new(gl: &Gl) -> anyhow::Result<LightTextures> {
        Ok(LightTextures {
            gl: gl.clone(),
            floats: TextureBuffer::new(gl, glow::RGBA32F)?,
            halves: None,
        })
    }

    /// Upload `scene`'s lights (`FrameLights::pack`'s bytes), and their
    /// halves when its frame reads those (`Err` when a value does not fit
    /// in a half; `check_lights_fit` has said so before).
    pub fn write(&mut self, scene: &Scene, float_bytes: &[u8]) -> anyhow::Result<()> {
        self.floats.write(float_bytes);
        if code(scene) == code::NONE {
            return Ok(());
        }
        let words = pack_scene(scene, float_bytes)?;
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_ne_bytes()).collect();
        if self.halves.is_none() {
            self.halves = Some(TextureBuffer::new(&self.gl, glow::RGBA32UI)?);
        }
        if let Some(h) = &self.halves {
            h.write(&bytes);
        }
        Ok(())
    }

    /// The texture a variant with `light_halves` = `code` reads.
    pub fn texture(&self, code: i32) -> glow::Texture {
        match (&self.halves, code) {
            (Some(h), code::HALVES | code::FLOAT_POSITION) => h.texture,
            _ => self.floats.texture,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_pair_low_first_and_the_float_position_keeps_its_bits() {
        let l: Vec<f32> = (0..16).map(|k| k as f32 * 0.5 + 0.25).collect();
        let h = pack(&l, code::HALVES, "t").unwrap();
        assert_eq!(h.len(), 8);
        // 0.25 = 0x3400, 0.75 = 0x3a00 (sign 0, exponent 13 and 14).
        assert_eq!(h[0], 0x3400 | (0x3a00 << 16));
        let p = pack(&l, code::FLOAT_POSITION, "t").unwrap();
        assert_eq!(p.len(), 12);
        assert_eq!(
            &p[..3],
            &[0.25f32.to_bits(), 0.75f32.to_bits(), 1.25f32.to_bits()]
        );
        assert_eq!(p[3], pack2(1.75, 2.25));
        assert_eq!(p[9], pack2(7.75, 0.0));
        assert_eq!(&p[10..], &[0, 0]);
    }

    #[test]
    fn a_value_over_a_half_names_the_light_and_field() {
        let mut l = vec![0.0f32; 32];
        l[16 + 9] = 70000.0;
        let e = pack(&l, code::HALVES, "s.toml").unwrap_err().to_string();
        assert!(
            e.contains("light 1's colour x intensity (green) is 70000"),
            "{e}"
        );
        // Position past a half is fine when positions stay floats.
        l[9 + 16] = 1.0;
        l[0] = 1.0e6;
        assert!(pack(&l, code::FLOAT_POSITION, "s.toml").is_ok());
        assert!(pack(&l, code::HALVES, "s.toml").is_err());
    }
}
