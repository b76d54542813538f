//! A geometry pass's textures for one object (notes 01 §5, §8.4, §8.2): the
//! diffuse texture (or its mip-colour twin), the normal map, the sampler
//! object that says how to read them, and the light map; and the light
//! maps' bake when the scene loads.

use crate::frame::draw_list::{DrawItem, DrawList};
use crate::frame::uniforms::unit;
use crate::gl::Gl;
use crate::gl::program::Program;
use crate::gl::texture::{Sampling, Texture};
use crate::lighting::shadow_reference::SceneTriangles;
use crate::lighting::static_lighting;
use crate::scene::meshes::mesh_data;
use crate::scene::{RenderSettings, Scene};
use anyhow::{Context as _, Result};
use glow::HasContext;

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
    let work = crate::frame::budget::bake_work(scene);
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

impl DrawList {
    /// The object's diffuse texture, if its material has one; with
    /// `render.mip_colors`, the twin of its size whose levels are colours.
    pub fn texture(&self, d: &DrawItem, r: &RenderSettings) -> Option<glow::Texture> {
        let t = &self.textures[d.texture?];
        if r.mip_colors {
            self.samplers.twin(t)
        } else {
            Some(t.id)
        }
    }

    /// The sampler object the object's texture is read with under `r`
    /// (glBindSampler on the diffuse texture's unit).
    pub fn sampler(&self, d: &DrawItem, r: &RenderSettings) -> Option<glow::Sampler> {
        d.texture.or(d.normal_map)?;
        self.samplers.sampler(&d.texturing, r)
    }

    /// The object's normal map, if its material has one and
    /// `render.normal_mapping` is on.
    pub fn normal_map(&self, d: &DrawItem, r: &RenderSettings) -> Option<glow::Texture> {
        let t = d.normal_map.filter(|_| r.normal_mapping)?;
        Some(self.textures[t].id)
    }

    /// A geometry pass's per-object texture binds (notes 01 §5, §8.4): the
    /// diffuse texture on unit DIFFUSE_TEXTURE and the normal map on unit
    /// NORMAL_MAP, each with the material's sampler object (the wrap rule
    /// per axis and the filter), and the light map on LIGHT_MAP (its own
    /// bilinear, clamped parameters), in this order:
    ///
    /// glActiveTexture(LIGHT_MAP); glBindTexture;
    /// glActiveTexture(NORMAL_MAP); glBindTexture; glBindSampler;
    /// glActiveTexture(DIFFUSE_TEXTURE); glBindTexture; glBindSampler;
    ///
    /// and `u_has_normal_map`, `u_has_light_map` for program `p`. Unit DIFFUSE_TEXTURE is left
    /// active; `unbind_textures` undoes it all.
    pub fn bind_textures(&self, gl: &glow::Context, p: &Program, d: &DrawItem, r: &RenderSettings) {
        let sampler = self.sampler(d, r);
        let normal_map = self.normal_map(d, r);
        let light_map = d
            .light_map
            .filter(|_| r.light_maps)
            .map(|t| self.textures[t].id);
        unsafe {
            gl.active_texture(glow::TEXTURE0 + unit::LIGHT_MAP);
            gl.bind_texture(glow::TEXTURE_2D, light_map);
            gl.active_texture(glow::TEXTURE0 + unit::NORMAL_MAP);
            gl.bind_texture(glow::TEXTURE_2D, normal_map);
            gl.bind_sampler(unit::NORMAL_MAP, sampler);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            gl.bind_texture(glow::TEXTURE_2D, self.texture(d, r));
            gl.bind_sampler(unit::DIFFUSE_TEXTURE, sampler);
        }
        p.set_bool("u_has_normal_map", normal_map.is_some());
        p.set_bool("u_has_light_map", light_map.is_some());
    }

    /// Unbind what `bind_textures` bound; unit 0 is left active.
    pub fn unbind_textures(gl: &glow::Context) {
        unsafe {
            for u in [unit::LIGHT_MAP, unit::NORMAL_MAP, unit::DIFFUSE_TEXTURE] {
                gl.active_texture(glow::TEXTURE0 + u);
                gl.bind_texture(glow::TEXTURE_2D, None);
                gl.bind_sampler(u, None);
            }
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
