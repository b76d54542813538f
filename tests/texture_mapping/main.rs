//! Texture mapping (notes 01 §5): the wrap rules on the notes' own
//! examples, bilinear filtering on the notes' 7.6, the mip level the level
//! of detail picks, and perspective-correct against affine texture
//! coordinates, each held to its CPU twin (src/math/texture_mapping.rs).

#[path = "../common/mod.rs"]
mod common;

mod atlas;
mod filtering;
mod hard_cases;
mod interpolation;
mod mip_mapping;
mod trilinear;
mod wrap;

use gloss::scene::Scene;

/// A scene from TOML text, as if it were the file scenes/t.toml.
pub fn scene(text: &str) -> Scene {
    Scene::parse(text, &common::root().join("scenes/t.toml"))
        .unwrap_or_else(|e| panic!("test scene: {e:#}"))
}

/// The ramp texture's texel (s, t) read back from a displayed pixel: red is
/// 4 s + 2 and green 4 t + 2 (scenes/assets/generate.rs, `uv_ramp`).
pub fn ramp_texel(p: &image::Rgba<u8>) -> (i64, i64) {
    let t = |c: u8| ((f64::from(c) - 2.0) / 4.0).round() as i64;
    (t(p[0]), t(p[1]))
}
