//! src/frame/gbuffer.rs `MaterialVariant` with the G-buffer pass and the
//! composite (techniques/deferred/gbuffer.rs, composite.rs): their material
//! code compiled only where the scene has it.
//!
//! * the variant leaves out what the scene's materials lack, and keeps what
//!   they have (read from the scene files: default has no glTF map, the glTF
//!   scene's model has them, bump-mapping has normal maps), with the
//!   `#define`s that drop it; `render.specialize = false` keeps everything
//!   and defines nothing (the general shader);
//! * every specialised G-buffer and composite gives the general shader's
//!   image exactly (0 differing bytes) on the deferred scenes, the light
//!   pre-pass's thin G-buffer and the light volumes included;
//! * so does the G-buffer's split by alpha test (an object whose material
//!   tests nothing drawn with the program built with NO_ALPHA_TEST): the
//!   general shader runs the alpha test for every object, and atrium's and
//!   model-loading's alpha-tested leaves and banners are drawn between the
//!   untested objects in both;
//! * and so does the light pre-pass's combine, specialised alike
//!   (techniques/deferred/deferred_lighting.rs): atrium and model-loading
//!   on the pre-pass.

use crate::common;
use crate::with_path;
use gloss::frame::gbuffer::MaterialVariant;
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene};

/// `s` with its every material emitting (glTF's emissiveFactor) and
/// microfacet (a Phong pixel has no emission in the G-buffer).
fn emissive(mut s: Scene) -> Scene {
    for m in &mut s.materials {
        m.pbr.emissive = glam::Vec3::new(0.3, 0.1, 0.05);
        m.microfacet
            .get_or_insert(gloss::scene::material::Microfacet {
                alpha: 0.3,
                eta: 1.5,
                k_s: 1.0,
            });
    }
    s
}

#[test]
fn the_variant_drops_what_the_materials_lack() {
    let default = MaterialVariant::of(&common::scene("default.toml"));
    assert!(!default.pbr && !default.emission, "{default:?}");
    let defines = default.defines();
    assert!(
        defines.contains(&("NO_PBR", "1".to_string())),
        "{defines:?}"
    );
    assert!(
        defines.contains(&("NO_SPECULAR_MAP", "1".to_string())),
        "{defines:?}"
    );

    // No shipped model has glTF maps: an emissive factor turns u_pbr on.
    let glowing = emissive(common::scene("default.toml"));
    let v = MaterialVariant::of(&glowing);
    assert!(v.pbr && v.emission, "an emissive material: {v:?}");
    assert!(!v.defines().iter().any(|(k, _)| *k == "NO_PBR"));

    let mut bumps = common::scene("bump-mapping.toml");
    let v = MaterialVariant::of(&bumps);
    assert!(v.normal_map, "{v:?}");
    assert!(!v.defines().iter().any(|(k, _)| *k == "VARIANT_NORMAL_MAPS"));
    bumps.render.normal_mapping = false;
    let v = MaterialVariant::of(&bumps);
    assert!(!v.normal_map, "normal mapping off: {v:?}");
    assert!(
        v.defines()
            .contains(&("VARIANT_NORMAL_MAPS", "0".to_string()))
    );

    for name in ["default.toml", "gltf-scene.toml", "bump-mapping.toml"] {
        let mut s = common::scene(name);
        s.render.specialize = false;
        assert_eq!(MaterialVariant::of(&s), MaterialVariant::GENERAL, "{name}");
        assert!(MaterialVariant::GENERAL.defines().is_empty());
    }
}

#[test]
fn each_specialised_gbuffer_and_composite_gives_the_general_image() {
    let ctx = common::context(common::backend());
    for (name, path) in [
        ("default.toml", RenderPath::Deferred),
        ("deferred-shading.toml", RenderPath::Volumes),
        ("atrium.toml", RenderPath::Deferred),
        ("logl-like.toml", RenderPath::Deferred),
        ("gltf-scene.toml", RenderPath::Deferred),
        ("ibl.toml", RenderPath::Deferred),
        ("model-loading.toml", RenderPath::Volumes),
        ("ambient-occlusion.toml", RenderPath::Deferred),
        ("bump-mapping.toml", RenderPath::Deferred),
        ("deferred-shading.toml", RenderPath::Prepass),
        ("atrium.toml", RenderPath::Prepass),
        ("model-loading.toml", RenderPath::Prepass),
        ("model-loading.toml", RenderPath::Tiled),
        // The combine with image-based lighting and the ambient light pass.
        ("ibl.toml", RenderPath::Prepass),
        ("ambient-occlusion.toml", RenderPath::Prepass),
    ] {
        let mut special = with_path(&common::scene(name), path);
        // Emission goes in the specular attachment, which deferred-shading's
        // two specular colours keep.
        if name == "deferred-shading.toml" && path == RenderPath::Volumes {
            special = emissive(special);
        }
        special.render.size = (160, 90);
        let mut general = special.clone();
        general.render.specialize = false;
        let a = render_scene(&ctx, &special, Output::Srgb8).expect("specialised");
        let b = render_scene(&ctx, &general, Output::Srgb8).expect("general");
        let (a, b) = (a.read_image(), b.read_image());
        let differ = (a.pixels().zip(b.pixels())).filter(|(p, q)| p != q).count();
        eprintln!(
            "{name} {path:?} [{:?}]: {differ} pixels differ",
            MaterialVariant::of(&special)
        );
        assert_eq!(differ, 0, "{name} {path:?}: specialised != general");
    }
    ctx.debug.check(&ctx.gl, "the material variants").unwrap();
}
