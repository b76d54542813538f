//! The light pre-pass's combine programs (notes 02, Deferred lighting; the
//! pass is deferred_lighting.rs): which program an object is drawn with and
//! its `#define`s, one decision for the pass and for `gloss plan`. Like the
//! G-buffer's (gbuffer.rs): the scene's `MaterialVariant`, and
//! `NO_ALPHA_TEST` for an object whose material tests no alpha
//! (`render.specialize = false`: the general program for every object).

use crate::frame::gbuffer::MaterialVariant;
use crate::frame::material_variant::tests_alpha;
use crate::frame::shadows;
use crate::scene::Scene;

/// What a combine program is built for: tinting by the cascade
/// (shadow.cascade_colors), the material variant, and the alpha test.
pub type CombineNeeds = (bool, MaterialVariant, bool);

/// Which combine program: the tints, the alpha test, the material variant.
pub fn combine_index((tints, material, alpha): CombineNeeds) -> usize {
    usize::from(tints) * 16 + usize::from(alpha) * 8 + material.index()
}

/// The `#define`s of the combine program for `needs`: what the pass builds,
/// and what the plan names.
pub fn combine_defines((tints, material, alpha): CombineNeeds) -> Vec<(&'static str, String)> {
    let mut defines = material.defines();
    if !alpha {
        defines.push(("NO_ALPHA_TEST", "1".into()));
    }
    if tints {
        defines.push(("CASCADE_TINTS", "1".into()));
    }
    defines
}

/// The combine's needs for an object whose material's alpha test is
/// `alpha_test` (`DrawItem::alpha_test`).
pub fn combine_needs(scene: &Scene, alpha_test: i32) -> CombineNeeds {
    (
        shadows::cascade_tints(scene),
        MaterialVariant::of(scene),
        tests_alpha(scene.render.specialize, alpha_test),
    )
}

/// The combine's shaders.
pub const COMBINE_STAGES: [(u32, &str); 2] = [
    (glow::VERTEX_SHADER, "deferred/gbuffer.vert"),
    (
        glow::FRAGMENT_SHADER,
        "deferred/deferred_lighting_combine.frag",
    ),
];
