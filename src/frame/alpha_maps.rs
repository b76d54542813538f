//! An MTL's map_d (src/scene/obj_materials.rs): the alpha map's first
//! channel put into the diffuse texture's alpha, so the alpha test (notes
//! 05) and the shadow pass read one texture.

use crate::gl::Gl;
use crate::gl::texture::{Sampling, Texture};
use crate::scene::material::Material;
use anyhow::Result;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Material `m`'s diffuse texture with its alpha map's first channel as
/// the alpha (an MTL's map_d; white where it has no diffuse texture),
/// uploaded once per pair (`made`); its index in `textures`.
pub fn with_alpha_map(
    gl: &Gl,
    textures: &mut Vec<Texture>,
    made: &mut HashMap<(Option<PathBuf>, PathBuf), usize>,
    m: &Material,
    alpha: &Path,
) -> Result<usize> {
    let key = (m.diffuse_texture.clone(), alpha.to_path_buf());
    if let Some(&i) = made.get(&key) {
        return Ok(i);
    }
    let img = crate::gl::image_file::load_rgba8_with_alpha(m.diffuse_texture.as_deref(), alpha)?;
    let (w, h) = img.dimensions();
    let t = Texture::from_rgba8(gl, w, h, img.as_raw(), true, Sampling::TRILINEAR_REPEAT)?;
    textures.push(t);
    made.insert(key, textures.len() - 1);
    Ok(textures.len() - 1)
}
