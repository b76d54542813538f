//! A `[[post]] pass = "fxaa"` entry's settings: FXAA 3.11's quality
//! version (Timothy Lottes, "FXAA", NVIDIA whitepaper, 2009, and the
//! FXAA 3.11 source, 2011). The names, the defaults and the presets' search
//! steps are that source's (`fxaaQualitySubpix`, `fxaaQualityEdgeThreshold`,
//! `fxaaQualityEdgeThresholdMin`, `FXAA_QUALITY__PRESET` and its
//! `FXAA_QUALITY__P0..P11`).
//!
//! ```toml
//! [[post]]
//! pass = "fxaa"
//! quality = 12              # a preset: 10..=15, 20..=29 or 39
//! subpix = 0.75             # sub-pixel aliasing removal, 0 (off) ..= 1 (softer)
//! edge_threshold = 0.166    # least local contrast, relative to the brightest neighbour
//! edge_threshold_min = 0.0833 # least local contrast in absolute luma (trims the darks)
//! ```

use super::post_entry::Entry;
use anyhow::Result;

/// The presets: (number, how far each search step moves along the edge,
/// in texels). The first step starts the search; a step past the last
/// fetch is the guess FXAA makes when the edge's end is not found.
pub const PRESETS: [(u32, &[f32]); 17] = [
    (10, &[1.5, 3.0, 12.0]),
    (11, &[1.0, 1.5, 3.0, 12.0]),
    (12, &[1.0, 1.5, 2.0, 4.0, 12.0]),
    (13, &[1.0, 1.5, 2.0, 2.0, 4.0, 12.0]),
    (14, &[1.0, 1.5, 2.0, 2.0, 2.0, 4.0, 12.0]),
    (15, &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 12.0]),
    (20, &[1.5, 2.0, 8.0]),
    (21, &[1.0, 1.5, 2.0, 8.0]),
    (22, &[1.0, 1.5, 2.0, 2.0, 8.0]),
    (23, &[1.0, 1.5, 2.0, 2.0, 2.0, 8.0]),
    (24, &[1.0, 1.5, 2.0, 2.0, 2.0, 3.0, 8.0]),
    (25, &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0]),
    (26, &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0]),
    (27, &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0]),
    (28, &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0]),
    (
        29,
        &[1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0],
    ),
    (
        39,
        &[1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0],
    ),
];

/// The most search steps a preset has (glsl/post/fxaa.frag's array).
pub const MAX_STEPS: usize = 12;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fxaa {
    /// `FXAA_QUALITY__PRESET`: 12, FXAA 3.11's default.
    pub quality: u32,
    /// `fxaaQualitySubpix`: 0.75 (1.00 softer, 0.50 sharper, 0 off).
    pub subpix: f32,
    /// `fxaaQualityEdgeThreshold`: 0.166 (0.333 too little, 0.125 high quality).
    pub edge_threshold: f32,
    /// `fxaaQualityEdgeThresholdMin`: 0.0833 (0.0625 high quality, 0.0312 visible limit).
    pub edge_threshold_min: f32,
}

impl Default for Fxaa {
    fn default() -> Self {
        Fxaa {
            quality: 12,
            subpix: 0.75,
            edge_threshold: 0.166,
            edge_threshold_min: 0.0833,
        }
    }
}

impl Fxaa {
    /// The search steps of this entry's preset.
    pub fn steps(&self) -> &'static [f32] {
        (PRESETS.iter())
            .find(|(q, _)| *q == self.quality)
            .map_or(&[], |(_, s)| s)
    }

    /// Read an fxaa entry.
    pub(super) fn parse(e: &Entry) -> Result<Fxaa> {
        e.only(&["quality", "subpix", "edge_threshold", "edge_threshold_min"])?;
        let d = Fxaa::default();
        let quality = match e.int("quality")? {
            None => d.quality,
            Some(q) if PRESETS.iter().any(|(p, _)| i64::from(*p) == q) => q as u32,
            Some(_) => return Err(e.bad("quality", "a preset: 10..=15, 20..=29 or 39")),
        };
        let number = |key: &str, default: f32, ok: fn(f32) -> bool, range: &str| -> Result<f32> {
            match e.float(key)? {
                None => Ok(default),
                Some(x) if x.is_finite() && ok(x) => Ok(x),
                Some(_) => Err(e.bad(key, range)),
            }
        };
        Ok(Fxaa {
            quality,
            subpix: number("subpix", d.subpix, |x| (0.0..=1.0).contains(&x), "0..=1")?,
            edge_threshold: number(
                "edge_threshold",
                d.edge_threshold,
                |x| x > 0.0 && x <= 1.0,
                "a number in (0, 1]",
            )?,
            edge_threshold_min: number(
                "edge_threshold_min",
                d.edge_threshold_min,
                |x| (0.0..=1.0).contains(&x),
                "0..=1",
            )?,
        })
    }

    /// The entry's keys besides `pass`, as the scene file writes them.
    pub fn table(&self) -> toml::Table {
        let mut t = toml::Table::new();
        let f = |x: f32| toml::Value::Float(f64::from(x));
        t.insert("quality".into(), i64::from(self.quality).into());
        t.insert("subpix".into(), f(self.subpix));
        t.insert("edge_threshold".into(), f(self.edge_threshold));
        t.insert("edge_threshold_min".into(), f(self.edge_threshold_min));
        t
    }
}
