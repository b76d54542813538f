//! The post-processing chain (notes 01 §9 "Post processing"; notes 03
//! "Blur Pass and Merge Pass", "Gamma Correction Pass"): the scene file
//! lists the passes in the order they run, each with its parameters.
//!
//! ```toml
//! [render]
//! post_chain = "ping_pong"   # or "cascaded": one framebuffer per step
//!
//! [[post]]
//! pass = "bloom"             # notes 03: four blurs into mip levels, Spencer merge
//! [[post]]
//! pass = "tonemap"
//! operator = "reinhard"      # clamp | reinhard | exposure | aces
//! exposure = 1.0
//! [[post]]
//! pass = "gamma"             # always the last entry
//! gamma = 2.2                # or srgb = true: exact sRGB via GL_FRAMEBUFFER_SRGB
//! ```
//!
//! Every entry is checked here: an unknown pass, an unknown key, a missing
//! parameter or a value out of range is an error naming the entry, its
//! pass and the key.

use super::bloom::Bloom;
use super::fxaa::Fxaa;
use super::post_entry::Entry;
pub use super::post_entry::{MAX_BLUR_RADIUS, Taps};
pub use super::settings::ChainForm;
use anyhow::{Result, bail};

/// A tone-mapping operator: HDR light (0..inf) to display range (0..1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToneOperator {
    /// min(x, 1): what an 8-bit target does with no tone mapping.
    Clamp,
    /// Reinhard: x / (1 + x).
    Reinhard,
    /// 1 - exp(-x): the exposure curve.
    Exposure,
    /// Narkowicz's fit of the ACES filmic curve.
    Aces,
}

impl ToneOperator {
    pub const ALL: [ToneOperator; 4] = [
        ToneOperator::Clamp,
        ToneOperator::Reinhard,
        ToneOperator::Exposure,
        ToneOperator::Aces,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ToneOperator::Clamp => "clamp",
            ToneOperator::Reinhard => "reinhard",
            ToneOperator::Exposure => "exposure",
            ToneOperator::Aces => "aces",
        }
    }

    /// The number glsl/post/tone_mapping.frag switches on.
    pub fn code(self) -> i32 {
        self as i32
    }
}

/// A 3x3 convolution kernel, row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Kernel3 {
    /// A preset's name ("sharpen", "edge", "emboss"), or None for weights
    /// written out in the file.
    pub preset: Option<&'static str>,
    pub weights: [f32; 9],
}

/// The kernels the scene file may name.
pub const KERNELS: [(&str, [f32; 9]); 3] = [
    ("sharpen", [0.0, -1.0, 0.0, -1.0, 5.0, -1.0, 0.0, -1.0, 0.0]),
    (
        "edge",
        [-1.0, -1.0, -1.0, -1.0, 8.0, -1.0, -1.0, -1.0, -1.0],
    ),
    ("emboss", [-2.0, -1.0, 0.0, -1.0, 1.0, 1.0, 0.0, 1.0, 2.0]),
];

/// The longest chain.
pub const MAX_POST_PASSES: usize = 16;

/// One entry of the chain.
#[derive(Clone, Debug, PartialEq)]
pub enum PostPass {
    /// Notes 03's bloom (src/scene/bloom.rs has its settings).
    Bloom(Bloom),
    Tonemap {
        operator: ToneOperator,
        /// The light is multiplied by this before the operator.
        exposure: f32,
    },
    /// The last pass: encode for the 8-bit output.
    Gamma {
        gamma: f32,
        /// Exact sRGB by the hardware (GL_FRAMEBUFFER_SRGB into an
        /// SRGB8_ALPHA8 output) instead of pow(c, 1 / gamma).
        srgb: bool,
    },
    /// A separable Gaussian blur: horizontal, then vertical.
    Blur {
        sigma: f32,
        radius: u32,
        taps: Taps,
    },
    /// A separable box blur (for comparison with the Gaussian).
    Box {
        radius: u32,
    },
    /// A 3x3 convolution.
    Kernel(Kernel3),
    Grayscale,
    Invert,
    /// FXAA 3.11 (src/scene/fxaa.rs): after a tonemap, before gamma.
    Fxaa(Fxaa),
}

/// The pass names a `[[post]]` entry may give.
pub const PASS_NAMES: [&str; 12] = [
    "bloom",
    "tonemap",
    "gamma",
    "blur",
    "box",
    "kernel",
    "sharpen",
    "edge",
    "emboss",
    "grayscale",
    "invert",
    "fxaa",
];

impl PostPass {
    /// The name the scene file gives it.
    pub fn name(&self) -> &'static str {
        match self {
            PostPass::Bloom(_) => "bloom",
            PostPass::Tonemap { .. } => "tonemap",
            PostPass::Gamma { .. } => "gamma",
            PostPass::Blur { .. } => "blur",
            PostPass::Box { .. } => "box",
            PostPass::Kernel(_) => "kernel",
            PostPass::Grayscale => "grayscale",
            PostPass::Invert => "invert",
            PostPass::Fxaa(_) => "fxaa",
        }
    }

    /// Read entry `post[i]`.
    pub fn parse(t: &toml::Table, i: usize) -> Result<PostPass> {
        let pass = match t.get("pass") {
            Some(toml::Value::String(s)) => s.as_str(),
            Some(v) => bail!("post[{i}].pass: expected a pass name, found {v}"),
            None => bail!(
                "post[{i}]: missing key 'pass' (one of {})",
                PASS_NAMES.join(", ")
            ),
        };
        let e = Entry { t, i, pass };
        let p = match pass {
            "bloom" => PostPass::Bloom(Bloom::parse(t, &format!("post[{i}] (bloom)"))?),
            "tonemap" => {
                e.only(&["operator", "exposure"])?;
                let name = e.string("operator")?.ok_or_else(|| e.missing("operator"))?;
                let operator = (ToneOperator::ALL.into_iter())
                    .find(|o| o.name() == name)
                    .ok_or_else(|| e.bad("operator", "clamp, reinhard, exposure or aces"))?;
                let exposure = e.float("exposure")?.unwrap_or(1.0);
                if !(exposure.is_finite() && exposure > 0.0) {
                    return Err(e.bad("exposure", "a number > 0"));
                }
                PostPass::Tonemap { operator, exposure }
            }
            "gamma" => {
                e.only(&["gamma", "srgb"])?;
                let gamma = e.float("gamma")?.unwrap_or(2.2);
                if !(gamma.is_finite() && (0.1..=10.0).contains(&gamma)) {
                    return Err(e.bad("gamma", "a number in 0.1..=10"));
                }
                let srgb = match t.get("srgb") {
                    None => false,
                    Some(toml::Value::Boolean(b)) => *b,
                    Some(_) => return Err(e.bad("srgb", "true or false")),
                };
                if srgb && t.contains_key("gamma") {
                    return Err(e.bad("gamma", "no gamma with srgb = true (sRGB is its own curve)"));
                }
                PostPass::Gamma { gamma, srgb }
            }
            "blur" => {
                e.only(&["sigma", "radius", "taps"])?;
                let sigma = e.float("sigma")?.ok_or_else(|| e.missing("sigma"))?;
                if !(sigma.is_finite() && sigma > 0.0 && sigma <= MAX_BLUR_RADIUS as f32 / 2.0) {
                    return Err(e.bad("sigma", "a number in (0, 63.5] texels"));
                }
                let radius = match e.int("radius")? {
                    Some(r) => e.radius(r)?,
                    None => ((3.0 * sigma).ceil() as u32).min(MAX_BLUR_RADIUS),
                };
                let taps = match e.string("taps")? {
                    None | Some("direct") => Taps::Direct,
                    Some("linear") => Taps::Linear,
                    Some(_) => return Err(e.bad("taps", "\"direct\" or \"linear\"")),
                };
                PostPass::Blur {
                    sigma,
                    radius,
                    taps,
                }
            }
            "box" => {
                e.only(&["radius"])?;
                let r = e.int("radius")?.ok_or_else(|| e.missing("radius"))?;
                PostPass::Box {
                    radius: e.radius(r)?,
                }
            }
            "kernel" => {
                e.only(&["kernel"])?;
                PostPass::Kernel(match t.get("kernel") {
                    None => return Err(e.missing("kernel")),
                    Some(toml::Value::String(s)) => preset(s)
                        .ok_or_else(|| e.bad("kernel", "sharpen, edge, emboss or nine numbers"))?,
                    Some(toml::Value::Array(a)) => {
                        let w: Option<Vec<f32>> = (a.iter())
                            .map(|v| match v {
                                toml::Value::Float(f) => Some(*f as f32),
                                toml::Value::Integer(n) => Some(*n as f32),
                                _ => None,
                            })
                            .collect();
                        let w = w.filter(|w| w.len() == 9 && w.iter().all(|x| x.is_finite()));
                        let w =
                            w.ok_or_else(|| e.bad("kernel", "nine finite numbers, row by row"))?;
                        Kernel3 {
                            preset: None,
                            weights: w.try_into().expect("nine"),
                        }
                    }
                    Some(_) => return Err(e.bad("kernel", "a preset name or nine numbers")),
                })
            }
            "sharpen" | "edge" | "emboss" => {
                e.only(&[])?;
                PostPass::Kernel(preset(pass).expect("a preset"))
            }
            "grayscale" => {
                e.only(&[])?;
                PostPass::Grayscale
            }
            "invert" => {
                e.only(&[])?;
                PostPass::Invert
            }
            "fxaa" => PostPass::Fxaa(Fxaa::parse(&e)?),
            other => bail!(
                "post[{i}].pass: unknown pass \"{other}\" (one of {})",
                PASS_NAMES.join(", ")
            ),
        };
        Ok(p)
    }

    /// The entry as the scene file writes it (save as).
    pub fn table(&self) -> toml::Table {
        let mut t = toml::Table::new();
        t.insert("pass".into(), self.name().into());
        let f = |x: f32| toml::Value::Float(f64::from(x));
        match self {
            PostPass::Bloom(b) => t.extend(b.table()),
            PostPass::Tonemap { operator, exposure } => {
                t.insert("operator".into(), operator.name().into());
                t.insert("exposure".into(), f(*exposure));
            }
            PostPass::Gamma { gamma, srgb } => {
                if *srgb {
                    t.insert("srgb".into(), true.into());
                } else {
                    t.insert("gamma".into(), f(*gamma));
                }
            }
            PostPass::Blur {
                sigma,
                radius,
                taps,
            } => {
                t.insert("sigma".into(), f(*sigma));
                t.insert("radius".into(), i64::from(*radius).into());
                t.insert("taps".into(), taps.name().into());
            }
            PostPass::Box { radius } => {
                t.insert("radius".into(), i64::from(*radius).into());
            }
            PostPass::Kernel(k) => {
                let v = match k.preset {
                    Some(p) => p.into(),
                    None => toml::Value::Array(k.weights.iter().map(|&w| f(w)).collect()),
                };
                t.insert("kernel".into(), v);
            }
            PostPass::Fxaa(x) => t.extend(x.table()),
            PostPass::Grayscale | PostPass::Invert => {}
        }
        t
    }
}

fn preset(name: &str) -> Option<Kernel3> {
    let (n, w) = KERNELS.iter().find(|(n, _)| *n == name)?;
    Some(Kernel3 {
        preset: Some(n),
        weights: *w,
    })
}

/// Read and check the whole `[[post]]` list: at most `MAX_POST_PASSES`
/// entries, and gamma last (the output is 8-bit and holds encoded values).
pub fn chain(entries: &[toml::Table]) -> Result<Vec<PostPass>> {
    if entries.len() > MAX_POST_PASSES {
        bail!("post: {} passes, at most {MAX_POST_PASSES}", entries.len());
    }
    let chain = (entries.iter().enumerate())
        .map(|(i, t)| PostPass::parse(t, i))
        .collect::<Result<Vec<_>>>()?;
    for (i, p) in chain.iter().enumerate() {
        // FXAA's thresholds are for display-range luma (docs/post/fxaa.md).
        let tonemapped = chain[..i]
            .iter()
            .any(|q| matches!(q, PostPass::Tonemap { .. }));
        if matches!(p, PostPass::Fxaa(_)) && !tonemapped {
            bail!(
                "post[{i}] (fxaa): FXAA reads display-range colour: put a tonemap pass before it (after tonemap, before gamma)"
            );
        }
        let last = i + 1 == chain.len();
        match (p, last) {
            (PostPass::Gamma { .. }, false) => bail!(
                "post[{i}] (gamma): gamma must be the last pass (it encodes the image for the 8-bit output)"
            ),
            (PostPass::Gamma { .. }, true) => {}
            (_, true) => bail!(
                "post: the chain must end with a gamma pass (the 8-bit output holds encoded values): add [[post]] pass = \"gamma\" after post[{i}] ({})",
                p.name()
            ),
            _ => {}
        }
    }
    Ok(chain)
}
