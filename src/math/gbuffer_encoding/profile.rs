//! The precision of a round trip through a format, measured over a range.

use super::*;

/// A range of values to measure a round trip over: [lo, hi], with errors
/// below `floor` measured absolutely (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValueRange {
    pub lo: f64,
    pub hi: f64,
    pub floor: f64,
}

impl ValueRange {
    /// [lo, hi] with `floor` (checked by [`relative_error_profile`]).
    pub const fn new(lo: f64, hi: f64, floor: f64) -> ValueRange {
        ValueRange { lo, hi, floor }
    }

    /// The error of decoding `v` as `decoded`: `|decoded - v| / max(v,
    /// floor)`, infinite where `decoded` is not a number.
    pub fn error(&self, v: f64, decoded: f64) -> f64 {
        if decoded.is_nan() {
            return f64::INFINITY;
        }
        (decoded - v).abs() / v.max(self.floor)
    }
}

/// What [`relative_error_profile`] measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorProfile {
    /// The largest error.
    pub max: f64,
    /// The mean error (infinite if any is).
    pub mean: f64,
    /// The sample with the largest error.
    pub worst_at: f64,
    /// How many samples were measured.
    pub samples: usize,
}

/// The round-trip error of `scheme` through `format` over `range`:
/// `samples` values log-spaced over [max(lo, floor), hi] (both ends
/// included), and, when lo < floor, a quarter as many (at least 2) spaced
/// evenly over [lo, floor). Refused for a range that is not finite, lo < 0,
/// hi <= lo, floor < 0, floor >= hi, a log-spaced start of 0, or fewer
/// than 2 samples.
pub fn relative_error_profile(
    range: ValueRange,
    format: Format,
    scheme: Scheme,
    samples: usize,
) -> Result<ErrorProfile> {
    let ValueRange { lo, hi, floor } = range;
    if !(lo.is_finite() && hi.is_finite() && floor.is_finite()) {
        bail!("range [{lo}, {hi}] floor {floor}: not finite");
    }
    let start = lo.max(floor);
    if !(lo >= 0.0 && lo < hi && floor >= 0.0 && floor < hi && start > 0.0) {
        bail!(
            "range [{lo}, {hi}] floor {floor}: needs 0 <= lo < hi, 0 <= floor < hi, max(lo, floor) > 0"
        );
    }
    if samples < 2 {
        bail!("{samples} samples: at least 2 are needed");
    }
    let (a, b) = (start.log2(), hi.log2());
    let last = samples - 1;
    let mut values: Vec<f64> = (0..samples)
        .map(|i| match i {
            0 => start,
            i if i == last => hi,
            i => (a + (b - a) * i as f64 / last as f64).exp2(),
        })
        .collect();
    if lo < floor {
        let n = (samples / 4).max(2);
        values.extend((0..n).map(|i| lo + (floor - lo) * i as f64 / n as f64));
    }
    let mut profile = ErrorProfile {
        max: 0.0,
        mean: 0.0,
        worst_at: values[0],
        samples: values.len(),
    };
    let mut sum = 0.0;
    for &v in &values {
        let e = range.error(v, round_trip(v, format, scheme));
        sum += e;
        if e > profile.max {
            profile.max = e;
            profile.worst_at = v;
        }
    }
    profile.mean = sum / values.len() as f64;
    Ok(profile)
}
