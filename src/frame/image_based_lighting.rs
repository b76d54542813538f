//! Image-based lighting's three textures (Karis 2013, "Real Shading in
//! Unreal Engine 4", Image-Based Lighting): the irradiance cube map (E / pi),
//! the prefiltered cube map (one GGX roughness per mip level) and the
//! split-sum table (A, B in RG16F), made when the scene asks for them
//! (`render.ibl` with an environment) and filled by
//! src/techniques/sky/image_based_lighting.rs from the environment cube
//! map, again whenever the sky is drawn anew. The forward pass and the
//! composite read them as the ambient term (glsl/common/image_based_lighting.glsl).

use crate::frame::uniforms::unit;
use crate::frame::unit_check::{self, UnitsNeeded};
use crate::gl::Gl;
use crate::gl::cube_map::CubeMap;
use crate::gl::program::Program;
use crate::gl::texture::{Sampling, Texture, set_sampling};
use crate::gl::texture_units::{self, OnUnit};
use crate::lighting::image_based_lighting::{
    BRDF_SIZE, IRRADIANCE_SIZE, PREFILTERED_LEVELS, PREFILTERED_SIZE,
};
use crate::scene::Scene;
use crate::scene::sky::SkySettings;
use anyhow::{Result, anyhow};
use glow::HasContext;
use std::cell::RefCell;

/// The maps' units and what `check_units` says without them.
const UNITS: UnitsNeeded = UnitsNeeded {
    key: "render.ibl",
    reads: "its maps",
    units: &[unit::IBL_IRRADIANCE, unit::IBL_PREFILTERED, unit::IBL_BRDF],
    instead: "set render.ibl = false",
};

pub struct IblMaps {
    gl: Gl,
    pub irradiance: CubeMap,
    pub prefiltered: CubeMap,
    pub brdf: Texture,
    /// The one framebuffer the precompute attaches each face and level to.
    pub framebuffer: glow::Framebuffer,
    /// What the maps were made from: None not yet; Some(None) faces;
    /// Some(Some(sky)) that sky.
    pub made_for: RefCell<Option<Option<SkySettings>>>,
}

/// Whether `scene` asks for image-based lighting and has an environment to light with.
pub fn wanted(scene: &Scene) -> bool {
    scene.render.ibl && scene.environment().is_some()
}

impl IblMaps {
    /// The three textures, empty.
    pub fn new(gl: &Gl) -> Result<IblMaps> {
        let irradiance = CubeMap::empty(gl, IRRADIANCE_SIZE)?;
        // Its own size whatever the environment's: the roughest level keeps
        // 4 texels a side, which a wide lobe needs.
        let prefiltered = CubeMap::empty(gl, PREFILTERED_SIZE)?;
        let brdf = Texture::render_target(gl, BRDF_SIZE, BRDF_SIZE, glow::RG16F)?;
        unsafe {
            // Only the levels the precompute fills are read.
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(irradiance.id));
            gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_MAX_LEVEL, 0);
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(prefiltered.id));
            let levels = PREFILTERED_LEVELS.min(prefiltered_levels(prefiltered.size));
            gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, glow::TEXTURE_MAX_LEVEL, levels - 1);
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
            gl.bind_texture(glow::TEXTURE_2D, Some(brdf.id));
            set_sampling(gl, Sampling::BILINEAR_CLAMP);
            gl.bind_texture(glow::TEXTURE_2D, None);
            let framebuffer = gl
                .create_framebuffer()
                .map_err(|e| anyhow!("glGenFramebuffers: {e}"))?;
            crate::gl::live::made(crate::gl::live::Kind::Framebuffer);
            Ok(IblMaps {
                gl: gl.clone(),
                irradiance,
                prefiltered,
                brdf,
                framebuffer,
                made_for: RefCell::new(None),
            })
        }
    }

    /// The three maps on their units (`bind`, `unbind`).
    fn on_units(&self) -> [OnUnit; 3] {
        let cube = glow::TEXTURE_CUBE_MAP;
        [
            OnUnit {
                unit: unit::IBL_IRRADIANCE,
                target: cube,
                texture: self.irradiance.id,
            },
            OnUnit {
                unit: unit::IBL_PREFILTERED,
                target: cube,
                texture: self.prefiltered.id,
            },
            OnUnit {
                unit: unit::IBL_BRDF,
                target: glow::TEXTURE_2D,
                texture: self.brdf.id,
            },
        ]
    }

    /// The prefiltered map's levels (fewer for a small environment).
    pub fn levels(&self) -> i32 {
        PREFILTERED_LEVELS.min(prefiltered_levels(self.prefiltered.size))
    }
}

/// The levels of a cube map of `size`: down to 1 texel.
fn prefiltered_levels(size: i32) -> i32 {
    32 - (size.max(1) as u32).leading_zeros() as i32
}

impl Drop for IblMaps {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_framebuffer(self.framebuffer);
            crate::gl::live::freed(crate::gl::live::Kind::Framebuffer);
        }
    }
}

/// Bind the maps for `p` (in use), which includes
/// glsl/common/image_based_lighting.glsl; without maps, u_has_ibl is false
/// and the samplers name units whose sampler types they share (a samplerCube
/// on unit::ENVIRONMENT, the table on unit::IBL_BRDF_OFF), so no draw mixes
/// two sampler types on one unit.
pub fn bind(gl: &glow::Context, p: &Program, maps: Option<&IblMaps>) {
    p.set_bool("u_has_ibl", maps.is_some());
    let Some(m) = maps else {
        p.set_i32("u_ibl_irradiance", unit::ENVIRONMENT as i32);
        p.set_i32("u_ibl_prefiltered", unit::ENVIRONMENT as i32);
        p.set_i32("u_ibl_brdf", unit::IBL_BRDF_OFF as i32);
        return;
    };
    p.set_i32("u_ibl_irradiance", unit::IBL_IRRADIANCE as i32);
    p.set_i32("u_ibl_prefiltered", unit::IBL_PREFILTERED as i32);
    p.set_i32("u_ibl_brdf", unit::IBL_BRDF as i32);
    p.set_f32("u_ibl_levels", m.levels() as f32);
    texture_units::bind(gl, &m.on_units());
}

/// Undo `bind`.
pub fn unbind(gl: &glow::Context, maps: Option<&IblMaps>) {
    if let Some(m) = maps {
        texture_units::unbind(gl, &m.on_units());
    }
}

/// A scene with image-based lighting needs units up to unit::IBL_BRDF:
/// say so clearly on a GL with fewer.
pub fn check_units(gl: &glow::Context, scene: &Scene) -> Result<()> {
    if !wanted(scene) {
        return Ok(());
    }
    unit_check::check_units(gl, &scene.path, &UNITS)
}
