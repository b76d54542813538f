//! A glTF 2.0 material as the file writes it (the metallic-roughness model,
//! §3.9 of the specification), with its textures as files beside the glTF
//! file and their samplers and KHR_texture_transform as GL values.
//! `scene::gltf_objects` maps it onto gloss's material (docs/gltf.md has
//! the formulas). What gloss does not draw goes into `dropped`, which the
//! reader turns into one warning per file.

use super::gltf_buffers::file_beside;
use crate::assets;
use anyhow::Result;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// `alphaMode`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AlphaMode {
    Opaque,
    /// Drawn where alpha >= the cutoff, discarded elsewhere.
    Mask(f32),
    Blend,
}

/// A texture: its image file, sampler (GL enums, None: the file gives
/// none) and uv transform in gloss's uv space (v up): uv' = uv x scale +
/// offset.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfTexture {
    pub path: PathBuf,
    pub wrap: [u32; 2],
    pub mag_filter: Option<u32>,
    pub min_filter: Option<u32>,
    pub uv_scale: [f32; 2],
    pub uv_offset: [f32; 2],
}

#[derive(Clone, Debug, PartialEq)]
pub struct GltfMaterial {
    pub name: String,
    /// baseColorFactor, linear RGBA.
    pub base_color: [f32; 4],
    pub base_texture: Option<GltfTexture>,
    pub metallic: f32,
    pub roughness: f32,
    pub normal_texture: Option<GltfTexture>,
    pub alpha: AlphaMode,
    pub double_sided: bool,
}

/// Read material `m` of the file at `path` (named `name`).
pub fn material(
    m: &gltf::Material,
    path: &Path,
    name: &str,
    dropped: &mut BTreeSet<String>,
) -> Result<GltfMaterial> {
    let label = m
        .name()
        .map_or(format!("material {}", m.index().unwrap_or(0)), |n| {
            format!("material '{n}'")
        });
    let pbr = m.pbr_metallic_roughness();
    let base_texture = pbr.base_color_texture().and_then(|t| {
        texture(
            &t.texture(),
            t.tex_coord(),
            t.texture_transform(),
            path,
            &label,
            "baseColorTexture",
            dropped,
        )
    });
    let normal_texture = m.normal_texture().and_then(|t| {
        if t.scale() != 1.0 {
            dropped.insert(format!(
                "{label}: normalTexture.scale {} (gloss's normal maps have no scale)",
                t.scale()
            ));
        }
        texture(
            &t.texture(),
            t.tex_coord(),
            None,
            path,
            &label,
            "normalTexture",
            dropped,
        )
    });
    if pbr.metallic_roughness_texture().is_some() {
        dropped.insert(format!(
            "{label}: metallicRoughnessTexture (its factors are used alone)"
        ));
    }
    if m.occlusion_texture().is_some() {
        dropped.insert(format!("{label}: occlusionTexture"));
    }
    if m.emissive_texture().is_some() || m.emissive_factor() != [0.0; 3] {
        dropped.insert(format!("{label}: emissive light"));
    }
    let at = format!("{name}: {label}");
    let check = |k: &str, v: f32| -> Result<f32> {
        if !(v.is_finite() && (0.0..=1.0).contains(&v)) {
            anyhow::bail!("{at}: {k} {v} is not in 0..=1");
        }
        Ok(v)
    };
    let c = pbr.base_color_factor();
    let tinted = c[0] != c[1] || c[1] != c[2] || pbr.base_color_texture().is_some();
    if pbr.metallic_factor() > 0.0 && tinted {
        dropped.insert(format!(
            "{label}: the metal's tint (gloss's highlights are white; F0 takes the base colour's luminance)"
        ));
    }
    for (k, v) in ["r", "g", "b", "a"].iter().zip(c) {
        check(&format!("baseColorFactor.{k}"), v)?;
    }
    let alpha = match m.alpha_mode() {
        gltf::material::AlphaMode::Opaque => AlphaMode::Opaque,
        gltf::material::AlphaMode::Mask => {
            AlphaMode::Mask(check("alphaCutoff", m.alpha_cutoff().unwrap_or(0.5))?)
        }
        gltf::material::AlphaMode::Blend => AlphaMode::Blend,
    };
    Ok(GltfMaterial {
        name: label,
        base_color: c,
        base_texture,
        metallic: check("metallicFactor", pbr.metallic_factor())?,
        roughness: check("roughnessFactor", pbr.roughness_factor())?,
        normal_texture,
        alpha,
        double_sided: m.double_sided(),
    })
}

/// The texture `t` as a file gloss can read, or None with what was dropped.
fn texture(
    t: &gltf::Texture,
    tex_coord: u32,
    transform: Option<gltf::texture::TextureTransform>,
    path: &Path,
    label: &str,
    slot: &str,
    dropped: &mut BTreeSet<String>,
) -> Option<GltfTexture> {
    let mut drop = |why: String| {
        dropped.insert(format!("{label}: {slot} ({why})"));
        None
    };
    let uri = match t.source().source() {
        gltf::image::Source::Uri { uri, .. } if !uri.starts_with("data:") => uri,
        _ => return drop("an image inside the file: gloss reads image files beside it".into()),
    };
    let Ok(file) = file_beside(uri, path, slot) else {
        return drop(format!("uri \"{uri}\" is not a file"));
    };
    if let Some(why) = assets::not_a_file(&file) {
        return drop(format!("file {} {why}", file.display()));
    }
    let readable = image::ImageFormat::from_path(&file).is_ok_and(|f| f.reading_enabled());
    if !readable {
        return drop(format!(
            "file {}: gloss's image decoder does not read this format",
            file.display()
        ));
    }
    let mut tc = tex_coord;
    let (mut scale, mut offset) = ([1.0, 1.0], [0.0, 0.0]);
    if let Some(x) = transform {
        if x.rotation() != 0.0 {
            dropped.insert(format!("{label}: {slot}'s KHR_texture_transform rotation"));
        }
        tc = x.tex_coord().unwrap_or(tc);
        let (s, o) = (x.scale(), x.offset());
        // glTF's v points down, gloss's up (v_gloss = 1 - v_gltf):
        // v' = 1 - ((1 - v) s + o) = v s + (1 - s - o).
        scale = s;
        offset = [o[0], 1.0 - s[1] - o[1]];
    }
    if tc != 0 {
        dropped.insert(format!(
            "{label}: {slot} reads TEXCOORD_{tc}; gloss uses TEXCOORD_0"
        ));
    }
    let s = t.sampler();
    Some(GltfTexture {
        path: file,
        wrap: [s.wrap_s().as_gl_enum(), s.wrap_t().as_gl_enum()],
        mag_filter: s.mag_filter().map(|f| f.as_gl_enum()),
        min_filter: s.min_filter().map(|f| f.as_gl_enum()),
        uv_scale: scale,
        uv_offset: offset,
    })
}
