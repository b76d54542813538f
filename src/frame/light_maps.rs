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

/// What one shadow ray costs in bake work, against one texel-light
/// evaluation (src/frame/budget.rs bounds the total).
pub const SHADOW_RAY_WORK: u64 = 3;

/// A bake of this much work (src/frame/budget.rs) or more prints its
/// progress: about a second.
pub const LONG_BAKE: u64 = 1 << 21;

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
    // The budget (src/frame/budget.rs) bounded the work; a long bake says
    // what it is doing, object by object.
    let work = bake_work(scene);
    let total: u64 = work.iter().map(|w| w.1).sum();
    let mut done = 0;
    for (i, o) in scene.objects.iter().enumerate() {
        let Some(l) = o.light_map else {
            maps.push(None);
            continue;
        };
        if total >= LONG_BAKE {
            let here = work.iter().find(|w| w.0 == i).map_or(0, |w| w.1);
            eprintln!(
                "gloss: baking the light map of object {} ({}x{} texels, {} lights{}): {}% of the bake done",
                o.name,
                l.size,
                l.size,
                scene.lights.len(),
                if l.shadows { ", shadow rays" } else { "" },
                100 * done / total
            );
            done += here;
        }
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

/// The light maps' bake: texels x lights, and x shadow rays where on.
pub fn bake_work(scene: &Scene) -> Vec<(usize, u64)> {
    if !scene.render.light_maps {
        return Vec::new();
    }
    let lights = scene.lights.len() as u64;
    (scene.objects.iter().enumerate())
        .filter_map(|(i, o)| {
            let l = o.light_map?;
            let per = 1 + if l.shadows { SHADOW_RAY_WORK } else { 0 };
            Some((i, u64::from(l.size) * u64::from(l.size) * lights * per))
        })
        .collect()
}
