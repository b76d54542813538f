//! The light pre-pass's combine programs (notes 02, Deferred lighting; the
//! pass is deferred_lighting.rs): which program an object is drawn with and
//! its `#define`s, one decision for the pass and for `gloss plan`. Like the
//! G-buffer's (gbuffer.rs): the scene's `MaterialVariant`, and
//! `NO_ALPHA_TEST` for an object whose material tests no alpha; like the
//! composite's (composite.rs), `NO_IBL` and `NO_AMBIENT_OCCLUSION` where
//! the scene has no image-based lighting or ambient light pass
//! (`render.specialize = false`: the general program for every object).

use super::ambient_light;
use crate::frame::gbuffer::MaterialVariant;
use crate::frame::image_based_lighting;
use crate::frame::material_variant::tests_alpha;
use crate::frame::shadows;
use crate::scene::Scene;

/// What a combine program is built for: tinting by the cascade
/// (shadow.cascade_colors), the material variant, the alpha test, the
/// image-based lighting code and the ambient light pass's occlusion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CombineNeeds {
    pub tints: bool,
    pub material: MaterialVariant,
    pub alpha: bool,
    pub ibl: bool,
    pub ambient_occlusion: bool,
}

impl CombineNeeds {
    /// What `scene`'s combine needs for objects that test alpha (`alpha`)
    /// or not: one decision for the pass and for the plan.
    pub fn of(scene: &Scene, alpha: bool) -> CombineNeeds {
        let general = !scene.render.specialize;
        CombineNeeds {
            tints: shadows::cascade_tints(scene),
            material: MaterialVariant::of(scene),
            alpha,
            ibl: general || image_based_lighting::wanted(scene),
            ambient_occlusion: general || ambient_light::result_target(scene).is_some(),
        }
    }

    /// Which combine program, of 128.
    pub fn index(&self) -> usize {
        let flags = [self.tints, self.ibl, self.ambient_occlusion, self.alpha];
        flags.iter().fold(0, |i, &on| i * 2 + usize::from(on)) * 8 + self.material.index()
    }

    /// The `#define`s of its program: what the pass builds, and what the
    /// plan names.
    pub fn defines(&self) -> Vec<(&'static str, String)> {
        let mut defines = self.material.defines();
        let flags = [
            (!self.alpha, "NO_ALPHA_TEST"),
            (self.tints, "CASCADE_TINTS"),
            (!self.ibl, "NO_IBL"),
            (!self.ambient_occlusion, "NO_AMBIENT_OCCLUSION"),
        ];
        let on = flags.into_iter().filter(|(on, _)| *on);
        defines.extend(on.map(|(_, name)| (name, "1".to_string())));
        defines
    }
}

/// The combine's needs for an object whose material's alpha test is
/// `alpha_test` (`DrawItem::alpha_test`).
pub fn combine_needs(scene: &Scene, alpha_test: i32) -> CombineNeeds {
    CombineNeeds::of(scene, tests_alpha(scene.render.specialize, alpha_test))
}

/// The combine's shaders.
pub const COMBINE_STAGES: [(u32, &str); 2] = [
    (glow::VERTEX_SHADER, "deferred/gbuffer.vert"),
    (
        glow::FRAGMENT_SHADER,
        "deferred/deferred_lighting_combine.frag",
    ),
];
