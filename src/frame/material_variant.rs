//! The G-buffer pass's and the composite's material variant: which parts of
//! glsl/common/material.glsl the scene's materials need.

/// Which material code the G-buffer pass and the composite compile: the
/// parts some drawn material needs (glsl/common/material.glsl). llvmpipe
/// runs the code behind a uniform branch even where the uniform is false,
/// so a scene with no glTF map pays for them all unless they are left out
/// (`NO_PBR`, `NO_SPECULAR_MAP`, `VARIANT_NORMAL_MAPS = 0`; the composite's
/// `NO_EMISSION`). `render.specialize = false`: every part, the general
/// shader (built without these defines).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialVariant {
    /// Some material has a glTF metallic-roughness, occlusion or emissive
    /// map, or an emissive factor (`u_pbr`).
    pub pbr: bool,
    /// Some material has a specular map.
    pub specular_map: bool,
    /// Some material has a normal map and `render.normal_mapping` is on.
    pub normal_map: bool,
    /// Some material emits light (an emissive factor): the composite adds it.
    pub emission: bool,
}

impl MaterialVariant {
    /// Every part, whatever the scene holds.
    pub const GENERAL: MaterialVariant = MaterialVariant {
        pbr: true,
        specular_map: true,
        normal_map: true,
        emission: true,
    };

    /// The parts `scene`'s objects' materials need.
    pub fn of(scene: &crate::scene::Scene) -> MaterialVariant {
        if !scene.render.specialize {
            return MaterialVariant::GENERAL;
        }
        let materials = || (scene.objects.iter()).map(|o| &scene.materials[o.material]);
        let emits = |m: &crate::scene::material::Material| m.pbr.emissive != glam::Vec3::ZERO;
        MaterialVariant {
            pbr: materials().any(|m| {
                m.pbr.metallic_roughness.is_some()
                    || m.pbr.occlusion.is_some()
                    || m.pbr.emissive_map.is_some()
                    || emits(m)
            }),
            specular_map: materials().any(|m| m.specular_map.is_some()),
            normal_map: scene.render.normal_mapping && materials().any(|m| m.normal_map.is_some()),
            emission: materials().any(emits),
        }
    }

    /// The G-buffer pass's `#define`s: none for every part.
    pub fn defines(&self) -> Vec<(&'static str, String)> {
        [
            (!self.pbr, "NO_PBR", "1"),
            (!self.specular_map, "NO_SPECULAR_MAP", "1"),
            (!self.normal_map, "VARIANT_NORMAL_MAPS", "0"),
        ]
        .into_iter()
        .filter(|(drop, _, _)| *drop)
        .map(|(_, k, v)| (k, v.to_string()))
        .collect()
    }

    /// Its index among the G-buffer pass's 8 programs of one layout.
    pub fn index(&self) -> usize {
        usize::from(self.pbr) * 4
            + usize::from(self.specular_map) * 2
            + usize::from(self.normal_map)
    }
}

/// Whether the opaque objects are drawn with a program without the alpha
/// test (false), with it (true), or both: the G-buffer's (techniques/deferred/gbuffer.rs)
/// and the light pre-pass's combine (deferred_lighting.rs) decide alike, per object by
/// [`tests_alpha`].
pub fn alpha_programs(scene: &crate::scene::Scene) -> std::collections::BTreeSet<bool> {
    (scene.objects.iter())
        .map(|o| &scene.materials[o.material])
        .filter(|m| !m.is_transparent())
        .map(|m| tests_alpha(scene.render.specialize, m.alpha_test.code()))
        .collect()
}

/// Whether an object whose material's alpha test is `alpha_test`
/// (`AlphaTest::code`, `DrawItem::alpha_test`) is drawn with the program
/// that tests: always with `render.specialize` off.
pub fn tests_alpha(specialize: bool, alpha_test: i32) -> bool {
    !specialize || alpha_test != crate::scene::AlphaTest::Always.code()
}
