//! Reading one `[[post]]` entry (src/scene/post.rs): its keys checked
//! against what its pass takes, each value read with an error that names
//! the entry, the pass and the key. With what the entries of several
//! passes share (the blur's limit and its taps), so that the passes' files
//! (bloom.rs, fxaa.rs) need not import post.rs, which imports them.

use anyhow::{Result, anyhow, bail};

/// The widest blur radius a pass takes (its weights are a uniform array).
pub const MAX_BLUR_RADIUS: u32 = 127;

/// How a separable blur reads its taps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Taps {
    /// One texel fetch per kernel weight.
    Direct,
    /// The linear-filtering trick: one bilinear fetch per pair of texels.
    Linear,
}

impl Taps {
    pub fn name(self) -> &'static str {
        match self {
            Taps::Direct => "direct",
            Taps::Linear => "linear",
        }
    }
}

/// One `[[post]]` table being read, for error messages.
pub(super) struct Entry<'a> {
    pub(super) t: &'a toml::Table,
    pub(super) i: usize,
    pub(super) pass: &'a str,
}

impl Entry<'_> {
    pub(super) fn key(&self, key: &str) -> String {
        format!("post[{}] ({}).{key}", self.i, self.pass)
    }

    pub(super) fn missing(&self, key: &str) -> anyhow::Error {
        anyhow!("post[{}] ({}): missing key '{key}'", self.i, self.pass)
    }

    pub(super) fn bad(&self, key: &str, expected: &str) -> anyhow::Error {
        let found = self
            .t
            .get(key)
            .map_or("nothing".into(), ToString::to_string);
        anyhow!("{}: expected {expected}, found {found}", self.key(key))
    }

    /// Refuse keys other than `pass` and `allowed`.
    pub(super) fn only(&self, allowed: &[&str]) -> Result<()> {
        for k in self.t.keys().filter(|k| *k != "pass") {
            if !allowed.contains(&k.as_str()) {
                let known = if allowed.is_empty() {
                    "it takes none".to_string()
                } else {
                    format!("known: {}", allowed.join(", "))
                };
                bail!(
                    "post[{}] ({}): unknown key '{k}' ({known})",
                    self.i,
                    self.pass
                );
            }
        }
        Ok(())
    }

    pub(super) fn float(&self, key: &str) -> Result<Option<f32>> {
        match self.t.get(key) {
            None => Ok(None),
            Some(toml::Value::Float(f)) => Ok(Some(*f as f32)),
            Some(toml::Value::Integer(n)) => Ok(Some(*n as f32)),
            Some(_) => Err(self.bad(key, "a number")),
        }
    }

    pub(super) fn int(&self, key: &str) -> Result<Option<i64>> {
        match self.t.get(key) {
            None => Ok(None),
            Some(toml::Value::Integer(n)) => Ok(Some(*n)),
            Some(_) => Err(self.bad(key, "a whole number")),
        }
    }

    pub(super) fn string(&self, key: &str) -> Result<Option<&str>> {
        match self.t.get(key) {
            None => Ok(None),
            Some(toml::Value::String(s)) => Ok(Some(s)),
            Some(_) => Err(self.bad(key, "a string")),
        }
    }

    pub(super) fn radius(&self, r: i64) -> Result<u32> {
        if !(1..=i64::from(MAX_BLUR_RADIUS)).contains(&r) {
            return Err(self.bad("radius", &format!("1..={MAX_BLUR_RADIUS} texels")));
        }
        Ok(r as u32)
    }
}
