//! A `[[post]] pass = "bloom"` entry's settings (notes 03, "Blur Pass and
//! Merge Pass"): four separable blurs, each `sigma` / `radius`, written into
//! mip levels 1-4 of one texture, and the Spencer et al. weights that merge
//! them with the original image. The defaults are the report's figures.

use anyhow::{Result, bail};

/// One of the four blurs: its standard deviation and radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BloomLevel {
    pub sigma: f64,
    pub radius: u32,
}

/// The notes' four blurs: blur1 .. blur4, into mip levels 1 .. 4.
pub const NOTES_LEVELS: [BloomLevel; 4] = [
    BloomLevel {
        sigma: 6.2,
        radius: 24,
    },
    BloomLevel {
        sigma: 24.9,
        radius: 80,
    },
    BloomLevel {
        sigma: 81.0,
        radius: 243,
    },
    BloomLevel {
        sigma: 263.0,
        radius: 799,
    },
];

/// Spencer et al.'s weights as notes 03 gives them: the original image,
/// then the four blurs.
pub const SPENCER_WEIGHTS: [f64; 5] = [0.8843, 0.1, 0.012, 0.0027, 0.001];

#[derive(Clone, Debug, PartialEq)]
pub struct Bloom {
    pub levels: [BloomLevel; 4],
    /// The merge's weights: original, blur1 .. blur4.
    pub weights: [f64; 5],
}

impl Default for Bloom {
    fn default() -> Self {
        Bloom {
            levels: NOTES_LEVELS,
            weights: SPENCER_WEIGHTS,
        }
    }
}

impl Bloom {
    /// Read a bloom entry (`key` names it in messages: "post[0] (bloom)").
    pub fn parse(t: &toml::Table, key: &str) -> Result<Bloom> {
        if let Some(k) = t.keys().find(|k| *k != "pass") {
            bail!("{key}: unknown key '{k}' (the bloom takes the notes' figures)");
        }
        Ok(Bloom::default())
    }

    /// The entry's keys besides `pass`, as the scene file writes them.
    pub fn table(&self) -> toml::Table {
        toml::Table::new()
    }
}
