//! Every program that includes glsl/common/material.glsl reads each of its
//! samplers on that sampler's own unit (src/frame/draw_textures.rs
//! `setup_program`, which `Programs` calls for every program it builds).
//!
//! glsl/common/material.glsl declares the glTF maps' samplers for every
//! geometry program; a material without them never sets their units, and a
//! sampler uniform left at GL's default reads unit 0, DIFFUSE_TEXTURE.
//! Their reads sit behind `u_pbr`, but llvmpipe runs a branch's texture
//! reads under a mask, so each one paid for the diffuse texture's filter
//! (4.5x the forward pass of scenes/texture-filtering.toml, docs/before-after.md).
//! The units are read back from the GL (glGetUniformiv) for every program the
//! forward pass used, Phong and Gouraud (flat shading reads no glTF map), and
//! for the G-buffer's, the light pre-pass's combine and the transparent
//! draws' (sorted, weighted blended, depth peeling).

use crate::common;
use gloss::frame::units::{
    DIFFUSE_TEXTURE, EMISSIVE_MAP, METAL_ROUGH_MAP, NORMAL_MAP, OCCLUSION_MAP, SPECULAR_MAP,
};
use gloss::scene::{RenderPath, Scene, Shading};
use gloss::trace::units::Sampler;
use gloss::trace::units::trace_with_samplers;
use std::collections::BTreeSet;

/// The programs technique `technique` used in a frame of `s`, by id, with
/// their sampler uniforms and the units they held at the frame's end.
fn programs_of(s: &Scene, technique: &str) -> Vec<(i64, Vec<Sampler>)> {
    let ctx = crate::tracing_context();
    let (calls, programs) = trace_with_samplers(&ctx, s).unwrap();
    let used: BTreeSet<i64> = (calls.iter())
        .filter(|c| c.function == "glUseProgram")
        .filter(|c| c.pass.as_ref().is_some_and(|p| p.technique == technique))
        .filter_map(|c| c.args.first()?.parse().ok())
        .filter(|&id| id != 0)
        .collect();
    assert!(!used.is_empty(), "no {technique} program");
    (used.into_iter())
        .map(|id| (id, programs[&id].clone()))
        .collect()
}

/// The sampler uniforms of the programs the forward pass of `s` used.
fn forward_samplers(s: &Scene) -> Vec<Vec<String>> {
    (programs_of(s, "forward").into_iter())
        .map(|(_, samplers)| samplers.into_iter().map(|s| s.name).collect())
        .collect()
}

/// material.glsl's samplers and their units (src/frame/units.rs).
const MATERIAL_UNITS: [(&str, u32); 6] = [
    ("u_diffuse_texture", DIFFUSE_TEXTURE),
    ("u_normal_map", NORMAL_MAP),
    ("u_specular_map", SPECULAR_MAP),
    ("u_metal_rough_map", METAL_ROUGH_MAP),
    ("u_occlusion_map", OCCLUSION_MAP),
    ("u_emissive_map", EMISSIVE_MAP),
];

/// The G-buffer's programs (full and the light pre-pass's thin one), the
/// pre-pass's combine, and the transparent draws' programs, general and
/// specialised: each material sampler the GL reports reads its own unit.
/// The general shaders have the glTF maps' samplers (else this would check
/// nothing of what moved).
#[test]
fn every_program_with_material_code_reads_each_map_on_its_own_unit() {
    let cases = [
        (
            "texture-filtering.toml",
            Some(RenderPath::Deferred),
            "gbuffer",
        ),
        (
            "texture-filtering.toml",
            Some(RenderPath::Prepass),
            "gbuffer",
        ),
        (
            "texture-filtering.toml",
            Some(RenderPath::Prepass),
            "deferred_lighting",
        ),
        (
            "texture-filtering.toml",
            Some(RenderPath::Forward),
            "forward",
        ),
        ("transparency.toml", None, "transparency"),
        ("oit.toml", None, "weighted_blended"),
        ("oit-depth-peeling.toml", None, "depth_peeling"),
    ];
    for (name, path, technique) in cases {
        for specialize in [false, true] {
            let mut s = common::scene(name);
            if let Some(path) = path {
                s.render.path = path;
            }
            s.render.size = (48, 27);
            s.render.specialize = specialize;
            let with_material: Vec<_> = (programs_of(&s, technique).into_iter())
                .filter(|(_, samplers)| samplers.iter().any(|x| x.name == "u_diffuse_texture"))
                .collect();
            let case = format!("{name} ({path:?}, {technique}, specialize {specialize})");
            assert!(
                !with_material.is_empty(),
                "{case}: no program with material code"
            );
            for (id, samplers) in with_material {
                let names: Vec<&str> = samplers.iter().map(|x| x.name.as_str()).collect();
                if !specialize {
                    for map in ["u_metal_rough_map", "u_occlusion_map", "u_emissive_map"] {
                        assert!(
                            names.contains(&map),
                            "{case}: program {id} has no {map}: {names:?}"
                        );
                    }
                }
                for x in &samplers {
                    if let Some((_, u)) = MATERIAL_UNITS.iter().find(|(n, _)| *n == x.name) {
                        assert_eq!(
                            x.unit_at_end, *u as i32,
                            "{case}: program {id}'s {} reads unit {}, not its own {u}",
                            x.name, x.unit_at_end
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn forward_programs_read_the_diffuse_unit_only_through_the_diffuse_texture() {
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
        for (id, samplers) in programs_of(&s, "forward") {
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
    let gltf_samplers = ["u_metal_rough_map", "u_occlusion_map", "u_emissive_map"];
    for shading in [Shading::Phong, Shading::Gouraud] {
        let mut s = common::scene("texture-atlas.toml");
        s.render.shading = shading;
        s.render.size = (48, 27);
        let plan = gloss::techniques::plan(&s).to_string();
        assert!(!plan.contains("glTF maps"), "{plan}");
        for names in forward_samplers(&s) {
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
        for names in forward_samplers(&s) {
            assert!(
                names.contains(&"u_metal_rough_map".to_string()),
                "{shading:?}: {names:?}"
            );
        }
    }
}
