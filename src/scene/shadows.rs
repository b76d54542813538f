//! A light's `shadow` key (notes 01 §8.5 "Shadow mapping", §8.5.1 "Issues";
//! notes 02 "Rendering Cast Shadows"): `shadow = true` casts with the
//! defaults below, or a table sets the knobs that make acne, peter-panning
//! and aliasing appear and disappear.
//!
//! ```toml
//! [[lights]]
//! type = "spot"
//! position = [0.0, 6.0, 0.0]
//! direction = [0.0, -1.0, 0.0]
//! shadow = { resolution = 1024, bias = 0.02, slope_bias = 2.0, pcf = "3x3" }
//! ```
//!
//! The defaults were picked from `gloss bench` on the shadow scenes (the
//! Pareto front of time against error; docs/shadows.md has the table).

use super::checks::{finite, non_negative};
use anyhow::{Result, bail};
use serde::Deserialize;

#[derive(Deserialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub(super) struct ShadowTable {
    resolution: Option<u32>,
    bias: Option<f32>,
    slope_bias: Option<f32>,
    normal_offset: Option<f32>,
    cull_front: Option<bool>,
    pcf: Option<String>,
    fit: Option<String>,
    cube: Option<String>,
    cascades: Option<u32>,
    split: Option<String>,
    lambda: Option<f32>,
    stable: Option<bool>,
    blend: Option<f32>,
    cascade_colors: Option<bool>,
}

/// Percentage-closer filtering: how many depth comparisons a shadow lookup
/// averages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pcf {
    /// One comparison, GL_NEAREST: the hard, aliased edge of the notes.
    None,
    /// One lookup with GL_LINEAR on the comparison texture: the hardware
    /// compares the four nearest texels and blends the results (2x2).
    Hardware,
    /// Nine GL_NEAREST comparisons, one texel apart.
    Box3,
    /// Twenty-five GL_NEAREST comparisons.
    Box5,
    /// Sixteen comparisons on a Poisson disc of radius 2.5 texels.
    Poisson,
}

impl Pcf {
    pub const ALL: [Pcf; 5] = [Pcf::None, Pcf::Hardware, Pcf::Box3, Pcf::Box5, Pcf::Poisson];

    pub fn name(self) -> &'static str {
        match self {
            Pcf::None => "none",
            Pcf::Hardware => "hardware",
            Pcf::Box3 => "3x3",
            Pcf::Box5 => "5x5",
            Pcf::Poisson => "poisson",
        }
    }

    pub fn parse(s: &str) -> Option<Pcf> {
        Pcf::ALL.into_iter().find(|p| p.name() == s)
    }

    /// The kernel number glsl/common/shadow.glsl switches on.
    pub fn code(self) -> i32 {
        self as i32
    }
}

/// What a directional light's orthographic box is fitted to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowFit {
    /// The bounding sphere of the whole scene: stable, but most texels
    /// land where the camera does not look.
    Scene,
    /// The part of the scene the camera sees (its frustum clipped to the
    /// scene's bounds), in x and y; in depth still every caster.
    Visible,
}

impl ShadowFit {
    pub const ALL: [ShadowFit; 2] = [ShadowFit::Scene, ShadowFit::Visible];

    pub fn name(self) -> &'static str {
        match self {
            ShadowFit::Scene => "scene",
            ShadowFit::Visible => "visible",
        }
    }
}

/// How a point light's six cube faces are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CubeRender {
    /// Six passes, one per face, each its own framebuffer.
    SixPasses,
    /// One pass: a geometry shader sends each triangle to all six faces
    /// (gl_Layer) of a layered framebuffer.
    GeometryShader,
}

impl CubeRender {
    pub const ALL: [CubeRender; 2] = [CubeRender::SixPasses, CubeRender::GeometryShader];

    pub fn name(self) -> &'static str {
        match self {
            CubeRender::SixPasses => "six_passes",
            CubeRender::GeometryShader => "geometry_shader",
        }
    }
}

/// How a directional light's cascades divide the camera's depth range
/// (Zhang et al. 2006, "Parallel-split shadow maps"; docs/shadows/cascaded_shadow_maps.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CascadeSplit {
    /// Equal depth ranges: C_i = n + (f - n) i / m.
    Uniform,
    /// Equal ratios: C_i = n (f / n)^(i / m), the ideal for perspective aliasing.
    Logarithmic,
    /// Zhang's practical scheme: lambda x logarithmic + (1 - lambda) x uniform.
    Practical,
}

impl CascadeSplit {
    pub const ALL: [CascadeSplit; 3] = [
        CascadeSplit::Uniform,
        CascadeSplit::Logarithmic,
        CascadeSplit::Practical,
    ];

    pub fn name(self) -> &'static str {
        match self {
            CascadeSplit::Uniform => "uniform",
            CascadeSplit::Logarithmic => "logarithmic",
            CascadeSplit::Practical => "practical",
        }
    }
}

/// The cascades a directional light's map may be split into (one layer of
/// a GL_TEXTURE_2D_ARRAY each); 1 is the single map of shadow_map.rs.
pub const MAX_CASCADES: u32 = 8;

/// A light's shadow map and how it is read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shadow {
    /// Texels along each side of the map (of each face, for a point light).
    pub resolution: u32,
    /// Constant bias: the point is moved this far towards the light, in
    /// world units, before it is compared with the map.
    pub bias: f32,
    /// Slope-scaled bias: glPolygonOffset(slope_bias, 0) in the shadow pass
    /// (for a point light's distance map the shader adds the same term).
    pub slope_bias: f32,
    /// Normal-offset bias: the point is moved along its normal by this many
    /// shadow-map texels (the notes' "offset along their normal").
    pub normal_offset: f32,
    /// glCullFace(GL_FRONT) in the shadow pass: only back faces are stored.
    pub cull_front: bool,
    pub pcf: Pcf,
    pub fit: ShadowFit,
    pub cube: CubeRender,
    /// A directional light's cascades (1..=MAX_CASCADES; 1: one map).
    pub cascades: u32,
    pub split: CascadeSplit,
    /// The practical split's weight of the logarithmic scheme, 0..=1.
    pub lambda: f32,
    /// Stable cascades: each a square around its slice's bounding sphere,
    /// moved in whole texels, so the edges do not shimmer as the camera moves.
    pub stable: bool,
    /// The band at the far end of each cascade, as a fraction of its depth
    /// range, across which the lookup blends into the next cascade.
    pub blend: f32,
    /// Tint each cascade's pixels (red, green, blue, yellow, ...): debugging.
    pub cascade_colors: bool,
}

/// Resolutions a map may have: powers of two from 64 to 8192.
pub const RESOLUTIONS: [u32; 8] = [64, 128, 256, 512, 1024, 2048, 4096, 8192];

impl Default for Shadow {
    fn default() -> Self {
        Shadow {
            resolution: 2048,
            bias: 0.01,
            slope_bias: 1.5,
            normal_offset: 1.0,
            cull_front: false,
            pcf: Pcf::Hardware,
            fit: ShadowFit::Visible,
            cube: CubeRender::SixPasses,
            cascades: 1,
            split: CascadeSplit::Practical,
            lambda: 0.5,
            stable: true,
            blend: 0.1,
            cascade_colors: false,
        }
    }
}

impl Shadow {
    /// The practical scheme's lambda that gives this split: 0 uniform, 1
    /// logarithmic (src/math/cascades.rs `splits`).
    pub fn split_lambda(&self) -> f32 {
        match self.split {
            CascadeSplit::Uniform => 0.0,
            CascadeSplit::Logarithmic => 1.0,
            CascadeSplit::Practical => self.lambda,
        }
    }

    /// The defaults for a point light: the same, with 1024-texel faces (six
    /// of them hold 1.5 times the texels of one 2048 map; `gloss bench` on
    /// shadows-point: 2048-texel faces cost 3.4 times the shadow pass of
    /// 1024 for an RMSE of 1.0/255 against them).
    pub fn point_default() -> Shadow {
        Shadow {
            resolution: 1024,
            ..Shadow::default()
        }
    }
}

/// A light's `shadow` key, checked; `key` names it in errors (`lights[2].shadow`).
/// The file writes `shadow = true`, `false` or a table (`toml::Value`,
/// read here so that an unknown key is named with its light).
pub(super) fn shadow(key: &str, file: Option<&toml::Value>, point: bool) -> Result<Option<Shadow>> {
    let d = if point {
        Shadow::point_default()
    } else {
        Shadow::default()
    };
    let t: ShadowTable = match file {
        None | Some(toml::Value::Boolean(false)) => return Ok(None),
        Some(toml::Value::Boolean(true)) => return Ok(Some(d)),
        Some(v @ toml::Value::Table(_)) => v
            .clone()
            .try_into()
            .map_err(|e| anyhow::anyhow!("{key}: {}", e.to_string().trim()))?,
        Some(other) => bail!(
            "{key}: expected true, false or a table, found {}",
            other.type_str()
        ),
    };
    let resolution = t.resolution.unwrap_or(d.resolution);
    if !RESOLUTIONS.contains(&resolution) {
        bail!("{key}.resolution: expected one of {RESOLUTIONS:?}, found {resolution}");
    }
    let bias = t.bias.unwrap_or(d.bias);
    let slope_bias = t.slope_bias.unwrap_or(d.slope_bias);
    let normal_offset = t.normal_offset.unwrap_or(d.normal_offset);
    for (k, v) in [
        ("bias", bias),
        ("slope_bias", slope_bias),
        ("normal_offset", normal_offset),
    ] {
        finite(&format!("{key}.{k}"), &[v])?;
        non_negative(&format!("{key}.{k}"), &[v])?;
    }
    let pcf = match &t.pcf {
        None => d.pcf,
        Some(s) => Pcf::parse(s).ok_or_else(|| {
            anyhow::anyhow!(
                "{key}.pcf: expected one of {}, found \"{s}\"",
                names(Pcf::ALL.map(Pcf::name))
            )
        })?,
    };
    let fit = match &t.fit {
        None => d.fit,
        Some(s) => ShadowFit::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                anyhow::anyhow!("{key}.fit: expected scene or visible, found \"{s}\"")
            })?,
    };
    let cube = match &t.cube {
        None => d.cube,
        Some(s) => CubeRender::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| {
                anyhow::anyhow!("{key}.cube: expected six_passes or geometry_shader, found \"{s}\"")
            })?,
    };
    let cascades = t.cascades.unwrap_or(d.cascades);
    if !(1..=MAX_CASCADES).contains(&cascades) {
        bail!("{key}.cascades: expected 1..={MAX_CASCADES}, found {cascades}");
    }
    // Every layer is a full map: 8 x 8192^2 floats would be 2 GiB.
    let texels = u64::from(cascades) * u64::from(resolution).pow(2);
    if texels > 1 << 27 {
        bail!(
            "{key}: {cascades} cascades of {resolution} x {resolution} texels are {} MiB of depth; at most 512 MiB (e.g. 8 x 4096 or 4 x 4096)",
            (texels * 4) >> 20
        );
    }
    let split = match &t.split {
        None => d.split,
        Some(s) => CascadeSplit::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| {
                anyhow::anyhow!(
                    "{key}.split: expected one of {}, found \"{s}\"",
                    names(CascadeSplit::ALL.map(CascadeSplit::name))
                )
            })?,
    };
    let lambda = t.lambda.unwrap_or(d.lambda);
    if !(0.0..=1.0).contains(&lambda) {
        bail!("{key}.lambda: expected a number in 0..=1, found {lambda}");
    }
    let blend = t.blend.unwrap_or(d.blend);
    if !(0.0..=0.5).contains(&blend) {
        bail!("{key}.blend: expected a fraction of a cascade in 0..=0.5, found {blend}");
    }
    Ok(Some(Shadow {
        resolution,
        bias,
        slope_bias,
        normal_offset,
        cull_front: t.cull_front.unwrap_or(d.cull_front),
        pcf,
        fit,
        cube,
        cascades,
        split,
        lambda,
        stable: t.stable.unwrap_or(d.stable),
        blend,
        cascade_colors: t.cascade_colors.unwrap_or(d.cascade_colors),
    }))
}

fn names<const N: usize>(n: [&str; N]) -> String {
    n.join(", ")
}

/// The `shadow` table as "save as" writes it: every knob, so the file says
/// what the light does.
pub fn shadow_table(s: &Shadow) -> toml::Table {
    let mut t = toml::Table::new();
    let f = |x: f32| toml::Value::Float(x.into());
    t.insert(
        "resolution".into(),
        toml::Value::Integer(s.resolution.into()),
    );
    t.insert("bias".into(), f(s.bias));
    t.insert("slope_bias".into(), f(s.slope_bias));
    t.insert("normal_offset".into(), f(s.normal_offset));
    t.insert("cull_front".into(), toml::Value::Boolean(s.cull_front));
    t.insert("pcf".into(), toml::Value::String(s.pcf.name().into()));
    t.insert("fit".into(), toml::Value::String(s.fit.name().into()));
    t.insert("cube".into(), toml::Value::String(s.cube.name().into()));
    t.insert("cascades".into(), toml::Value::Integer(s.cascades.into()));
    t.insert("split".into(), toml::Value::String(s.split.name().into()));
    t.insert("lambda".into(), f(s.lambda));
    t.insert("stable".into(), toml::Value::Boolean(s.stable));
    t.insert("blend".into(), f(s.blend));
    t.insert(
        "cascade_colors".into(),
        toml::Value::Boolean(s.cascade_colors),
    );
    t
}

/// A shadow-casting light limit: four 2D maps (directional and spot
/// lights) and four cube maps (point lights), each on its own texture unit.
pub const MAX_SHADOW_MAPS_2D: usize = 4;
pub const MAX_SHADOW_CUBES: usize = 4;

#[cfg(test)]
mod tests;
