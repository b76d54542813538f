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
//! gloss's highlight is white: a metal keeps its F0's luminance and loses
//! its tint (the reader's one warning per file says so). MASK is the alpha
//! test `alpha >= alphaCutoff` (notes 05), BLEND the transparency pass with
//! opacity baseColor.a, doubleSided turns culling off; the base colour
//! texture's sampler and KHR_texture_transform become the material's
//! texturing.

use super::material::Microfacet;
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
    let sampled = m.base_texture.as_ref().or(m.normal_texture.as_ref());
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
        alpha: AlphaMode::Opaque,
        double_sided: false,
    };
    (scene.materials.iter().chain([&default]))
        .map(|m| material(m, &file))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::microfacet::brdf;
    use glam::DVec3;
    use std::f64::consts::PI;

    /// glTF 2.0's specular BRDF (Appendix B.3): Schlick's Fresnel from F0,
    /// GGX with alpha = roughness^2 and the height-correlated visibility
    /// V = 1 / (2 (n.l sqrt(n.v^2 (1 - a^2) + a^2) + n.v sqrt(n.l^2 (1 - a^2) + a^2))),
    /// written here from the specification, not from gloss's code.
    fn gltf_specular(l: DVec3, v: DVec3, n: DVec3, f0: f64, roughness: f64) -> f64 {
        let h = (l + v).normalize();
        let a2 = (roughness * roughness).powi(2);
        let (nl, nv, nh, vh) = (n.dot(l), n.dot(v), n.dot(h), v.dot(h));
        let f = f0 + (1.0 - f0) * (1.0 - vh).powi(5);
        let d = a2 / (PI * (nh * nh * (a2 - 1.0) + 1.0).powi(2));
        let vis = 0.5
            / (nl * (nv * nv * (1.0 - a2) + a2).sqrt() + nv * (nl * nl * (1.0 - a2) + a2).sqrt());
        f * d * vis
    }

    #[test]
    fn metallic_roughness_matches_gltfs_brdf_through_the_cpu_microfacet() {
        let n = DVec3::Z;
        let grey = Vec3::splat(0.7);
        for (metallic, base) in [(0.0, Vec3::new(0.8, 0.3, 0.1)), (0.5, grey), (1.0, grey)] {
            for roughness in [0.2f32, 0.5, 1.0] {
                let m = microfacet(metallic, roughness, base);
                let f0 = 0.04 * (1.0 - metallic as f64) + luminance(base) as f64 * metallic as f64;
                let ours =
                    |l: DVec3, v: DVec3| brdf(l, v, n, m.alpha as f64, m.eta as f64, m.k_s as f64);
                // Light from the eye (l = v = h): Fresnel at normal
                // incidence on the microfacet, where the mapping is exact.
                for deg in [0.0f64, 20.0, 45.0, 70.0] {
                    let t = deg.to_radians();
                    let l = DVec3::new(t.sin(), 0.0, t.cos());
                    let v = l;
                    let (a, b) = (ours(l, v), gltf_specular(l, v, n, f0, roughness as f64));
                    assert!(
                        (a - b).abs() <= 2e-5 * b,
                        "metallic {metallic} roughness {roughness} at {deg}°: {a} vs {b}"
                    );
                }
                // Off the mirror direction, v.h >= 0.9: within what
                // Schlick's fit differs from the exact Fresnel there.
                for (tl, tv) in [(10.0f64, 30.0f64), (0.0, 40.0), (30.0, 10.0)] {
                    let l = DVec3::new(tl.to_radians().sin(), 0.0, tl.to_radians().cos());
                    let v = DVec3::new(0.0, tv.to_radians().sin(), tv.to_radians().cos());
                    let h = (l + v).normalize();
                    assert!(v.dot(h) >= 0.9);
                    let (a, b) = (ours(l, v), gltf_specular(l, v, n, f0, roughness as f64));
                    assert!(
                        (a - b).abs() <= 0.03 * b,
                        "metallic {metallic} roughness {roughness} off the eye: {a} vs {b}"
                    );
                }
            }
        }
        // A metal has no diffuse; a dielectric keeps its base colour.
        let gm = |metallic: f32| GltfMaterial {
            name: "m".into(),
            base_color: [0.8, 0.3, 0.1, 1.0],
            base_texture: None,
            metallic,
            roughness: 0.5,
            normal_texture: None,
            alpha: AlphaMode::Opaque,
            double_sided: false,
        };
        assert_eq!(material(&gm(1.0), "f").diffuse, Vec3::ZERO);
        assert_eq!(material(&gm(0.0), "f").diffuse, Vec3::new(0.8, 0.3, 0.1));
    }
}
