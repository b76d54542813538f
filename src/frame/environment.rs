//! The environment cube map (notes 03, Implementation): what the skybox pass
//! draws behind the world and what reflective materials mirror, made when
//! the scene loads (`Scene::environment`): the `[skybox]` faces, uploaded
//! here, or an empty RGBA16F cube map that the sky's cube-map pass
//! (src/techniques/sky/sky_cube_map.rs) renders the `[sky]` into, again
//! whenever the sky changes (`drawn_for`).

use crate::frame::uniforms::unit;
use crate::gl::Gl;
use crate::gl::cube_map::CubeMap;
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::sky::SkySettings;
use crate::scene::skybox::Environment as Source;
use anyhow::{Context as _, Result};
use glow::HasContext;
use std::cell::RefCell;

pub struct Environment {
    /// None: the scene has no environment.
    pub cube: Option<CubeMap>,
    /// Where it comes from.
    pub source: Option<Source>,
    /// The sky the cube map holds (None: not drawn yet, or faces).
    pub drawn_for: RefCell<Option<SkySettings>>,
    /// Image-based lighting's maps, made from the cube map when the scene
    /// asks (`render.ibl`; src/frame/image_based_lighting.rs).
    pub ibl: Option<super::image_based_lighting::IblMaps>,
}

impl Environment {
    pub fn new(gl: &Gl, scene: &Scene) -> Result<Environment> {
        let source = scene.environment();
        let cube = match &source {
            None => None,
            Some(Source::Faces(paths)) => {
                Some(CubeMap::from_faces(gl, paths).context("skybox.faces")?)
            }
            Some(Source::Sky { size }) => Some(CubeMap::empty(gl, *size as i32)?),
        };
        let ibl = match &cube {
            Some(_) if super::image_based_lighting::wanted(scene) => {
                Some(super::image_based_lighting::IblMaps::new(gl).context("render.ibl's maps")?)
            }
            _ => None,
        };
        Ok(Environment {
            cube,
            source,
            drawn_for: RefCell::new(None),
            ibl,
        })
    }

    /// The cube map the sky must be rendered into for `scene`'s `[sky]`
    /// (None: it holds faces, or that sky already).
    pub fn sky_to_draw(&self, scene: &Scene) -> Option<(&CubeMap, SkySettings)> {
        let sky = scene.sky.as_ref()?;
        let cube = self.cube.as_ref()?;
        let from_sky = matches!(self.source, Some(Source::Sky { .. }));
        (from_sky && self.drawn_for.borrow().as_ref() != Some(sky)).then(|| (cube, sky.clone()))
    }

    /// Bind the cube map on unit::ENVIRONMENT for `p` (in use), which
    /// includes glsl/common/environment.glsl. The sampler uniform is set even
    /// without a cube map: a samplerCube left on unit 0 with a sampler2D
    /// there is an invalid draw.
    pub fn bind(&self, gl: &glow::Context, p: &Program) {
        p.set_i32("u_environment", unit::ENVIRONMENT as i32);
        p.set_bool("u_has_environment", self.cube.is_some());
        unsafe {
            gl.active_texture(glow::TEXTURE0 + unit::ENVIRONMENT);
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, self.cube.as_ref().map(|c| c.id));
            gl.active_texture(glow::TEXTURE0);
        }
    }

    /// Undo `bind`.
    pub fn unbind(gl: &glow::Context) {
        unsafe {
            gl.active_texture(glow::TEXTURE0 + unit::ENVIRONMENT);
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
