//! glTF 2.0's metallic-roughness material (the specification's Appendix B)
//! on gloss's material: the microfacet triple of notes 03 (alpha, eta, k_s)
//! with a Lambert diffuse colour. docs/gltf.md derives it:
//!
//! ```text
//! c_d   = baseColor.rgb x (1 - metallic)          (a metal has no diffuse)
//! alpha = roughness^2                             (glTF's alpha, GGX's width)
//! F0    = 0.04 (1 - metallic) + lum(baseColor) x metallic
//! eta   = (1 + sqrt F0) / (1 - sqrt F0), within 1..=10 (so F(normal) = F0)
//! k_s   = F0 / ((eta - 1) / (eta + 1))^2          (1 unless eta was capped)
//! ```
//!
//! With a metallicRoughnessTexture the shader takes the same formulas per
//! texel, metallic = metallicFactor x B and roughness = roughnessFactor x
//! G, with baseColor = the factor x the base colour texture
//! (glsl/common/material.glsl, `material_triple`). normalTexture.scale is
//! the normal map's scale; occlusionTexture multiplies the ambient term by
//! 1 + strength (R - 1); emissiveFactor x emissiveTexture is added to the
//! lit colour.
//!
//! gloss's highlight is white: a metal keeps its F0's luminance and loses
//! its tint (the reader's one warning per file says so). MASK is the alpha
//! test `alpha >= alphaCutoff` (notes 05), BLEND the transparency pass with
//! opacity baseColor.a, doubleSided turns culling off; the base colour
//! texture's sampler and KHR_texture_transform become the material's
//! texturing.

use super::material::{Microfacet, PbrMaps};
use super::texturing::{TextureFilter, Texturing, Wrap};
use super::{AlphaTest, Cull, Material, Winding};
use crate::geometry::{AlphaMode, GltfMaterial, GltfScene, GltfTexture};
use glam::Vec3;
use std::path::Path;

/// The Rec. 709 luminance of a linear colour.
fn luminance(c: Vec3) -> f32 {
    c.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}

/// The triple for glTF's `metallic`, `roughness` and base colour.
pub fn microfacet(metallic: f32, roughness: f32, base: Vec3) -> Microfacet {
    let (a_lo, a_hi) = Microfacet::ALPHA;
    let (e_lo, e_hi) = Microfacet::ETA;
    let f0 = 0.04 * (1.0 - metallic) + luminance(base) * metallic;
    let r = f0.clamp(0.0, 0.999).sqrt();
    let eta = ((1.0 + r) / (1.0 - r)).clamp(e_lo, e_hi);
    let f0_eta = ((eta - 1.0) / (eta + 1.0)).powi(2);
    let k_s = if f0_eta > 0.0 { f0 / f0_eta } else { 0.0 };
    Microfacet {
        alpha: (roughness * roughness).clamp(a_lo, a_hi),
        eta,
        k_s: k_s.clamp(Microfacet::K_S.0, Microfacet::K_S.1),
    }
}

/// gloss's material for `m`, named after the file.
pub fn material(m: &GltfMaterial, file: &str) -> Material {
    let [r, g, b, a] = m.base_color;
    let base = Vec3::new(r, g, b);
    let (alpha_test, alpha_ref) = match m.alpha {
        // The shader tests the texture's alpha; the factor's a scales it.
        AlphaMode::Mask(cutoff) if a > 0.0 => (AlphaTest::Gequal, (cutoff / a).min(1.0)),
        AlphaMode::Mask(_) => (AlphaTest::Never, 0.5),
        _ => (AlphaTest::Always, 0.5),
    };
    let sampled = (m.base_texture.as_ref())
        .or(m.normal_texture.as_ref())
        .or(m.metallic_roughness_texture.as_ref())
        .or(m.occlusion_texture.as_ref())
        .or(m.emissive_texture.as_ref());
    let path = |t: &Option<GltfTexture>| t.as_ref().map(|t| t.path.clone());
    Material {
        name: format!("{file}#{}", m.name),
        diffuse: base * (1.0 - m.metallic),
        diffuse_texture: m.base_texture.as_ref().map(|t| t.path.clone()),
        normal_map: m.normal_texture.as_ref().map(|t| t.path.clone()),
        specular: Vec3::ZERO,
        shininess: 32.0,
        microfacet: Some(microfacet(m.metallic, m.roughness, base)),
        alpha_test,
        alpha_ref,
        opacity: if m.alpha == AlphaMode::Blend { a } else { 1.0 },
        reflectivity: 0.0,
        depth_func: None,
        cull: if m.double_sided {
            Cull::None
        } else {
            Cull::Back
        },
        winding: Winding::Ccw,
        texturing: sampled.map_or_else(Texturing::default, texturing),
        normal_scale: m.normal_scale,
        pbr: PbrMaps {
            metallic_roughness: path(&m.metallic_roughness_texture),
            base,
            metallic: m.metallic,
            roughness: m.roughness,
            occlusion: path(&m.occlusion_texture),
            occlusion_strength: m.occlusion_strength,
            emissive: Vec3::from(m.emissive),
            emissive_map: path(&m.emissive_texture),
        },
        ..Material::default()
    }
}

/// The sampler and uv transform of `t`.
fn texturing(t: &GltfTexture) -> Texturing {
    let wrap = t.wrap.map(|w| match w {
        glow::CLAMP_TO_EDGE => Wrap::Clamp,
        glow::MIRRORED_REPEAT => Wrap::Mirror,
        _ => Wrap::Repeat,
    });
    let filter = match (t.min_filter, t.mag_filter) {
        (Some(glow::NEAREST), _) => TextureFilter::Nearest,
        (Some(glow::LINEAR), _) => TextureFilter::Bilinear,
        (Some(glow::NEAREST_MIPMAP_NEAREST), _) => TextureFilter::NearestMip,
        (Some(glow::LINEAR_MIPMAP_NEAREST), _) => TextureFilter::BilinearMip,
        (None, Some(glow::NEAREST)) => TextureFilter::Nearest,
        _ => TextureFilter::Trilinear,
    };
    Texturing {
        wrap,
        filter,
        uv_scale: t.uv_scale,
        uv_offset: t.uv_offset,
        ..Texturing::default()
    }
}

/// The file's materials in order, then glTF's default material (for
/// primitives that name none: white, metallic 1, roughness 1).
pub(super) fn materials(scene: &GltfScene, path: &Path) -> Vec<Material> {
    let file = path
        .file_name()
        .map_or_else(String::new, |f| f.to_string_lossy().into_owned());
    let default = GltfMaterial {
        name: "default".into(),
        base_color: [1.0; 4],
        base_texture: None,
        metallic: 1.0,
        roughness: 1.0,
        normal_texture: None,
        normal_scale: 1.0,
        metallic_roughness_texture: None,
        occlusion_texture: None,
        occlusion_strength: 1.0,
        emissive: [0.0; 3],
        emissive_texture: None,
        alpha: AlphaMode::Opaque,
        double_sided: false,
    };
    (scene.materials.iter().chain([&default]))
        .map(|m| material(m, &file))
        .collect()
}
