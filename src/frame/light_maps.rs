//! The light maps' bake when the scene loads (notes 01 §8.2, static
//! lighting): each object's light map baked on the CPU and uploaded; the
//! draw list keeps them, and src/frame/draw_textures.rs binds them.

use crate::gl::Gl;
use crate::gl::texture::{Sampling, Texture};
use crate::lighting::shadow_reference::SceneTriangles;
use crate::lighting::static_lighting;
use crate::scene::Scene;
use crate::scene::meshes::mesh_data;
use anyhow::{Context as _, Result};

/// Each object's light map (notes 01 §8.2), baked on the CPU
/// (src/lighting/static_lighting.rs) and uploaded as GL_RGBA16F; None for
/// an object without `light_map`.
pub fn bake_light_maps(gl: &Gl, scene: &Scene) -> Result<Vec<Option<Texture>>> {
    let shadows = scene
        .objects
        .iter()
        .any(|o| o.light_map.is_some_and(|l| l.shadows));
    let occluders = if shadows {
        Some(SceneTriangles::new(scene)?)
    } else {
        None
    };
    let mut maps = Vec::new();
    for (i, o) in scene.objects.iter().enumerate() {
        let Some(l) = o.light_map else {
            maps.push(None);
            continue;
        };
        let mesh = mesh_data(&o.mesh)?;
        let occluders = occluders.as_ref().filter(|_| l.shadows);
        let baked = static_lighting::bake(scene, i, &mesh, l.size, occluders);
        if baked.overlaps > 0 {
            eprintln!(
                "gloss: warning: object {}'s uvs overlap ({} light-map texels lie in two triangles): the light map holds one of them",
                o.name, baked.overlaps
            );
        }
        let rgb: Vec<f32> = baked.texels.iter().flatten().copied().collect();
        let t = Texture::from_rgb_f32(gl, l.size, l.size, &rgb, Sampling::BILINEAR_CLAMP)
            .with_context(|| format!("the light map of object {}", o.name))?;
        maps.push(Some(t));
    }
    Ok(maps)
}
