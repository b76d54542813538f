//! What can be checked of a frame without a GL context (`gloss plan`): the
//! light count against the most any GL holds, and every mesh, texture and
//! sprite the renderer would load, read and decoded by the same functions
//! in the same order (`scene::meshes::mesh_data`, `gl::texture::load_rgba8`,
//! `billboards::load_sprites`), so a file `gloss render` refuses is refused
//! here with the same message. What only a GL can answer is returned, in
//! words, for the plan to print.

use crate::frame::billboards::load_sprites;
use crate::frame::lights::{
    BUFFER_LIGHTS_ON_EVERY_GL, LIGHTS_ON_EVERY_GL, MAX_LIGHTS, check_lights_fit,
    lights_in_buffer_texture,
};
use crate::frame::multisample;
use crate::gl::texture::load_rgba8;
use crate::scene::meshes::mesh_data;
use crate::scene::{MeshSource, Scene};
use anyhow::Result;
use std::collections::HashSet;
use std::path::PathBuf;

/// Check `scene` as far as the CPU can; returns what it could not check
/// (each a phrase: "GL_MAX_SAMPLES for render.msaa = 8").
pub fn check_without_gl(scene: &Scene) -> Result<Vec<String>> {
    check_lights_fit(
        scene,
        MAX_LIGHTS,
        &format!("gloss's limit on any GL; every GL 3.3 holds {LIGHTS_ON_EVERY_GL}"),
        // Mesa and the desktop drivers hold 2^27 texels; the renderer checks its own GL.
        1 << 27,
    )?;
    // The draw list's order: each object's mesh, its material's textures,
    // its mirror's roughness texture; each file once.
    let mut meshes: HashSet<&MeshSource> = HashSet::new();
    let mut textures: HashSet<&PathBuf> = HashSet::new();
    for o in &scene.objects {
        if meshes.insert(&o.mesh) {
            mesh_data(&o.mesh)?;
        }
        let m = &scene.materials[o.material];
        let maps = [
            &m.diffuse_texture,
            &m.normal_map,
            &m.specular_map,
            &m.alpha_map,
            &m.pbr.metallic_roughness,
            &m.pbr.occlusion,
            &m.pbr.emissive_map,
        ];
        for p in maps.into_iter().flatten() {
            if textures.insert(p) {
                load_rgba8(p)?;
            }
        }
        if let Some(p) = o.mirror.as_ref().and_then(|m| m.roughness.as_ref()) {
            load_rgba8(p)?;
        }
    }
    let sprites = load_sprites(scene)?;
    let (w, h) = scene.render.size;
    let mut unchecked = vec![
        "the shaders compile".to_string(),
        "the framebuffers are complete".to_string(),
        format!("GL_MAX_TEXTURE_SIZE for the {w}x{h} targets"),
    ];
    if let Some(first) = sprites.first() {
        let (sw, sh) = first.dimensions();
        unchecked.push(format!(
            "GL_MAX_TEXTURE_SIZE for the {}x{sh} sprite sheet",
            u64::from(sw) * sprites.len() as u64
        ));
    }
    let samples = multisample::samples(scene);
    if samples > 1 {
        unchecked.push(format!("GL_MAX_SAMPLES for render.msaa = {samples}"));
    }
    let deferred = scene.render.path != crate::scene::RenderPath::Forward;
    if deferred && !crate::frame::gbuffer::material_attachments(scene).is_empty() {
        unchecked
            .push("GL_MAX_TEXTURE_IMAGE_UNITS >= 18 for the G-buffer's microfacet triple".into());
    }
    if (scene.lights.iter()).any(|l| l.shadow.is_some_and(|s| s.cascades > 1)) {
        unchecked.push(format!(
            "GL_MAX_TEXTURE_IMAGE_UNITS >= {} for the shadow cascades",
            crate::frame::units::SHADOW_CASCADES + 1
        ));
    }
    if lights_in_buffer_texture(scene) {
        if scene.lights.len() > BUFFER_LIGHTS_ON_EVERY_GL {
            unchecked.push(format!(
                "GL_MAX_TEXTURE_BUFFER_SIZE for {} lights (every GL 3.3 holds {BUFFER_LIGHTS_ON_EVERY_GL})",
                scene.lights.len()
            ));
        }
    } else if scene.lights.len() > LIGHTS_ON_EVERY_GL {
        unchecked.push(format!(
            "GL_MAX_UNIFORM_BLOCK_SIZE for {} lights (every GL 3.3 holds {LIGHTS_ON_EVERY_GL})",
            scene.lights.len()
        ));
    }
    Ok(unchecked)
}
