//! `[ambient_occlusion]`: screen-space ambient occlusion (SSAO), notes 03,
//! "Ambient Light" (src/techniques/deferred/ambient_light.rs). Its knobs,
//! checked, and the knobs the demo's panel edits them with.
//!
//! ```toml
//! [ambient_occlusion]
//! samples = 16   # directions in the hemisphere, 1..=64
//! radius = 0.5   # r: what lies within r of a point occludes it (world units)
//! bias = 0.01    # a point counts as inside the geometry only this far behind it
//! blur = true    # the 4x4 blur that removes the rotation pattern
//! ```
//!
//! The table lives in the render settings (`RenderSettings::ambient_occlusion`)
//! so that the panel's knobs, which edit render settings, reach it. Only the
//! paths with a G-buffer run it: on the forward path it is a warning.

use super::RenderSettings;
use super::knobs::{Kind, Knob, Value};
use anyhow::{Result, bail};
use serde::Deserialize;

/// The most samples a pixel takes (the kernel is a uniform array of this
/// many vec3: 64 of GL 3.3's 1024 fragment uniform components x 4).
pub const MAX_SAMPLES: u32 = 64;

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub struct AmbientOcclusionFile {
    #[serde(default = "default_samples")]
    pub samples: u32,
    #[serde(default = "default_radius")]
    pub radius: f32,
    #[serde(default = "default_bias")]
    pub bias: f32,
    #[serde(default = "yes")]
    pub blur: bool,
}

fn default_samples() -> u32 {
    AmbientOcclusion::DEFAULT.samples
}
fn default_radius() -> f32 {
    AmbientOcclusion::DEFAULT.radius
}
fn default_bias() -> f32 {
    AmbientOcclusion::DEFAULT.bias
}
fn yes() -> bool {
    true
}

/// The scene's SSAO, checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmbientOcclusion {
    /// Directions per pixel (the kernel's size), 1..=MAX_SAMPLES.
    pub samples: u32,
    /// r: the AO of a point is the cosine-weighted fraction of its
    /// hemisphere's directions along which nothing lies within r.
    pub radius: f32,
    /// A sample counts as inside the geometry only when it lies more than
    /// this behind the visible surface (world units; 0 <= bias < radius).
    pub bias: f32,
    /// Blur the AO over 4x4 pixels (the rotation tile), depth-aware.
    pub blur: bool,
}

impl AmbientOcclusion {
    pub const DEFAULT: AmbientOcclusion = AmbientOcclusion {
        samples: 16,
        radius: 0.5,
        bias: 0.01,
        blur: true,
    };
}

/// Check `[ambient_occlusion]`.
pub(super) fn resolve(f: Option<&AmbientOcclusionFile>) -> Result<Option<AmbientOcclusion>> {
    let Some(a) = f else { return Ok(None) };
    if !(1..=MAX_SAMPLES).contains(&a.samples) {
        bail!(
            "ambient_occlusion.samples: expected 1..={MAX_SAMPLES} directions per pixel, found {}",
            a.samples
        );
    }
    if !(a.radius.is_finite() && a.radius > 0.0) {
        bail!(
            "ambient_occlusion.radius: expected a distance > 0 (world units), found {}",
            a.radius
        );
    }
    if !(a.bias.is_finite() && a.bias >= 0.0 && a.bias < a.radius) {
        bail!(
            "ambient_occlusion.bias: expected a distance in 0..radius ({}), found {}",
            a.radius,
            a.bias
        );
    }
    Ok(Some(AmbientOcclusion {
        samples: a.samples,
        radius: a.radius,
        bias: a.bias,
        blur: a.blur,
    }))
}

/// The warning for a scene whose path has no G-buffer (src/scene/warnings.rs).
pub(super) fn warning(r: &RenderSettings) -> Option<String> {
    (r.ambient_occlusion.is_some() && r.path == super::RenderPath::Forward).then(|| {
        "ambient_occlusion has no effect on the forward path: SSAO reads the G-buffer's depth and normals, which only the deferred paths have (the ambient term is not occluded)".to_string()
    })
}

/// Write the table as it is now into `table` ("save as"; the panel edits it).
pub(super) fn save(r: &RenderSettings, table: &mut toml::Table) {
    let Some(a) = r.ambient_occlusion else { return };
    let mut t = toml::Table::new();
    t.insert("samples".into(), toml::Value::Integer(a.samples.into()));
    t.insert("radius".into(), toml::Value::Float(a.radius.into()));
    t.insert("bias".into(), toml::Value::Float(a.bias.into()));
    t.insert("blur".into(), toml::Value::Boolean(a.blur));
    table.insert("ambient_occlusion".into(), toml::Value::Table(t));
}

fn get(r: &RenderSettings) -> AmbientOcclusion {
    r.ambient_occlusion.unwrap_or(AmbientOcclusion::DEFAULT)
}

/// Change the scene's table, if it has one (the panel shows these knobs
/// only when the technique runs, that is when it has).
fn set(r: &mut RenderSettings, f: impl FnOnce(&mut AmbientOcclusion)) {
    if let Some(a) = &mut r.ambient_occlusion {
        f(a);
    }
}

pub static SAMPLES: Knob = Knob {
    key: "ambient_occlusion.samples",
    label: "AO samples",
    help: "directions in the hemisphere per pixel (notes 03, Ambient Light: random points in the hemisphere); the 4x4 rotation tile and its blur make it 16 times as many",
    kind: Kind::Count {
        min: 1,
        max: MAX_SAMPLES,
    },
    get: |r| Value::Count(get(r).samples),
    set: |r, v| {
        if let Value::Count(n) = v {
            set(r, |a| a.samples = n);
        }
    },
};

pub static RADIUS: Knob = Knob {
    key: "ambient_occlusion.radius",
    label: "AO radius",
    help: "r: geometry within r of a point occludes it (world units)",
    kind: Kind::Number {
        min: 0.02,
        max: 5.0,
        log: true,
    },
    get: |r| Value::Number(get(r).radius),
    set: |r, v| {
        if let Value::Number(x) = v {
            set(r, |a| {
                a.radius = x;
                a.bias = a.bias.min(0.5 * x);
            });
        }
    },
};

pub static BIAS: Knob = Knob {
    key: "ambient_occlusion.bias",
    label: "AO bias",
    help: "a sample counts as inside the geometry only this far behind the visible surface (world units): against self-occlusion",
    kind: Kind::Number {
        min: 0.0,
        max: 0.2,
        log: false,
    },
    get: |r| Value::Number(get(r).bias),
    set: |r, v| {
        if let Value::Number(x) = v {
            set(r, |a| a.bias = x.min(0.5 * a.radius));
        }
    },
};

pub static BLUR: Knob = Knob {
    key: "ambient_occlusion.blur",
    label: "AO blur",
    help: "blur the AO over the 4x4 rotation tile, only across surfaces alike (depth-aware); off shows the noise pattern",
    kind: Kind::Bool,
    get: |r| Value::Bool(get(r).blur),
    set: |r, v| {
        if let Value::Bool(b) = v {
            set(r, |a| a.blur = b);
        }
    },
};
