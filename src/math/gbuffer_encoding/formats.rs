//! The G-buffer formats' quantisation: 8-bit UNORM, half float, f32.

/// A G-buffer colour format a GL 3.3 renderer would store the triple in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// GL_RGBA8: 8-bit unsigned normalised.
    Rgba8,
    /// GL_RGBA16F: IEEE half floats.
    Rgba16F,
    /// GL_RGBA32F: IEEE single floats.
    Rgba32F,
}

impl Format {
    /// The three formats, smallest first.
    pub const ALL: [Format; 3] = [Format::Rgba8, Format::Rgba16F, Format::Rgba32F];

    /// What reading back `s` gives after a shader wrote it to a channel of
    /// this format.
    pub fn quantise(self, s: f64) -> f64 {
        match self {
            Format::Rgba8 => quantise_unorm8(s),
            Format::Rgba16F => quantise_f16(s),
            Format::Rgba32F => s as f32 as f64,
        }
    }
}

/// The UNORM8 value nearest `s`: clamp to [0, 1], round(255 s) / 255 (the
/// GL's float to normalised fixed-point conversion). NaN gives 0.
pub fn quantise_unorm8(s: f64) -> f64 {
    if s.is_nan() {
        return 0.0;
    }
    (s.clamp(0.0, 1.0) * 255.0).round() / 255.0
}

/// The largest finite half float.
pub const F16_MAX: f64 = 65504.0;
/// The smallest normal half float, 2^-14.
pub const F16_MIN_NORMAL: f64 = 1.0 / 16384.0;

/// The half float nearest `x`, rounding ties to even, back in f64: rounded
/// straight from f64 (not through f32, which could round twice). The
/// spacing of half floats in [2^e, 2^(e+1)) is 2^(e - 10) for e >= -14, and
/// 2^-24 below 2^-14 (the subnormals). A value from 65520 up (half-way past
/// [`F16_MAX`]) becomes infinite; NaN and infinities are kept.
pub fn quantise_f16(x: f64) -> f64 {
    if !x.is_finite() {
        return x;
    }
    let a = x.abs();
    let e = if a < F16_MIN_NORMAL {
        -14
    } else {
        // a is a normal f64 here: its unbiased exponent, floor(log2 a).
        ((a.to_bits() >> 52) & 0x7ff) as i32 - 1023
    };
    let ulp = 2f64.powi(e - 10);
    let q = (a / ulp).round_ties_even() * ulp;
    let q = if q > F16_MAX { f64::INFINITY } else { q };
    q.copysign(x)
}
