//! A material: the Phong terms of notes 01 §8.3, its texture and how it is
//! sampled (§5), and the fragment tests its objects use (§3.4, notes 05).

use super::{AlphaTest, Cull, DepthFunc, Winding, texturing};
use glam::Vec3;
use std::path::PathBuf;

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub diffuse: Vec3,
    pub diffuse_texture: Option<PathBuf>,
    /// A tangent-space normal map (notes 01 §8.4): linear RGB, (n + 1) / 2.
    pub normal_map: Option<PathBuf>,
    pub specular: Vec3,
    pub shininess: f32,
    /// Alpha test on the diffuse texture's alpha: op and reference (notes 05).
    pub alpha_test: AlphaTest,
    pub alpha_ref: f32,
    /// Alpha (notes 01 §4.5): 1 = opaque; below 1 the transparency pass draws it.
    pub opacity: f32,
    /// The depth test for this material's objects (None: `render.depth_func`).
    pub depth_func: Option<DepthFunc>,
    /// The faces its objects cull (notes 01 §3.4).
    pub cull: Cull,
    /// Which winding its meshes' front faces have (notes 01 §3.4).
    pub winding: Winding,
    /// How its texture is sampled: wrap, filter, uv transform (notes 01 §5).
    pub texturing: texturing::Texturing,
}

impl Material {
    /// Drawn by the transparency pass, not by the opaque passes.
    pub fn is_transparent(&self) -> bool {
        self.opacity < 1.0
    }
}
