//! A glTF 2.0 material as the file writes it (the metallic-roughness model,
//! §3.9 of the specification), with its textures (files beside the glTF
//! file, or images inside it: `FILE#images[N]`, gltf_images.rs) and their samplers and KHR_texture_transform as GL values.
//! `scene::gltf_objects` maps it onto gloss's material (docs/gltf.md has
//! the formulas). What gloss does not draw goes into `dropped`, which the
//! reader turns into one warning per file.

use super::gltf_buffers::file_beside;
use super::gltf_images::gltf_image_path;
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
    /// normalTexture.scale: the map's x and y are multiplied by it.
    pub normal_scale: f32,
    /// metallicRoughnessTexture: B metallic, G roughness (linear).
    pub metallic_roughness_texture: Option<GltfTexture>,
    /// occlusionTexture (R) and its strength.
    pub occlusion_texture: Option<GltfTexture>,
    pub occlusion_strength: f32,
    /// emissiveFactor (linear RGB) and emissiveTexture (sRGB).
    pub emissive: [f32; 3],
    pub emissive_texture: Option<GltfTexture>,
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
    let metallic_roughness_texture = pbr.metallic_roughness_texture().and_then(|t| {
        texture(
            &t.texture(),
            t.tex_coord(),
            t.texture_transform(),
            path,
            &label,
            "metallicRoughnessTexture",
            dropped,
        )
    });
    let occlusion_texture = m.occlusion_texture().and_then(|t| {
        texture(
            &t.texture(),
            t.tex_coord(),
            None,
            path,
            &label,
            "occlusionTexture",
            dropped,
        )
    });
    let emissive_texture = m.emissive_texture().and_then(|t| {
        texture(
            &t.texture(),
            t.tex_coord(),
            t.texture_transform(),
            path,
            &label,
            "emissiveTexture",
            dropped,
        )
    });
    // gloss samples every map of a material with one sampler and one uv
    // transform: the base colour texture's (else the first map's).
    let maps = [
        ("baseColorTexture", &base_texture),
        ("normalTexture", &normal_texture),
        ("metallicRoughnessTexture", &metallic_roughness_texture),
        ("occlusionTexture", &occlusion_texture),
        ("emissiveTexture", &emissive_texture),
    ];
    let sampling = |t: &GltfTexture| (t.wrap, t.mag_filter, t.min_filter, t.uv_scale, t.uv_offset);
    if let Some((first, t0)) = maps.iter().find_map(|(k, t)| t.as_ref().map(|t| (k, t))) {
        for (k, t) in &maps {
            if t.as_ref().is_some_and(|t| sampling(t) != sampling(t0)) {
                dropped.insert(format!(
                    "{label}: {k}'s own sampler or transform (sampled as {first} is)"
                ));
            }
        }
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
    let metal = pbr.metallic_factor() > 0.0;
    if metal && tinted {
        dropped.insert(format!(
            "{label}: the metal's tint (gloss's highlights are white; F0 takes the base colour's luminance)"
        ));
    }
    for (k, v) in ["r", "g", "b", "a"].iter().zip(c) {
        check(&format!("baseColorFactor.{k}"), v)?;
    }
    let e = m.emissive_factor();
    for (k, v) in ["r", "g", "b"].iter().zip(e) {
        check(&format!("emissiveFactor.{k}"), v)?;
    }
    let occlusion_strength = m.occlusion_texture().map_or(1.0, |t| t.strength());
    check("occlusionTexture.strength", occlusion_strength)?;
    let normal_scale = m.normal_texture().map_or(1.0, |t| t.scale());
    if !(normal_scale.is_finite() && normal_scale.abs() <= 100.0) {
        anyhow::bail!("{at}: normalTexture.scale {normal_scale} is not within ±100");
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
        normal_scale,
        metallic_roughness_texture,
        occlusion_texture,
        occlusion_strength,
        emissive: e,
        emissive_texture,
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
    let image = t.source();
    // An image inside the file (a buffer view, a data: URI) is read from the
    // file when its texture loads (gltf_images.rs); its MIME type must be one
    // gloss decodes.
    let inside = |mime: &str| {
        let readable =
            image::ImageFormat::from_mime_type(mime).is_some_and(|f| f.reading_enabled());
        let at = gltf_image_path(path, image.index());
        (!readable).then(|| {
            format!(
                "{}: gloss's image decoder does not read \"{mime}\"",
                at.display()
            )
        })
    };
    let file = match image.source() {
        gltf::image::Source::View { mime_type, .. } => match inside(mime_type) {
            Some(why) => return drop(why),
            None => gltf_image_path(path, image.index()),
        },
        gltf::image::Source::Uri { uri, .. } if uri.starts_with("data:") => {
            let mime = uri["data:".len()..].split([';', ',']).next().unwrap_or("");
            match inside(mime) {
                Some(why) => return drop(why),
                None => gltf_image_path(path, image.index()),
            }
        }
        gltf::image::Source::Uri { uri, .. } => {
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
            file
        }
    };
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
