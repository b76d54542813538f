//! The CPU side of the G-buffer material encoding (notes 03, Geometry Pass):
//! how the material triple (alpha, eta, k_s) is put into [0, 1] for a
//! G-buffer texel, what a GL 3.3 colour format then does to it, and how much
//! of each quantity comes back.
//!
//! # The report's scheme
//!
//! The geometry pass writes four G-buffers: gNormal = (n + 1) / 2,
//! gDiffuse_r (the diffuse reflectance, already in [0, 1]), gAlpha =
//! vec3(alpha, eta, k_s) and gConvert. Each element of gAlpha is
//!
//! ```text
//! v <= 1:  gAlpha = v,      gConvert = 0
//! v >  1:  gAlpha = 1 / v,  gConvert = 1
//! decode:  v = gConvert == 1 ? 1 / gAlpha : gAlpha
//! ```
//!
//! so the three flags are packed one per channel of a fourth attachment,
//! gConvert.xyz = 0.0 or 1.0 ([`ReportTexel`]). That is the report's packing
//! and the one followed here; [`pack_flags`] is the compact alternative
//! (the three flags as bits of gAlpha's free fourth channel), which saves
//! the whole gConvert attachment. 0 and 1 are exact in every format, so only
//! the stored value loses anything.
//!
//! # Formats, and how the error is measured
//!
//! A GL 3.3 G-buffer channel is one of ([`Format`]):
//!
//! * RGBA8 (UNORM): s is clamped to [0, 1] and rounded to a multiple of
//!   1/255, so the stored value is off by at most half a step, 1/510;
//! * RGBA16F: s is rounded to the nearest half float (11 significant bits,
//!   ties to even), off by at most 2^-11 of s for s >= 2^-14;
//! * RGBA32F: the nearest f32, off by at most 2^-24 of s.
//!
//! [`round_trip`] encodes a value, quantises the stored value to a format
//! and decodes it. [`relative_error_profile`] measures that round trip over
//! log-spaced samples of a [`ValueRange`]: the error of v is
//! `|decoded - v| / max(v, floor)`, relative above `floor` and absolute
//! (in units of `floor`) below it. alpha (1e-3..1e3) and eta (1..4) are
//! measured purely relatively (floor 0). k_s reaches 0, where any relative
//! error is unbounded (RGBA8 stores k_s = 0.001 as 0), so k_s (0..10) is
//! measured with floor 0.01: below k_s = 0.01 an error counts as
//! |error| / 0.01, and 0 itself is sampled.
//!
//! # Measured precision of the report's scheme
//!
//! Max relative error over 100 001 samples ([`Quantity`] gives the ranges):
//!
//! | format  | alpha 1e-3..1e3 | eta 1..4          | k_s 0..10         | derived bound                     |
//! |---------|-----------------|-------------------|-------------------|-----------------------------------|
//! | RGBA8   | inf (mean inf)  | 7.80e-3 (2.1e-3)  | 1.96e-1 (3.2e-2)  | inf; d / (1/4 - d); d / 0.01      |
//! | RGBA16F | 4.85e-4 (1.8e-4)| 4.85e-4 (1.8e-4)  | 4.85e-4 (1.6e-4)  | u / (1 - u) = 4.88e-4, u = 2^-11  |
//! | RGBA32F | 5.95e-8 (2.1e-8)| 5.93e-8 (2.2e-8)  | 5.94e-8 (1.9e-8)  | u / (1 - u) = 5.96e-8, u = 2^-24  |
//!
//! (mean in brackets; k_s with floor 0.01.) The bounds: a format moves s
//! by at most d = 1/510 (RGBA8) or u s (floats). For v <= 1 the error is
//! that, over v; for v > 1 it is |1/s' - 1/s| v = |s - s'| / s' <=
//! d / (s - d), largest at the smallest s, 1 / hi. So at RGBA8 the error
//! is about d / min(v, 1/v): best at v = 1 (1/510 = 0.2 %) and growing
//! toward both ends; nothing is lost near 1. For alpha it is unbounded:
//! alpha above 510 stores 1/alpha < 1/510, which rounds to 0 and decodes to
//! 1/0 = inf, and alpha below 1/510 comes back as 0. At eta = 4 (s = 1/4)
//! RGBA8's error reaches 0.8 %, and 20 % where k_s meets its floor. In a
//! float format every channel is within one rounding, 2^-11 or 2^-24, over
//! all three ranges.
//!
//! # A better encoding: logarithmic ([`LogScale`])
//!
//! With a known range [lo, hi] and an offset c (0 where lo > 0):
//!
//! ```text
//! s = (log2(v + c) - log2(lo + c)) / (log2(hi + c) - log2(lo + c))
//! v = exp2(log2(lo + c) + s (log2(hi + c) - log2(lo + c))) - c
//! ```
//!
//! A rounding error e in s becomes the factor 2^(e R) on v + c, R =
//! log2((hi + c) / (lo + c)): a relative error that is the same over the
//! whole range, and needs no flag. alpha uses [1e-3, 1e3], c = 0 (R = 19.9
//! octaves), eta [1, 4], c = 0 (R = 2); k_s, which reaches 0, uses [0, 10]
//! with c = 0.001, i.e. s = log2(1 + k_s / c) / log2(1 + 10 / c): logarithmic
//! for k_s well above c and running linearly into 0.
//!
//! Max relative error per scheme ([`Scheme::Direct`] stores v as it is):
//!
//! | format  | scheme | alpha 1e-3..1e3 | eta 1..4 | k_s 0..10 | log's derived bound (alpha; eta; k_s) |
//! |---------|--------|-----------------|----------|-----------|---------------------------------------|
//! | RGBA8   | report | inf             | 7.80e-3  | 1.96e-1   |                                       |
//! | RGBA8   | log    | 2.75e-2         | 2.72e-3  | 2.00e-2   | 2.75e-2; 2.72e-3; 2.00e-2             |
//! | RGBA8   | direct | 1 (clamped)     | 0.75     | 0.90      |                                       |
//! | RGBA16F | report | 4.85e-4         | 4.85e-4  | 4.85e-4   |                                       |
//! | RGBA16F | log    | 3.38e-3         | 3.38e-4  | 2.27e-3   | 3.38e-3; 3.38e-4; 2.48e-3             |
//! | RGBA16F | direct | 4.85e-4         | 4.86e-4  | 4.85e-4   |                                       |
//! | RGBA32F | report | 5.95e-8         | 5.93e-8  | 5.94e-8   |                                       |
//! | RGBA32F | log    | 4.12e-7         | 4.13e-8  | 2.77e-7   | 4.12e-7; 4.13e-8; 3.02e-7             |
//! | RGBA32F | direct | 5.96e-8         | 5.93e-8  | 5.94e-8   |                                       |
//!
//! The log bound is (1 + c / floor)(2^(d R) - 1) with d the most the format
//! moves s in [0, 1]: 1/510, 2^-12 (half a half-float step in [1/2, 1]) or
//! 2^-25. At RGBA8 it is reached everywhere: the worst error of each sixth
//! of alpha's range (a decade) is 2.746e-2 to 0.03 %, where the report's
//! runs 1, 0.18, 0.020, 0.019, 0.17, inf. The mean is half the max (1.36e-2
//! for alpha), as for any rounding error spread evenly over a step, so
//! flatness is judged by the worst error piece by piece, not max / mean.
//!
//! Which is better:
//!
//! * **RGBA8: the log scale**, for all three quantities. alpha keeps 2.75 %
//!   over the whole 1e-3..1e3 instead of an unbounded error (the report's
//!   scheme is better only for alpha in about [0.07, 14], where
//!   d / min(v, 1/v) < 2.75 %); eta's worst error is 2.9 times smaller and
//!   k_s's 10 times smaller. It also needs no flags, so no gConvert.
//! * **RGBA16F and RGBA32F: neither; store the value as it is.** A float is
//!   already logarithmic, so the reciprocal gains nothing (the same 2^-11),
//!   and a half float holds 6.1e-5..65504 directly, with no flag and no
//!   gConvert attachment. The log scale is worse there (7 times for alpha,
//!   5 for k_s) because it spends the float's fine steps near 0 on one end
//!   of the range only; eta's short range is the exception (3.4e-4).
//!
//! All encoders clamp rather than fail, as a shader must: the report's
//! scheme stores a negative or NaN value as 0 and +inf as 0 flagged (it
//! decodes back to +inf), the direct scheme stores negatives and NaN as 0,
//! and a [`LogScale`] clamps to [lo, hi] (NaN to lo). Decoding runs in f64
//! here; a shader decodes in f32, which adds about 1e-7 relative (more
//! through `exp2`), so the RGBA32F figures are what the format allows, not
//! what a shader gets.

use anyhow::{Result, bail};

#[cfg(test)]
mod format_tests;
mod formats;
mod profile;
#[cfg(test)]
mod tests;

pub use formats::{F16_MAX, F16_MIN_NORMAL, Format, quantise_f16, quantise_unorm8};
pub use profile::{ErrorProfile, ValueRange, relative_error_profile};

/// The report's encoding of one value: `(v, false)` for v <= 1 and
/// `(1 / v, true)` above 1. A negative or NaN `v` is stored as 0; +inf as
/// `(0, true)`.
pub fn encode_report(v: f64) -> (f64, bool) {
    let v = v.max(0.0);
    if v > 1.0 { (1.0 / v, true) } else { (v, false) }
}

/// The report's decoding: `1 / stored` where `convert` is set, else
/// `stored`. A flagged 0 (a value too large for the format) gives +inf.
pub fn decode_report(stored: f64, convert: bool) -> f64 {
    if convert { 1.0 / stored } else { stored }
}

/// One texel of the report's gAlpha and gConvert: `g_alpha` holds the
/// stored (alpha, eta, k_s), `g_convert[i]` is 1.0 where `g_alpha[i]` holds
/// a reciprocal and 0.0 where not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReportTexel {
    pub g_alpha: [f64; 3],
    pub g_convert: [f64; 3],
}

impl ReportTexel {
    /// Both G-buffers after writing to `format` and reading back.
    pub fn quantised(&self, format: Format) -> ReportTexel {
        ReportTexel {
            g_alpha: self.g_alpha.map(|s| format.quantise(s)),
            g_convert: self.g_convert.map(|f| format.quantise(f)),
        }
    }
}

/// The report's encoding of the triple `m` = (alpha, eta, k_s).
pub fn encode_report_triple(m: [f64; 3]) -> ReportTexel {
    let e = m.map(encode_report);
    ReportTexel {
        g_alpha: e.map(|(s, _)| s),
        g_convert: e.map(|(_, c)| if c { 1.0 } else { 0.0 }),
    }
}

/// (alpha, eta, k_s) back from a report texel; a flag reads as set where
/// its channel is above 1/2.
pub fn decode_report_triple(t: &ReportTexel) -> [f64; 3] {
    std::array::from_fn(|i| decode_report(t.g_alpha[i], t.g_convert[i] > 0.5))
}

/// The three flags as bits of one channel: `(x + 2 y + 4 z) / 7`, so that
/// they fit in gAlpha's unused fourth channel instead of a gConvert
/// attachment. The levels are 1/7 apart, far more than any format's
/// rounding (1/510 at RGBA8).
pub fn pack_flags(convert: [bool; 3]) -> f64 {
    let bits = convert
        .iter()
        .enumerate()
        .map(|(i, &c)| (c as u32) << i)
        .sum::<u32>();
    bits as f64 / 7.0
}

/// The flags back from [`pack_flags`]'s channel: the nearest of its eight
/// levels (clamped; NaN reads as no flag set).
pub fn unpack_flags(w: f64) -> [bool; 3] {
    let bits = if w.is_nan() {
        0
    } else {
        (w * 7.0).round().clamp(0.0, 7.0) as u32
    };
    std::array::from_fn(|i| bits & (1 << i) != 0)
}

/// A logarithmic encoding of [lo, hi] with offset c (see the module docs):
/// s = (log2(v + c) - log2(lo + c)) / (log2(hi + c) - log2(lo + c)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogScale {
    lo: f64,
    hi: f64,
    offset: f64,
}

impl LogScale {
    /// The scale over [lo, hi] with offset c = `offset`; refused unless all
    /// three are finite, lo < hi, offset >= 0 and lo + offset > 0.
    pub fn new(lo: f64, hi: f64, offset: f64) -> Result<LogScale> {
        if !(lo.is_finite() && hi.is_finite() && offset.is_finite()) {
            bail!("log scale [{lo}, {hi}] offset {offset}: not finite");
        }
        if !(lo < hi && offset >= 0.0 && lo + offset > 0.0) {
            bail!(
                "log scale [{lo}, {hi}] offset {offset}: needs lo < hi, offset >= 0, lo + offset > 0"
            );
        }
        Ok(LogScale { lo, hi, offset })
    }

    /// The smallest value it holds, stored as 0.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The largest value it holds, stored as 1.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The offset c.
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// R = log2((hi + c) / (lo + c)): the octaves that s's [0, 1] spans.
    pub fn octaves(&self) -> f64 {
        (self.hi + self.offset).log2() - (self.lo + self.offset).log2()
    }

    /// s in [0, 1] for `v`, clamped to [lo, hi] first (NaN to lo). The
    /// ends are exactly 0 and 1.
    pub fn encode(&self, v: f64) -> f64 {
        if v.is_nan() || v <= self.lo {
            return 0.0;
        }
        if v >= self.hi {
            return 1.0;
        }
        let base = (self.lo + self.offset).log2();
        ((v + self.offset).log2() - base) / self.octaves()
    }

    /// v for a stored `s`, clamped to [0, 1] (NaN to 0); 0 and 1 give
    /// exactly lo and hi.
    pub fn decode(&self, s: f64) -> f64 {
        if s.is_nan() || s <= 0.0 {
            return self.lo;
        }
        if s >= 1.0 {
            return self.hi;
        }
        let base = (self.lo + self.offset).log2();
        ((base + s * self.octaves()).exp2() - self.offset).clamp(self.lo, self.hi)
    }
}

/// How a value is put into a G-buffer channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scheme {
    /// Notes 03: v, or 1 / v with the convert flag above 1.
    Report,
    /// v as it is, no flag (negatives and NaN as 0): what a float target
    /// allows; an RGBA8 target clamps it to [0, 1].
    Direct,
    /// A logarithmic scale over a known range, no flag.
    Log(LogScale),
}

/// `v` encoded under `scheme`: the stored value and the convert flag
/// (always false but for [`Scheme::Report`]).
pub fn encode(v: f64, scheme: Scheme) -> (f64, bool) {
    match scheme {
        Scheme::Report => encode_report(v),
        Scheme::Direct => (v.max(0.0), false),
        Scheme::Log(scale) => (scale.encode(v), false),
    }
}

/// The value back from a stored value and its flag under `scheme`.
pub fn decode(stored: f64, convert: bool, scheme: Scheme) -> f64 {
    match scheme {
        Scheme::Report => decode_report(stored, convert),
        Scheme::Direct => stored,
        Scheme::Log(scale) => scale.decode(stored),
    }
}

/// `v` encoded under `scheme`, its stored value quantised to `format` (the
/// flag is exact in every format), and decoded.
pub fn round_trip(v: f64, format: Format, scheme: Scheme) -> f64 {
    let (s, convert) = encode(v, scheme);
    decode(format.quantise(s), convert, scheme)
}

/// The material quantities of gAlpha.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// Roughness alpha, 1e-3..1e3 (lighting::microfacet's ALPHA_MIN and
    /// ALPHA_MAX).
    Alpha,
    /// Index of refraction eta, 1..4 (air to germanium; diamond is 2.42).
    Eta,
    /// Specular scale k_s, 0..10.
    Ks,
}

impl Quantity {
    /// alpha, eta, k_s in gAlpha's order.
    pub const ALL: [Quantity; 3] = [Quantity::Alpha, Quantity::Eta, Quantity::Ks];

    /// The range to measure it over (floor 0.01 for k_s, see the module docs).
    pub fn range(self) -> ValueRange {
        match self {
            Quantity::Alpha => ValueRange::new(1e-3, 1e3, 0.0),
            Quantity::Eta => ValueRange::new(1.0, 4.0, 0.0),
            Quantity::Ks => ValueRange::new(0.0, 10.0, 0.01),
        }
    }

    /// Its logarithmic scale: [1e-3, 1e3], [1, 4] and [0, 10] with c = 0.001.
    pub fn log_scale(self) -> LogScale {
        let r = self.range();
        let offset = if self == Quantity::Ks { 1e-3 } else { 0.0 };
        LogScale {
            lo: r.lo,
            hi: r.hi,
            offset,
        }
    }
}

/// The triple (alpha, eta, k_s) on each quantity's [`LogScale`]: three
/// channels, no flags.
pub fn encode_log_triple(m: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| Quantity::ALL[i].log_scale().encode(m[i]))
}

/// (alpha, eta, k_s) back from [`encode_log_triple`]'s channels.
pub fn decode_log_triple(s: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| Quantity::ALL[i].log_scale().decode(s[i]))
}
