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

use crate::frame::lights::FrameLights;
use crate::scene::{Falloff, LightKind, Scene};

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
        ]
    }

    /// In words, for `gloss plan`: "point + spot, notes falloff, no
    /// shadows, Phong", or "general" for every part.
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
        let shadows = if self.cascades {
            "shadows (cascaded)"
        } else if self.shadows {
            "shadows"
        } else {
            "no shadows"
        };
        let model = if self.microfacet {
            "Phong + microfacet"
        } else {
            "Phong"
        };
        format!("{types}, {falloff}, {shadows}, {model}")
    }
}
