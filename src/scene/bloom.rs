//! A `[[post]] pass = "bloom"` entry's settings (notes 03, "Blur Pass and
//! Merge Pass"): four separable blurs, each `sigma` / `radius`, written into
//! mip levels 1-4 of one texture, and the Spencer et al. weights that merge
//! them with the original image. The defaults are the report's figures.
//!
//! ```toml
//! [[post]]
//! pass = "bloom"
//! sigma = [6.2, 24.9, 81.0, 263.0]    # full-resolution pixels
//! radius = [24, 80, 243, 799]          # full-resolution pixels
//! weights = [0.8843, 0.1, 0.012, 0.0027, 0.001]   # original, blur1 .. blur4
//! taps = "direct"                      # or "linear": one bilinear fetch per pair of texels
//! scheme = "mips"                      # or "full": every blur at full resolution (the bench's)
//! radius_scale = 1.0                   # below 1: each kernel cut shorter (fewer taps)
//! ```
//!
//! Sigma and radius are in full-resolution pixels at every level: the
//! report's radius is about 3 sigma for all four blurs, so both are in one
//! unit, and a radius of 799 texels at level 4 would be 12800 pixels, ten
//! times a 1280-pixel image. docs/post/bloom.md has the test that holds the
//! rendered spread to these sigmas.

use super::post_entry::Taps;
use anyhow::{Result, anyhow, bail};

/// One of the four blurs: its standard deviation and radius, in
/// full-resolution pixels.
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
/// then the four blurs. They sum to 1.0000.
pub const SPENCER_WEIGHTS: [f64; 5] = [0.8843, 0.1, 0.012, 0.0027, 0.001];

/// The widest blur radius, in full-resolution pixels: 2000 direct taps fit
/// the 16 KB uniform block every GL 3.3 driver offers (two taps a vec4).
pub const MAX_RADIUS: u32 = 2000;

/// Where the blurs run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BloomScheme {
    /// The notes': blur k in mip level k, its kernel in level-k texels.
    Mips,
    /// Every blur at full resolution with the notes' kernel as written
    /// (the bench's exact but slow variant).
    Full,
}

impl BloomScheme {
    pub const ALL: [BloomScheme; 2] = [BloomScheme::Mips, BloomScheme::Full];

    pub fn name(self) -> &'static str {
        match self {
            BloomScheme::Mips => "mips",
            BloomScheme::Full => "full",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Bloom {
    pub levels: [BloomLevel; 4],
    /// The merge's weights: original, blur1 .. blur4.
    pub weights: [f64; 5],
    pub taps: Taps,
    pub scheme: BloomScheme,
    /// Each kernel's radius is multiplied by this (0 < scale <= 1) and
    /// rounded up: fewer taps, a slightly narrower blur.
    pub radius_scale: f64,
}

impl Default for Bloom {
    fn default() -> Self {
        Bloom {
            levels: NOTES_LEVELS,
            weights: SPENCER_WEIGHTS,
            taps: Taps::Direct,
            scheme: BloomScheme::Mips,
            radius_scale: 1.0,
        }
    }
}

const KEYS: [&str; 6] = [
    "sigma",
    "radius",
    "weights",
    "taps",
    "scheme",
    "radius_scale",
];

impl Bloom {
    /// Read a bloom entry (`key` names it in messages: "post[0] (bloom)").
    pub fn parse(t: &toml::Table, key: &str) -> Result<Bloom> {
        if let Some(k) = t
            .keys()
            .find(|k| *k != "pass" && !KEYS.contains(&k.as_str()))
        {
            bail!("{key}: unknown key '{k}' (known: {})", KEYS.join(", "));
        }
        let mut b = Bloom::default();
        let name = |k: &str| format!("{key}.{k}");
        if let Some(v) = t.get("sigma") {
            let s: [f64; 4] = numbers(v, &name("sigma"))?;
            for (level, s) in b.levels.iter_mut().zip(s) {
                if !(s > 0.0 && s <= f64::from(MAX_RADIUS)) {
                    bail!(
                        "{}: expected four numbers in (0, {MAX_RADIUS}] pixels, found {v}",
                        name("sigma")
                    );
                }
                level.sigma = s;
            }
        }
        if let Some(v) = t.get("radius") {
            let r: [f64; 4] = numbers(v, &name("radius"))?;
            for (level, r) in b.levels.iter_mut().zip(r) {
                if r.fract() != 0.0 || !(1.0..=f64::from(MAX_RADIUS)).contains(&r) {
                    bail!(
                        "{}: expected four whole numbers in 1..={MAX_RADIUS} pixels, found {v}",
                        name("radius")
                    );
                }
                level.radius = r as u32;
            }
        }
        if let Some(v) = t.get("weights") {
            b.weights = numbers(v, &name("weights"))?;
            if b.weights.iter().any(|w| *w < 0.0) {
                bail!("{}: expected five numbers >= 0, found {v}", name("weights"));
            }
        }
        if let Some(v) = t.get("taps") {
            b.taps = match v.as_str() {
                Some("direct") => Taps::Direct,
                Some("linear") => Taps::Linear,
                _ => bail!(
                    "{}: expected \"direct\" or \"linear\", found {v}",
                    name("taps")
                ),
            };
        }
        if let Some(v) = t.get("scheme") {
            b.scheme = (BloomScheme::ALL.into_iter())
                .find(|s| Some(s.name()) == v.as_str())
                .ok_or_else(|| {
                    anyhow!(
                        "{}: expected \"mips\" or \"full\", found {v}",
                        name("scheme")
                    )
                })?;
        }
        if let Some(v) = t.get("radius_scale") {
            let s = v.as_float().or(v.as_integer().map(|n| n as f64));
            b.radius_scale = s.filter(|s| *s > 0.0 && *s <= 1.0).ok_or_else(|| {
                anyhow!(
                    "{}: expected a number in (0, 1], found {v}",
                    name("radius_scale")
                )
            })?;
        }
        Ok(b)
    }

    /// The entry's keys besides `pass`, as the scene file writes them.
    pub fn table(&self) -> toml::Table {
        let mut t = toml::Table::new();
        let floats = |v: &[f64]| toml::Value::Array(v.iter().map(|&x| x.into()).collect());
        t.insert("sigma".into(), floats(&self.levels.map(|l| l.sigma)));
        t.insert(
            "radius".into(),
            toml::Value::Array(
                self.levels
                    .iter()
                    .map(|l| i64::from(l.radius).into())
                    .collect(),
            ),
        );
        t.insert("weights".into(), floats(&self.weights));
        t.insert("taps".into(), self.taps.name().into());
        t.insert("scheme".into(), self.scheme.name().into());
        t.insert("radius_scale".into(), self.radius_scale.into());
        t
    }
}

/// `N` finite numbers (whole numbers accepted) from an array value.
fn numbers<const N: usize>(v: &toml::Value, key: &str) -> Result<[f64; N]> {
    let found: Option<Vec<f64>> = v.as_array().map(|a| {
        a.iter()
            .filter_map(|x| x.as_float().or(x.as_integer().map(|n| n as f64)))
            .filter(|x| x.is_finite())
            .collect()
    });
    match found {
        Some(list) if list.len() == N && v.as_array().is_some_and(|a| a.len() == N) => {
            Ok(list.try_into().expect("N numbers"))
        }
        _ => bail!("{key}: expected {N} finite numbers, found {v}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Bloom> {
        let t: toml::Table = toml::from_str(text).unwrap();
        Bloom::parse(&t, "post[0] (bloom)")
    }

    #[test]
    fn the_defaults_are_the_notes_and_their_weights_sum_to_one() {
        let b = parse("pass = \"bloom\"").unwrap();
        assert_eq!(b, Bloom::default());
        assert_eq!(b.levels, NOTES_LEVELS);
        let sum: f64 = b.weights.iter().sum();
        assert!((sum - 1.0).abs() < 1e-12, "{sum}");
    }

    #[test]
    fn every_key_reads_and_the_saved_table_reads_back_the_same() {
        let b = parse(
            "sigma = [1, 2.5, 3, 4]\nradius = [3, 8, 9, 12]\nweights = [0.5, 0.5, 0, 0, 0]\n\
             taps = \"linear\"\nscheme = \"full\"\nradius_scale = 0.5",
        )
        .unwrap();
        assert_eq!(
            b.levels[1],
            BloomLevel {
                sigma: 2.5,
                radius: 8
            }
        );
        assert_eq!(b.weights, [0.5, 0.5, 0.0, 0.0, 0.0]);
        assert_eq!(
            (b.taps, b.scheme, b.radius_scale),
            (Taps::Linear, BloomScheme::Full, 0.5)
        );
        assert_eq!(Bloom::parse(&b.table(), "again").unwrap(), b);
    }

    #[test]
    fn bad_values_name_their_key() {
        for (text, key) in [
            ("sigma = [1, 2, 3]", "post[0] (bloom).sigma"),
            ("sigma = [1, 2, 3, -4]", "post[0] (bloom).sigma"),
            ("sigma = [1, 2, 3, \"x\"]", "post[0] (bloom).sigma"),
            ("sigma = [1, 2, 3, nan]", "post[0] (bloom).sigma"),
            ("radius = [1, 2, 3, 4.5]", "post[0] (bloom).radius"),
            ("radius = [1, 2, 3, 0]", "post[0] (bloom).radius"),
            ("radius = [1, 2, 3, 5000]", "post[0] (bloom).radius"),
            ("weights = [1, 0, 0, 0]", "post[0] (bloom).weights"),
            ("weights = [1, 0, 0, 0, -1]", "post[0] (bloom).weights"),
            ("weights = [1, 0, 0, 0, inf]", "post[0] (bloom).weights"),
            ("taps = \"fast\"", "post[0] (bloom).taps"),
            ("scheme = 3", "post[0] (bloom).scheme"),
            ("radius_scale = 0", "post[0] (bloom).radius_scale"),
            ("radius_scale = 1.5", "post[0] (bloom).radius_scale"),
            ("sigmas = [1, 2, 3, 4]", "unknown key 'sigmas'"),
        ] {
            let e = format!("{:#}", parse(text).unwrap_err());
            assert!(e.contains(key), "{text}: {e}");
        }
    }
}
