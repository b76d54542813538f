//! Lighting shaders specialised to the frame: which parts of the general
//! lighting model (glsl/common/lighting.glsl) a scene's lights and materials
//! need. The general shader loops over every light evaluating every light
//! type, every falloff, the shadow casters and the microfacet material; a
//! software rasteriser runs both sides of a branch wherever any pixel of a
//! block takes either, so code a scene never needs still costs. A variant
//! leaves that code out with `#define`s, compiled from the same source.
//!
//! The plan names each lighting pass's variant (`gloss plan`); the renderer
//! builds a technique's programs once per variant and keeps them (a change
//! of settings that changes the variant builds or reuses the other set).
//! `render.specialize = false` gives the general shader, which is also what
//! a program built without these defines compiles.
//!
//! Besides the lights and the materials, the switches cover the shadow
//! lookup (how many maps of each kind, which filters: glsl/common/shadow.glsl
//! keeps one inlined copy of its filter per sampler, so a frame with one 2D
//! map drops seven), the normal maps and the G-buffer's material encoding.

use crate::frame::gbuffer;
use crate::frame::gbuffer_slim;
use crate::frame::light_halves;
use crate::frame::lights::FrameLights;
use crate::frame::shadows;
use crate::scene::shadows::Pcf;
use crate::scene::{Falloff, LightData, LightKind, Scene};

/// What one lighting variant evaluates. `GENERAL` is everything.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightingVariant {
    pub directional: bool,
    pub point: bool,
    pub spot: bool,
    /// Some light has the windowed falloff (render.falloff = "windowed").
    pub windowed: bool,
    /// Some light has notes 01's linear falloff (render.falloff = "linear").
    pub linear: bool,
    /// Some light casts a shadow (the caster loop and its lookups).
    pub shadows: bool,
    /// A directional light's map is split into cascades (glsl/shadows/cascaded_shadow_maps.glsl).
    pub cascades: bool,
    /// Some object's material is microfacet (opaque: the G-buffer has
    /// gAlpha; any: the forward pass shades it), so a pixel may need notes
    /// 03's BRDF rather than Phong's lobe.
    pub microfacet: bool,
    /// How many 2D shadow maps (directional and spot casters, 0-4) and
    /// cube maps (point casters, 0-4) the frame has: the lookup keeps one
    /// copy of its filter per map the frame has, none for a kind it lacks.
    pub shadow_maps_2d: u8,
    pub shadow_cubes: u8,
    /// Some caster filters with a 3x3 or 5x5 box, or the Poisson disc
    /// (`shadow.pcf`): the filter loops (none and hardware are one lookup).
    pub pcf_box: bool,
    pub pcf_poisson: bool,
    /// Some object's material has a normal map and `render.normal_mapping`
    /// is on: the forward pass reads it (the G-buffer pass is not a variant).
    pub normal_maps: bool,
    /// How the G-buffer holds the microfacet triple
    /// (src/frame/gbuffer.rs `material_code`): a compile-time constant for
    /// the lighting passes that read it, instead of `u_gbuffer_material`.
    pub gbuffer_material: i32,
    /// Tiled shading and the far field read the lights from the `Lights`
    /// uniform block (every light fits in it on every GL, and
    /// `render.light_block` is on) rather than from the buffer texture.
    pub light_block: bool,
    /// Tiled shading and the far field read the lights as packed halves
    /// (src/frame/light_halves.rs `code`: 0 none, 1 every value, 2 all but
    /// the position; `render.light_data`).
    pub light_halves: i32,
    /// The G-buffer is the packed one (octahedral normal + shininess index,
    /// src/frame/gbuffer.rs `octahedral`).
    pub gbuffer_octahedral: bool,
    /// The G-buffer has its specular attachment; false: the slim one, whose
    /// specular colour is a uniform (src/frame/gbuffer_slim.rs).
    pub gbuffer_specular: bool,
    /// Some object's material has a glTF metallic-roughness, occlusion or
    /// emissive map, or emits: the geometry shaders' glTF code
    /// (glsl/common/material.glsl behind `u_pbr`). Without it llvmpipe
    /// still ran that code's texture reads under a mask.
    pub forward_gltf: bool,
}

impl LightingVariant {
    /// The general model: every part, whatever the scene holds.
    pub const GENERAL: LightingVariant = LightingVariant {
        directional: true,
        point: true,
        spot: true,
        windowed: true,
        linear: true,
        shadows: true,
        cascades: true,
        microfacet: true,
        shadow_maps_2d: 4,
        shadow_cubes: 4,
        pcf_box: true,
        pcf_poisson: true,
        normal_maps: true,
        gbuffer_material: -1,
        light_block: false,
        light_halves: light_halves::code::NONE,
        gbuffer_octahedral: false,
        gbuffer_specular: true,
        forward_gltf: true,
    };

    /// The parts `scene` needs, or `GENERAL` with `render.specialize` off.
    /// The falloff flags follow `FrameLights::pack`: a light gets one only
    /// when it has a volume radius.
    pub fn of(scene: &Scene, lights: &FrameLights) -> LightingVariant {
        if !scene.render.specialize {
            return LightingVariant::GENERAL;
        }
        let has = |k: LightKind| scene.lights.iter().any(|l| l.kind == k);
        let with_radius = lights.lights.iter().any(|f| f.radius.is_some());
        let casters = shadows::casters(scene);
        let pcf = |k: &[Pcf]| casters.iter().any(|c| k.contains(&c.shadow.pcf));
        let material = match gbuffer::material_attachments(scene).len() {
            0 => gbuffer::material_code::NONE,
            1 => gbuffer::material_code::PLAIN,
            _ => gbuffer::material_code::REPORT,
        };
        LightingVariant {
            directional: has(LightKind::Directional),
            point: has(LightKind::Point),
            spot: has(LightKind::Spot),
            windowed: with_radius && scene.render.falloff == Falloff::Windowed,
            linear: with_radius && scene.render.falloff == Falloff::Linear,
            shadows: scene.lights.iter().any(|l| l.shadow.is_some()),
            cascades: (scene.lights.iter()).any(|l| l.shadow.is_some_and(|s| s.cascades > 1)),
            microfacet: (scene.objects.iter())
                .any(|o| scene.materials[o.material].microfacet.is_some()),
            shadow_maps_2d: casters.iter().filter(|c| !c.cube).count() as u8,
            shadow_cubes: casters.iter().filter(|c| c.cube).count() as u8,
            pcf_box: pcf(&[Pcf::Box3, Pcf::Box5]),
            pcf_poisson: pcf(&[Pcf::Poisson]),
            normal_maps: scene.render.normal_mapping
                && (scene.objects.iter()).any(|o| scene.materials[o.material].normal_map.is_some()),
            gbuffer_material: material,
            light_block: (scene.render.light_block || scene.render.light_data == LightData::Block)
                && scene.lights.len() <= crate::frame::lights::LIGHTS_ON_EVERY_GL,
            light_halves: if scene.render.light_block {
                light_halves::code::NONE
            } else {
                light_halves::code(scene)
            },
            gbuffer_octahedral: gbuffer::octahedral(scene),
            gbuffer_specular: gbuffer_slim::constant_specular(scene).is_none(),
            forward_gltf: (scene.objects.iter()).any(|o| gltf_code(&scene.materials[o.material])),
        }
    }

    /// The `#define`s glsl/common/lighting.glsl reads (none for `GENERAL`,
    /// whose program is the one built without them).
    pub fn defines(&self) -> Vec<(&'static str, String)> {
        if *self == LightingVariant::GENERAL {
            return vec![];
        }
        let b = |x: bool| if x { "1" } else { "0" }.to_string();
        vec![
            ("LIGHTING_VARIANT", "1".into()),
            ("VARIANT_DIRECTIONAL", b(self.directional)),
            ("VARIANT_POINT", b(self.point)),
            ("VARIANT_SPOT", b(self.spot)),
            ("VARIANT_WINDOWED", b(self.windowed)),
            ("VARIANT_LINEAR", b(self.linear)),
            ("VARIANT_SHADOWS", b(self.shadows)),
            ("VARIANT_CASCADES", b(self.cascades)),
            ("VARIANT_MICROFACET", b(self.microfacet)),
            ("VARIANT_SHADOW_2D", self.shadow_maps_2d.to_string()),
            ("VARIANT_SHADOW_CUBE", self.shadow_cubes.to_string()),
            ("VARIANT_PCF_BOX", b(self.pcf_box)),
            ("VARIANT_PCF_POISSON", b(self.pcf_poisson)),
            ("VARIANT_NORMAL_MAPS", b(self.normal_maps)),
            (
                "VARIANT_GBUFFER_MATERIAL",
                self.gbuffer_material.to_string(),
            ),
            ("VARIANT_LIGHT_BLOCK", b(self.light_block)),
            ("VARIANT_LIGHT_HALVES", self.light_halves.to_string()),
            ("VARIANT_GBUFFER_OCTAHEDRAL", b(self.gbuffer_octahedral)),
            ("VARIANT_GBUFFER_SPECULAR", b(self.gbuffer_specular)),
            ("VARIANT_FORWARD_GLTF", b(self.forward_gltf)),
        ]
    }

    /// In words, for `gloss plan`: "point + spot, notes falloff, no
    /// shadows, Phong", with what the shadows filter, the normal maps and
    /// the G-buffer's material encoding when there are any ("1 2D map, 3x3
    /// or 5x5 PCF"), or "general" for every part.
    pub fn describe(&self) -> String {
        if *self == LightingVariant::GENERAL {
            return "general (every light type, falloff, shadows, microfacet)".into();
        }
        let types: Vec<&str> = [
            (self.directional, "directional"),
            (self.point, "point"),
            (self.spot, "spot"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, n)| *n)
        .collect();
        let types = if types.is_empty() {
            "no lights".to_string()
        } else {
            types.join(" + ")
        };
        let falloff = match (self.windowed, self.linear) {
            (true, true) => "windowed + linear falloff",
            (true, false) => "windowed falloff",
            (false, true) => "linear falloff",
            (false, false) => "notes falloff",
        };
        let shadows = if self.shadows {
            let mut maps = Vec::new();
            if self.shadow_maps_2d > 0 {
                maps.push(format!("{} 2D", self.shadow_maps_2d));
            }
            if self.shadow_cubes > 0 {
                maps.push(format!("{} cube", self.shadow_cubes));
            }
            let filter = match (self.pcf_box, self.pcf_poisson) {
                (false, false) => "one-lookup PCF",
                (true, false) => "box PCF",
                (false, true) => "Poisson PCF",
                (true, true) => "box + Poisson PCF",
            };
            let n = self.shadow_maps_2d + self.shadow_cubes;
            let noun = if n == 1 { "map" } else { "maps" };
            let cascaded = if self.cascades { ", cascaded" } else { "" };
            format!("shadows ({} {noun}{cascaded}, {filter})", maps.join(" + "))
        } else {
            "no shadows".to_string()
        };
        let model = if self.microfacet {
            "Phong + microfacet"
        } else {
            "Phong"
        };
        let mut extra = String::new();
        if self.normal_maps {
            extra.push_str(", normal maps");
        }
        match self.gbuffer_material {
            gbuffer::material_code::PLAIN => extra.push_str(", plain G-buffer triple"),
            gbuffer::material_code::REPORT => extra.push_str(", report's G-buffer triple"),
            _ => {}
        }
        if self.light_block {
            extra.push_str(", lights from the uniform block");
        }
        match self.light_halves {
            light_halves::code::HALVES => extra.push_str(", lights as halves (2 texels a light)"),
            light_halves::code::FLOAT_POSITION => {
                extra.push_str(", lights as halves, positions float (3 texels a light)")
            }
            _ => {}
        }
        if self.gbuffer_octahedral {
            extra.push_str(", octahedral G-buffer normal");
        }
        if !self.gbuffer_specular {
            extra.push_str(", specular colour from a uniform (no G-buffer attachment)");
        }
        if self.forward_gltf {
            extra.push_str(", glTF maps");
        }
        format!("{types}, {falloff}, {shadows}, {model}{extra}")
    }
}

/// Material `m` needs material.glsl's glTF code: a map of glTF's or an
/// emission (src/frame/draw_textures.rs sets `u_pbr` for the same).
fn gltf_code(m: &crate::scene::material::Material) -> bool {
    let p = &m.pbr;
    p.metallic_roughness.is_some()
        || p.occlusion.is_some()
        || p.emissive_map.is_some()
        || p.emissive != glam::Vec3::ZERO
}
