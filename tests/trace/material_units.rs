//! The forward pass reads the diffuse texture's unit through
//! `u_diffuse_texture` alone (src/frame/draw_textures.rs `setup_program`).
//!
//! glsl/common/material.glsl declares the glTF maps' samplers for every
//! geometry program; a material without them never sets their units, and a
//! sampler uniform left at GL's default reads unit 0, DIFFUSE_TEXTURE.
//! Their reads sit behind `u_pbr`, but llvmpipe runs a branch's texture
//! reads under a mask, so each one paid for the diffuse texture's filter
//! (4.5x the forward pass of scenes/texture-filtering.toml, docs/before-after.md).
//! The units are read back from the GL (glGetUniformiv) for every program the
//! forward pass used, Phong and Gouraud (flat shading reads no glTF map).

use crate::common;
use gloss::frame::units::DIFFUSE_TEXTURE;
use gloss::scene::{Scene, Shading};
use gloss::trace::units::{Sampler, trace_with_samplers};
use std::collections::BTreeSet;

/// The programs the forward pass of `s` used, each with its sampler
/// uniforms, read back from the GL.
fn forward_programs(ctx: &gloss::gl::Headless, s: &Scene) -> Vec<(i64, Vec<Sampler>)> {
    let (calls, mut programs) = trace_with_samplers(ctx, s).unwrap();
    let used: BTreeSet<i64> = (calls.iter())
        .filter(|c| c.function == "glUseProgram")
        .filter(|c| c.pass.as_ref().is_some_and(|p| p.technique == "forward"))
        .filter_map(|c| c.args.first()?.parse().ok())
        .filter(|&id| id != 0)
        .collect();
    assert!(!used.is_empty(), "{}: no forward program", s.name);
    (used.into_iter())
        .map(|id| (id, programs.remove(&id).unwrap()))
        .collect()
}

/// The names of the sampler uniforms of each program the forward pass of
/// `s` used.
fn forward_samplers(ctx: &gloss::gl::Headless, s: &Scene) -> Vec<Vec<String>> {
    (forward_programs(ctx, s).into_iter())
        .map(|(_, samplers)| samplers.into_iter().map(|s| s.name).collect())
        .collect()
}

#[test]
fn forward_programs_read_the_diffuse_unit_only_through_the_diffuse_texture() {
    let ctx = crate::tracing_context();
    let cases = [
        ("texture-filtering.toml", Shading::Phong),
        ("texture-atlas.toml", Shading::Phong),
        ("shading-gouraud.toml", Shading::Gouraud),
        ("texture-atlas.toml", Shading::Gouraud),
    ];
    for (name, shading) in cases {
        let mut s = common::scene(name);
        s.render.shading = shading;
        s.render.size = (48, 27);
        // The general shader, which has the glTF code (a frame without glTF
        // maps leaves it out: tests below).
        s.render.specialize = false;
        for (id, samplers) in forward_programs(&ctx, &s) {
            let names: Vec<&str> = samplers.iter().map(|s| s.name.as_str()).collect();
            // The program has the glTF maps' samplers (else this checks nothing).
            // Gouraud's fragment stage reads the metallic-roughness map
            // alone (material_diffuse); Phong's all three.
            let maps: &[&str] = match shading {
                Shading::Gouraud => &["u_metal_rough_map"],
                _ => &["u_metal_rough_map", "u_occlusion_map", "u_emissive_map"],
            };
            for map in maps {
                assert!(
                    names.contains(map),
                    "{name} ({shading:?}): program {id} has no {map}: {names:?}"
                );
            }
            let on_diffuse: Vec<&str> = (samplers.iter())
                .filter(|s| s.unit_at_end == DIFFUSE_TEXTURE as i32)
                // IBL_BRDF_OFF names unit 0 on purpose (src/frame/units.rs):
                // not this file's to move.
                .filter(|s| s.name != "u_ibl_brdf")
                .map(|s| s.name.as_str())
                .collect();
            assert_eq!(
                on_diffuse,
                ["u_diffuse_texture"],
                "{name} ({shading:?}): program {id}'s samplers on unit {DIFFUSE_TEXTURE} \
                 (the diffuse texture's), of {names:?}"
            );
        }
    }
}

/// The lighting variant leaves material.glsl's glTF code out of the forward
/// programs of a frame with no glTF map or emission (VARIANT_FORWARD_GLTF 0:
/// the maps' samplers are not in the linked program), keeps it where a
/// material emits, and `gloss plan` says which.
#[test]
fn the_forward_variant_has_the_gltf_code_only_where_a_material_needs_it() {
    let ctx = crate::tracing_context();
    let gltf_samplers = ["u_metal_rough_map", "u_occlusion_map", "u_emissive_map"];
    for shading in [Shading::Phong, Shading::Gouraud] {
        let mut s = common::scene("texture-atlas.toml");
        s.render.shading = shading;
        s.render.size = (48, 27);
        let plan = gloss::techniques::plan(&s).to_string();
        assert!(!plan.contains("glTF maps"), "{plan}");
        for names in forward_samplers(&ctx, &s) {
            assert!(
                names.contains(&"u_diffuse_texture".to_string()),
                "{names:?}"
            );
            for map in gltf_samplers {
                assert!(
                    !names.contains(&map.to_string()),
                    "{shading:?}: {map} in {names:?}"
                );
            }
        }
        // One material emits: the code is back, and the plan names it.
        s.materials[s.objects[0].material].pbr.emissive = glam::Vec3::new(0.2, 0.1, 0.0);
        let plan = gloss::techniques::plan(&s).to_string();
        assert!(plan.contains("glTF maps"), "{plan}");
        for names in forward_samplers(&ctx, &s) {
            assert!(
                names.contains(&"u_metal_rough_map".to_string()),
                "{shading:?}: {names:?}"
            );
        }
    }
}
