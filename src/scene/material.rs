//! A material: the Phong terms of notes 01 §8.3 or notes 03's microfacet
//! triple, its texture and how it is sampled (§5), and the fragment tests
//! its objects use (§3.4, notes 05).
//!
//! ```toml
//! [materials.bunny]
//! diffuse = [0.4, 0.3, 0.2]
//! model = "microfacet"   # or "phong", the default
//! alpha = 0.3            # GGX width, 1e-3..=1e3 (notes 03 "Geometry Pass")
//! eta = 1.5              # index of refraction, 1..=10
//! k_s = 1.0              # the specular weight, 0..=10
//! ```
//!
//! A Phong material's `specular` and `shininess` drive the Phong lobe; a
//! microfacet material's highlight is k_s times Cook-Torrance's f_s
//! (src/lighting/microfacet.rs), white as a dielectric's is, and `specular`
//! and `shininess` are unused (setting them is an error, as is giving
//! alpha, eta or k_s to a Phong material).

use super::file::MaterialFile;
use super::texturing::{Texturing, Wrap};
use super::{AlphaTest, Cull, DepthFunc, Winding};
use anyhow::{Result, bail};
use glam::Vec3;
use std::path::PathBuf;

pub use super::settings::{GBufferEncoding, GBufferNormals, Model};

/// Notes 03's material triple.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Microfacet {
    /// GGX's width alpha_g (not squared): 1e-3 is near a mirror, 1 is rough.
    pub alpha: f32,
    /// The index of refraction of a dielectric.
    pub eta: f32,
    /// The specular weight.
    pub k_s: f32,
}

impl Microfacet {
    pub const ALPHA: (f32, f32) = (1e-3, 1e3);
    pub const ETA: (f32, f32) = (1.0, 10.0);
    pub const K_S: (f32, f32) = (0.0, 10.0);

    /// The Blinn-Phong exponent whose lobe is as wide, 2 / alpha^2 - 2
    /// (Walter et al. 2007, section 5.2), in 1..=4096: the shininess the far
    /// field's error bound takes for a microfacet surface.
    pub fn equivalent_shininess(&self) -> f32 {
        (2.0 / (self.alpha * self.alpha) - 2.0).clamp(1.0, 4096.0)
    }
}

/// The triple of material `name` (None: a Phong material), checked.
pub(super) fn microfacet(name: &str, m: &MaterialFile) -> Result<Option<Microfacet>> {
    let key = |k: &str| format!("materials.{name}.{k}");
    let given = [("alpha", m.alpha), ("eta", m.eta), ("k_s", m.k_s)];
    match m.model.unwrap_or(Model::Phong) {
        Model::Phong => {
            if let Some((k, _)) = given.iter().find(|(_, v)| v.is_some()) {
                bail!(
                    "{}: {k} belongs to the microfacet model: add model = \"microfacet\" \
                     to the material",
                    key(k)
                );
            }
            Ok(None)
        }
        Model::Microfacet => {
            // (A value other than the default: the file cannot say more.)
            let specular_given = m.specular != super::file::spec_default();
            if specular_given || m.shininess != super::file::shininess_default() {
                let k = if specular_given {
                    "specular"
                } else {
                    "shininess"
                };
                bail!(
                    "{}: a microfacet material has no {k}: its highlight is k_s times the \
                     Cook-Torrance BRDF (use alpha, eta and k_s)",
                    key(k)
                );
            }
            let ranges = [Microfacet::ALPHA, Microfacet::ETA, Microfacet::K_S];
            let defaults = [0.3, 1.5, 1.0];
            let mut v = [0.0; 3];
            for (i, (k, x)) in given.iter().enumerate() {
                let x = x.unwrap_or(defaults[i]);
                let (lo, hi) = ranges[i];
                if !(x.is_finite() && (lo..=hi).contains(&x)) {
                    bail!("{}: expected a number in {lo}..={hi}, found {x}", key(k));
                }
                v[i] = x;
            }
            Ok(Some(Microfacet {
                alpha: v[0],
                eta: v[1],
                k_s: v[2],
            }))
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub diffuse: Vec3,
    pub diffuse_texture: Option<PathBuf>,
    /// A tangent-space normal map (notes 01 §8.4): linear RGB, (n + 1) / 2.
    pub normal_map: Option<PathBuf>,
    pub specular: Vec3,
    pub shininess: f32,
    /// Notes 03's triple: Some for a microfacet material, None for Phong.
    pub microfacet: Option<Microfacet>,
    /// Alpha test on the diffuse texture's alpha: op and reference (notes 05).
    pub alpha_test: AlphaTest,
    pub alpha_ref: f32,
    /// Alpha (notes 01 §4.5): 1 = opaque; below 1 the transparency pass draws it.
    pub opacity: f32,
    /// How much of the environment it mirrors (notes 03, Implementation:
    /// the skybox mirror reflection), 0..=1 (src/scene/skybox.rs).
    pub reflectivity: f32,
    /// The depth test for this material's objects (None: `render.depth_func`).
    pub depth_func: Option<DepthFunc>,
    /// The faces its objects cull (notes 01 §3.4).
    pub cull: Cull,
    /// Which winding its meshes' front faces have (notes 01 §3.4).
    pub winding: Winding,
    /// How its texture is sampled: wrap, filter, uv transform (notes 01 §5).
    pub texturing: Texturing,
    /// A specular map (an MTL's map_Ks; LearnOpenGL's "lighting maps"):
    /// linear RGB that multiplies the specular colour (or k_s) per texel;
    /// sampled like the diffuse texture.
    pub specular_map: Option<PathBuf>,
    /// The normal map's strength (an MTL's `-bm`, glTF's normalTexture
    /// scale): the map's x and y are multiplied by it before normalising.
    pub normal_scale: f32,
    /// An alpha map (an MTL's map_d): its first channel replaces the
    /// diffuse texture's alpha (a white texture when there is none), so the
    /// alpha test, the shadow pass's included, reads it.
    pub alpha_map: Option<PathBuf>,
    /// glTF 2.0's maps beyond the base colour and the normal map
    /// (src/scene/gltf_material.rs; docs/gltf.md has the formulas).
    pub pbr: PbrMaps,
    /// A height map (linear greyscale, white high) for parallax mapping
    /// (lighting/parallax_mapping.rs), and the depth of its relief in
    /// texture uv units (black lies `height_scale` below white).
    pub height_map: Option<PathBuf>,
    pub height_scale: f32,
}

/// glTF 2.0's metallic-roughness, occlusion and emissive maps and factors
/// (the specification's §3.9). Without a metallic-roughness map the
/// material's `diffuse` and `microfacet` already hold the factors' mapping;
/// with one the shader takes it per texel (glsl/common/material.glsl).
#[derive(Clone, Debug, PartialEq)]
pub struct PbrMaps {
    /// metallicRoughnessTexture: B multiplies `metallic`, G `roughness`;
    /// linear data.
    pub metallic_roughness: Option<PathBuf>,
    /// baseColorFactor.rgb (linear), metallicFactor and roughnessFactor.
    pub base: Vec3,
    pub metallic: f32,
    pub roughness: f32,
    /// occlusionTexture (R, linear): the ambient term is multiplied by
    /// 1 + strength (R - 1).
    pub occlusion: Option<PathBuf>,
    pub occlusion_strength: f32,
    /// Emitted light, linear: emissiveFactor, times emissiveTexture (sRGB)
    /// where there is one.
    pub emissive: Vec3,
    pub emissive_map: Option<PathBuf>,
}

impl Default for PbrMaps {
    /// No maps, no emission.
    fn default() -> Self {
        PbrMaps {
            metallic_roughness: None,
            base: Vec3::ONE,
            metallic: 1.0,
            roughness: 1.0,
            occlusion: None,
            occlusion_strength: 1.0,
            emissive: Vec3::ZERO,
            emissive_map: None,
        }
    }
}

impl Default for Material {
    /// gloss's default material (material 0: what an object without
    /// `material` is drawn with).
    fn default() -> Self {
        Material {
            name: "default".into(),
            diffuse: Vec3::splat(0.6),
            diffuse_texture: None,
            normal_map: None,
            specular: Vec3::splat(0.3),
            shininess: 32.0,
            microfacet: None,
            alpha_test: AlphaTest::Always,
            alpha_ref: 0.5,
            opacity: 1.0,
            reflectivity: 0.0,
            depth_func: None,
            cull: Cull::Back,
            winding: Winding::Ccw,
            texturing: Default::default(),
            specular_map: None,
            normal_scale: 1.0,
            alpha_map: None,
            pbr: PbrMaps::default(),
            height_map: None,
            height_scale: 0.05,
        }
    }
}

impl Material {
    /// Drawn by the transparency pass, not by the opaque passes.
    pub fn is_transparent(&self) -> bool {
        self.opacity < 1.0
    }

    /// Samples a texture: a diffuse texture or any map.
    pub fn is_textured(&self) -> bool {
        self.diffuse_texture.is_some()
            || self.normal_map.is_some()
            || self.specular_map.is_some()
            || self.alpha_map.is_some()
            || self.height_map.is_some()
            || self.pbr.metallic_roughness.is_some()
            || self.pbr.occlusion.is_some()
            || self.pbr.emissive_map.is_some()
    }
}

/// Check the sampling keys of material `name` (src/scene/file.rs): how its texture
/// is sampled (src/scene/texturing.rs), checked here with the rest of the
/// material so that texturing.rs, which the file's tables use, does not
/// import the file.
pub(super) fn texturing(name: &str, f: &MaterialFile) -> Result<Texturing> {
    let key = |k: &str| format!("materials.{name}.{k}");
    let mut t = Texturing::default();
    if let Some(v) = &f.wrap {
        t.wrap = wrap(v).map_err(|e| anyhow::anyhow!("{}: {e}", key("wrap")))?;
    }
    if let Some(filter) = f.filter {
        t.filter = filter;
    }
    if let Some(a) = f.anisotropy {
        if !(a.is_finite() && (1.0..=16.0).contains(&a)) {
            bail!(
                "{}: expected a number in 1..=16 (samples along the footprint), found {a}",
                key("anisotropy")
            );
        }
        t.anisotropy = a;
    }
    if let Some(l) = f.max_lod {
        if !(l.is_finite() && (0.0..=1000.0).contains(&l)) {
            bail!(
                "{}: expected a mip level in 0..=1000, found {l}",
                key("max_lod")
            );
        }
        t.max_lod = l;
    }
    for (k, v, out) in [
        ("uv_scale", f.uv_scale, &mut t.uv_scale),
        ("uv_offset", f.uv_offset, &mut t.uv_offset),
    ] {
        if let Some(v) = v {
            if v.iter().any(|x| !x.is_finite() || x.abs() > 1e6) {
                bail!(
                    "{}: expected finite numbers within ±1e6, found {v:?}",
                    key(k)
                );
            }
            if k == "uv_scale" && v.contains(&0.0) {
                bail!(
                    "{}: a scale of 0 squeezes the texture to one texel; expected nonzero numbers, found {v:?}",
                    key(k)
                );
            }
            *out = v;
        }
    }
    Ok(t)
}

fn wrap(v: &toml::Value) -> Result<[Wrap; 2]> {
    let word = |v: &toml::Value| -> Result<Wrap> {
        let s = v
            .as_str()
            .ok_or_else(|| anyhow::anyhow!("expected a word, found {v}"))?;
        Wrap::ALL
            .iter()
            .copied()
            .find(|w| w.name() == s)
            .ok_or_else(|| anyhow::anyhow!("expected clamp, repeat or mirror, found \"{s}\""))
    };
    match v {
        toml::Value::Array(a) if a.len() == 2 => Ok([word(&a[0])?, word(&a[1])?]),
        toml::Value::Array(a) => {
            bail!("expected one word or two ([s, t]), found {} words", a.len())
        }
        v => Ok([word(v)?; 2]),
    }
}
