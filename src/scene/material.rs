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
use super::settings::setting;
use super::{AlphaTest, Cull, DepthFunc, Winding, texturing};
use anyhow::{Result, bail};
use glam::Vec3;
use std::path::PathBuf;

setting! {
    /// Which reflectance model a material uses.
    pub enum Model {
        /// Notes 01 §8.3: k_d (N . L) + k_s (N . H)^n.
        Phong = "phong",
        /// Notes 03: Cook-Torrance with GGX, dielectric Fresnel and Smith masking.
        Microfacet = "microfacet",
    }
}

setting! {
    /// How the G-buffer stores the microfacet triple (notes 03, Geometry
    /// Pass; src/math/gbuffer_encoding.rs measures each).
    pub enum GBufferEncoding {
        /// The report's: each value above 1 stored as its reciprocal with a
        /// flag in gConvert, gAlpha in 8 bits (UNORM) as the report's [0, 1]
        /// range implies.
        ReportRgba8 = "report_rgba8",
        /// The report's scheme with gAlpha in half floats.
        ReportRgba16f = "report_rgba16f",
        /// The plain values in half floats: no gConvert attachment.
        PlainRgba16f = "plain_rgba16f",
    }
}

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
    pub texturing: texturing::Texturing,
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
    /// A height map (linear greyscale, white high) for parallax mapping
    /// (lighting/parallax_mapping.rs), and the depth of its relief in
    /// texture uv units (black lies `height_scale` below white).
    pub height_map: Option<PathBuf>,
    pub height_scale: f32,
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
    }
}
