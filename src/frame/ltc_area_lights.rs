//! The area lights' GPU data (Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time
//! Polygonal-Light Shading with Linearly Transformed Cosines"): the two LTC
//! fit tables (src/lighting/ltc_tables/) as 64 x 64 RGBA32F textures, made
//! when a scene with `[[area_lights]]` loads, and the lights' uniforms. The
//! forward pass and the G-buffer paths' area-light pass
//! (src/techniques/deferred/ltc_area_lights_deferred.rs) bind them for
//! glsl/lighting/ltc_area_lights.glsl; the technique
//! (src/techniques/lighting/ltc_area_lights.rs) draws the lights.

use crate::frame::uniforms::unit;
use crate::frame::unit_check::{self, UnitsNeeded};
use crate::gl::Gl;
use crate::gl::program::Program;
use crate::gl::texture::{Sampling, Texture, set_sampling};
use crate::gl::texture_units::{self, OnUnit};
use crate::lighting::ltc::{LTC_SIZE, ltc_1, ltc_2};
use crate::scene::area_lights::{AreaLightReference, MAX_AREA_LIGHTS};
use crate::scene::{RenderPath, Scene, Shading};
use anyhow::{Result, bail};
use glow::{HasContext, PixelUnpackData};

/// The tables' units and what `check_units` says without them.
const UNITS: UnitsNeeded = UnitsNeeded {
    key: "[[area_lights]]",
    reads: "the LTC tables",
    units: &[unit::LTC_1, unit::LTC_2],
    instead: "set render.area_lights = false",
};

/// The two tables, on units 25 and 26 while a pass that shades with them draws.
pub struct LtcTables {
    pub ltc_1: Texture,
    pub ltc_2: Texture,
}

/// Whether the frame shades and draws the scene's area lights: it has some,
/// `render.area_lights` is on, and the path lights per pixel: a G-buffer
/// path, or forward with Phong shading (what else leaves them out is in the
/// scene's warnings).
pub fn wanted(scene: &Scene) -> bool {
    let r = &scene.render;
    !scene.area_lights.is_empty()
        && r.area_lights
        && (r.path != RenderPath::Forward || r.shading == Shading::Phong)
}

impl LtcTables {
    /// The two tables on their units (`bind`, `unbind`).
    fn on_units(&self) -> [OnUnit; 2] {
        let on = |unit, t: &Texture| OnUnit {
            unit,
            target: glow::TEXTURE_2D,
            texture: t.id,
        };
        [on(unit::LTC_1, &self.ltc_1), on(unit::LTC_2, &self.ltc_2)]
    }

    /// The tables for `scene` (None: it has no area lights). Made whatever
    /// the knobs say, so that switching the lights on needs nothing new.
    pub fn for_scene(gl: &Gl, scene: &Scene) -> Result<Option<LtcTables>> {
        if scene.area_lights.is_empty() {
            return Ok(None);
        }
        Ok(Some(LtcTables {
            ltc_1: upload(gl, ltc_1())?,
            ltc_2: upload(gl, ltc_2())?,
        }))
    }
}

/// One table as a GL_RGBA32F texture, read with GL_LINEAR between texel
/// centres and clamped at the edges (the shader's uv x 63/64 + 0.5/64).
fn upload(gl: &Gl, table: &[[f32; 4]]) -> Result<Texture> {
    let n = LTC_SIZE as i32;
    if table.len() != LTC_SIZE * LTC_SIZE {
        bail!(
            "LTC table: expected {} texels, found {}",
            LTC_SIZE * LTC_SIZE,
            table.len()
        );
    }
    let texture = Texture::render_target(gl, n, n, glow::RGBA32F)?;
    let bytes: Vec<u8> = table
        .iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    unsafe {
        gl.bind_texture(glow::TEXTURE_2D, Some(texture.id));
        gl.tex_sub_image_2d(
            glow::TEXTURE_2D,
            0,
            0,
            0,
            n,
            n,
            glow::RGBA,
            glow::FLOAT,
            PixelUnpackData::Slice(Some(&bytes)),
        );
        set_sampling(gl, Sampling::BILINEAR_CLAMP);
        gl.bind_texture(glow::TEXTURE_2D, None);
    }
    Ok(texture)
}

/// Set the area lights' uniforms of `p` (in use; it includes
/// glsl/lighting/ltc_area_lights.glsl) and bind the tables on units 25 and
/// 26. Without them (or not `wanted`) the count is 0; the samplers still
/// name units 25 and 26, which hold nothing else.
pub fn bind(gl: &glow::Context, p: &Program, scene: &Scene, tables: Option<&LtcTables>) {
    p.set_i32("u_ltc_1", unit::LTC_1 as i32);
    p.set_i32("u_ltc_2", unit::LTC_2 as i32);
    let Some(t) = tables.filter(|_| wanted(scene)) else {
        p.set_i32("u_area_light_count", 0);
        return;
    };
    let lights = &scene.area_lights[..scene.area_lights.len().min(MAX_AREA_LIGHTS)];
    p.set_i32("u_area_light_count", lights.len() as i32);
    // LTC (0), or the reference by quadrature (glsl/lighting/area_light_reference.glsl).
    let r = &scene.render;
    p.set_i32(
        "u_area_light_reference",
        reference_mode(r.area_light_reference),
    );
    if r.area_light_reference != AreaLightReference::Off {
        p.set_i32("u_area_light_points", r.area_light_points as i32);
    }
    for (i, l) in lights.iter().enumerate() {
        for (k, c) in l.corners().iter().enumerate() {
            p.set_vec3(&format!("u_area_corners[{}]", 4 * i + k), *c);
        }
        p.set_vec3(&format!("u_area_radiance[{i}]"), l.radiance());
        p.set_bool(&format!("u_area_two_sided[{i}]"), l.two_sided);
    }
    texture_units::bind(gl, &t.on_units());
}

/// The shader's `u_area_light_reference`: 0 LTC, 1 the quadrature with the
/// exact Fresnel, 2 with the table's Schlick-average Fresnel.
fn reference_mode(r: AreaLightReference) -> i32 {
    match r {
        AreaLightReference::Off => 0,
        AreaLightReference::Exact => 1,
        AreaLightReference::TableFresnel => 2,
    }
}

/// Undo `bind`.
pub fn unbind(gl: &glow::Context, tables: Option<&LtcTables>) {
    if let Some(t) = tables {
        texture_units::unbind(gl, &t.on_units());
    }
}

/// A scene with area lights reads the tables from units 25 and 26: say so
/// clearly on a GL with fewer fragment texture units.
pub fn check_units(gl: &glow::Context, scene: &Scene) -> Result<()> {
    if !wanted(scene) {
        return Ok(());
    }
    unit_check::check_units(gl, &scene.path, &UNITS)
}
