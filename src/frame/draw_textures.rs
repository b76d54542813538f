//! A geometry pass's textures for one object (notes 01 §5, §8.4, §8.2): the
//! diffuse texture (or its mip-colour twin), the normal map, the sampler
//! object that says how to read them, and the light map (baked when the
//! scene loads: src/frame/light_maps.rs).

use crate::frame::draw_list::{DrawItem, DrawList};
use crate::frame::uniforms::unit;
use crate::gl::program::Program;
use crate::scene::RenderSettings;
use glow::HasContext;

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
        let [a, b, c] = d.pbr_maps;
        d.texture
            .or(d.normal_map)
            .or(d.specular_map)
            .or(a)
            .or(b)
            .or(c)?;
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
    /// and `u_has_normal_map`, `u_normal_scale`, `u_has_light_map` for
    /// program `p`. The specular map, if any, goes on unit SPECULAR_MAP
    /// with the same sampler (`u_has_specular_map`), bound before the
    /// light map. Unit DIFFUSE_TEXTURE is left
    /// active; `unbind_textures` undoes it all.
    pub fn bind_textures(&self, gl: &glow::Context, p: &Program, d: &DrawItem, r: &RenderSettings) {
        let sampler = self.sampler(d, r);
        let normal_map = self.normal_map(d, r);
        let light_map = d
            .light_map
            .filter(|_| r.light_maps)
            .map(|t| self.textures[t].id);
        let specular_map = d.specular_map.map(|t| self.textures[t].id);
        unsafe {
            gl.active_texture(glow::TEXTURE0 + unit::SPECULAR_MAP);
            gl.bind_texture(glow::TEXTURE_2D, specular_map);
            gl.bind_sampler(unit::SPECULAR_MAP, specular_map.and(sampler));
            gl.active_texture(glow::TEXTURE0 + unit::LIGHT_MAP);
            gl.bind_texture(glow::TEXTURE_2D, light_map);
            gl.active_texture(glow::TEXTURE0 + unit::NORMAL_MAP);
            gl.bind_texture(glow::TEXTURE_2D, normal_map);
            gl.bind_sampler(unit::NORMAL_MAP, sampler);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            gl.bind_texture(glow::TEXTURE_2D, self.texture(d, r));
            gl.bind_sampler(unit::DIFFUSE_TEXTURE, sampler);
        }
        self.bind_pbr_maps(gl, p, d, sampler);
        p.set_bool("u_has_normal_map", normal_map.is_some());
        p.set_f32("u_normal_scale", d.normal_scale);
        p.set_bool("u_has_specular_map", specular_map.is_some());
        p.set_bool("u_has_light_map", light_map.is_some());
    }

    /// glTF's maps (src/scene/gltf_material.rs), with the material's
    /// sampler: metallic-roughness, occlusion and emissive on their units,
    /// each bound only where the material has it, and their factors; for
    /// a material with none of them and no emission, `u_pbr` false alone.
    fn bind_pbr_maps(
        &self,
        gl: &glow::Context,
        p: &Program,
        d: &DrawItem,
        sampler: Option<glow::Sampler>,
    ) {
        let pbr = d.pbr_maps.iter().any(Option::is_some) || d.pbr.emissive != glam::Vec3::ZERO;
        p.set_bool("u_pbr", pbr);
        if !pbr {
            return;
        }
        let maps = [
            ("u_metal_rough_map", unit::METAL_ROUGH_MAP),
            ("u_occlusion_map", unit::OCCLUSION_MAP),
            ("u_emissive_map", unit::EMISSIVE_MAP),
        ];
        for ((name, u), t) in maps.into_iter().zip(d.pbr_maps) {
            if let Some(t) = t {
                unsafe {
                    gl.active_texture(glow::TEXTURE0 + u);
                    gl.bind_texture(glow::TEXTURE_2D, Some(self.textures[t].id));
                    gl.bind_sampler(u, sampler);
                }
                p.set_i32(name, u as i32);
            }
        }
        let [metal_rough, occlusion, emissive] = d.pbr_maps.map(|t| t.is_some());
        p.set_bool("u_has_metal_rough_map", metal_rough);
        p.set_bool("u_has_occlusion_map", occlusion);
        p.set_bool("u_has_emissive_map", emissive);
        if metal_rough {
            p.set_vec3("u_base_color", d.pbr.base);
            p.set_vec2(
                "u_metal_rough",
                glam::Vec2::new(d.pbr.metallic, d.pbr.roughness),
            );
        }
        p.set_f32("u_occlusion_strength", d.pbr.occlusion_strength);
        p.set_vec3("u_emissive", d.pbr.emissive);
    }

    /// Point every sampler of glsl/common/material.glsl that program `p`
    /// has at its own unit, once when it is built: the diffuse texture,
    /// normal map and specular map, and glTF's maps (`u_metal_rough_map`,
    /// `u_occlusion_map`, `u_emissive_map`). `Programs` calls it for every
    /// program it builds (src/frame/technique.rs), so each pass that draws
    /// materials (forward, the G-buffer, the light pre-pass's combine, the
    /// transparent draws) gets it from one place. `bind_pbr_maps` sets the
    /// glTF units only for a material with the map; left at GL's default,
    /// unit 0, they would read the diffuse texture, and llvmpipe runs those
    /// reads (with the material's filter: 16x anisotropic on
    /// texture-filtering) under a mask even where `u_pbr` is false. On an
    /// empty unit a read costs next to nothing. A program with none of
    /// these samplers is left alone.
    pub fn setup_program(p: &Program) {
        let units = [
            ("u_diffuse_texture", unit::DIFFUSE_TEXTURE),
            ("u_normal_map", unit::NORMAL_MAP),
            ("u_specular_map", unit::SPECULAR_MAP),
            ("u_metal_rough_map", unit::METAL_ROUGH_MAP),
            ("u_occlusion_map", unit::OCCLUSION_MAP),
            ("u_emissive_map", unit::EMISSIVE_MAP),
        ];
        if !units.iter().any(|(name, _)| p.has_uniform(name)) {
            return;
        }
        p.use_program();
        for (name, u) in units {
            p.set_i32(name, u as i32);
        }
        p.unuse();
    }

    /// Unbind what `bind_textures` bound; unit 0 is left active.
    pub fn unbind_textures(gl: &glow::Context) {
        unsafe {
            for u in [
                unit::METAL_ROUGH_MAP,
                unit::OCCLUSION_MAP,
                unit::EMISSIVE_MAP,
                unit::SPECULAR_MAP,
                unit::LIGHT_MAP,
                unit::NORMAL_MAP,
                unit::DIFFUSE_TEXTURE,
            ] {
                gl.active_texture(glow::TEXTURE0 + u);
                gl.bind_texture(glow::TEXTURE_2D, None);
                gl.bind_sampler(u, None);
            }
            gl.active_texture(glow::TEXTURE0);
        }
    }
}
