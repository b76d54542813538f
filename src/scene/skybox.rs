//! `[skybox]`: the cube map drawn behind the world (notes 03,
//! Implementation; src/techniques/sky/skybox.rs), and the environment that
//! reflective materials (`reflectivity`) mirror.
//!
//! ```toml
//! [skybox]
//! faces = ["px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"]  # +x, -x, +y, -y, +z, -z
//! # or no faces: the [sky] rendered into a cube map of `size` texels a side
//! size = 256
//! ```
//!
//! Without `[skybox]`, a scene with a `[sky]` and a reflective material
//! mirrors the sky rendered into a cube map of `DEFAULT_SIZE`.

use super::{RenderPath, Scene, Shading};
use crate::assets;
use crate::gl::cube_map::check_face_sizes;
use anyhow::{Result, bail};
use serde::Deserialize;
use std::path::{Path, PathBuf};

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub struct SkyboxFile {
    pub faces: Option<Vec<String>>,
    pub size: Option<u32>,
}

/// The side of the sky's cube map when the scene does not say.
pub const DEFAULT_SIZE: u32 = 256;
/// The largest side `skybox.size` takes.
pub const MAX_SIZE: u32 = 2048;

/// Where the environment cube map comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum Environment {
    /// Six PNGs, +x, -x, +y, -y, +z, -z.
    Faces(Vec<PathBuf>),
    /// The scene's `[sky]` rendered into a cube map of this side.
    Sky { size: u32 },
}

/// Check `[skybox]` (read from a file in `base`; `has_sky`: the scene has a `[sky]`).
pub(super) fn skybox(
    f: &Option<SkyboxFile>,
    has_sky: bool,
    base: &Path,
) -> Result<Option<Environment>> {
    let Some(s) = f else { return Ok(None) };
    let Some(faces) = &s.faces else {
        if !has_sky {
            bail!(
                "skybox: no faces and no [sky] to render into the cube map: give \
                 skybox.faces = [six PNGs: +x, -x, +y, -y, +z, -z] or add a [sky]"
            );
        }
        let size = s.size.unwrap_or(DEFAULT_SIZE);
        if !(1..=MAX_SIZE).contains(&size) {
            bail!("skybox.size: expected 1..={MAX_SIZE} texels a side, found {size}");
        }
        return Ok(Some(Environment::Sky { size }));
    };
    if s.size.is_some() {
        bail!(
            "skybox.size: only for the [sky] rendered into a cube map (no faces); \
             a skybox of faces is as large as its images"
        );
    }
    if faces.len() != 6 {
        bail!(
            "skybox.faces: expected six paths (+x, -x, +y, -y, +z, -z), found {}",
            faces.len()
        );
    }
    let mut paths = Vec::new();
    let mut sizes = Vec::new();
    for (i, face) in faces.iter().enumerate() {
        let p = super::checks::relative_to(base, face);
        if let Some(why) = assets::not_a_file(&p) {
            bail!("skybox.faces[{i}]: file {} {why}", p.display());
        }
        let size = crate::gl::image_file::dimensions(&p)
            .map_err(|e| anyhow::anyhow!("skybox.faces[{i}]: {e:#}"))?;
        sizes.push(size);
        paths.push(p);
    }
    check_face_sizes(&paths, &sizes).map_err(|e| anyhow::anyhow!("skybox.faces: {e}"))?;
    Ok(Some(Environment::Faces(paths)))
}

impl Scene {
    /// The cube map reflective materials mirror and the skybox pass draws:
    /// the `[skybox]`, else the `[sky]` rendered into a cube map when a
    /// material reflects (None: neither).
    pub fn environment(&self) -> Option<Environment> {
        if let Some(e) = &self.skybox {
            return Some(e.clone());
        }
        let reflects = self.materials.iter().any(|m| m.reflectivity > 0.0);
        // Image-based lighting lights with the sky's cube map too.
        ((reflects || self.render.ibl) && self.sky.is_some())
            .then_some(Environment::Sky { size: DEFAULT_SIZE })
    }

    /// Whether the skybox is drawn before the opaque world
    /// (`render.sky_first`, the forward path only) rather than after it at z = w.
    pub fn sky_first(&self) -> bool {
        self.render.sky_first && self.skybox.is_some() && self.render.path == RenderPath::Forward
    }

    /// What `[skybox]`, `render.sky_first` and `reflectivity` set to no effect.
    pub(super) fn skybox_warnings(&self, w: &mut Vec<String>) {
        if self.render.ibl && self.environment().is_none() {
            w.push(
                "render.ibl = true has no effect without a [sky] or a [skybox]: there is no \
                 environment to light with (the constant ambient is used)"
                    .into(),
            );
        }
        if self.render.sky_first && self.skybox.is_none() {
            w.push("render.sky_first = true has no effect without a [skybox]".into());
        } else if self.render.sky_first && self.render.path != RenderPath::Forward {
            w.push(format!(
                "render.sky_first = true has no effect on the {} path: its last pass writes \
                 every pixel, so the skybox is drawn after the world, at z = w (forward only)",
                self.render.path.name()
            ));
        }
        for m in self.materials.iter().filter(|m| m.reflectivity > 0.0) {
            if m.is_transparent() {
                w.push(format!(
                    "materials.{}.reflectivity has no effect: the transparency pass \
                     (opacity < 1) does not mirror the environment",
                    m.name
                ));
            } else if self.render.path == RenderPath::Forward
                && self.render.shading != Shading::Phong
            {
                w.push(format!(
                    "materials.{}.reflectivity has no effect with {} shading: only Phong \
                     shading (per fragment) mirrors the environment",
                    m.name,
                    self.render.shading.name()
                ));
            }
        }
    }
}

/// A reflective material needs an environment: a `[skybox]` or a `[sky]`.
pub(super) fn check_reflective(scene: &Scene) -> Result<()> {
    if scene.skybox.is_some() || scene.sky.is_some() {
        return Ok(());
    }
    if let Some(m) = scene.materials.iter().find(|m| m.reflectivity > 0.0) {
        bail!(
            "materials.{}.reflectivity: a reflective material mirrors the environment, \
             and this scene has none: add a [skybox] or a [sky]",
            m.name
        );
    }
    Ok(())
}

/// Check material `name`'s `reflectivity`: 0 (the default) ..= 1.
pub(super) fn reflectivity(name: &str, r: f32) -> Result<f32> {
    if !(r.is_finite() && (0.0..=1.0).contains(&r)) {
        bail!("materials.{name}.reflectivity: expected a number in 0..=1, found {r}");
    }
    Ok(r)
}
