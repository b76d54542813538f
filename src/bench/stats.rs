//! Median and spread of `gloss bench`'s timing samples.

/// Summary of timing samples, in milliseconds.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Stats {
    pub median: f64,
    /// 10th percentile.
    pub p10: f64,
    /// 90th percentile.
    pub p90: f64,
    pub min: f64,
    pub max: f64,
    /// Number of samples summarised (non-finite samples are left out).
    pub n: usize,
}

impl Stats {
    /// Summarises `samples` (milliseconds). Sorts `samples` in place.
    ///
    /// Percentiles interpolate linearly between the closest ranks (the
    /// "type 7" definition that NumPy and spreadsheets use by default), so
    /// the median of an even count is the mean of the middle two. NaN and
    /// infinite samples are left out and not counted in `n`; with no finite
    /// samples every field but `n` is NaN.
    pub fn from_samples(samples: &mut [f64]) -> Stats {
        samples.sort_by(f64::total_cmp);
        let finite: Vec<f64> = samples.iter().copied().filter(|v| v.is_finite()).collect();
        let Some((&min, &max)) = finite.first().zip(finite.last()) else {
            return Stats {
                median: f64::NAN,
                p10: f64::NAN,
                p90: f64::NAN,
                min: f64::NAN,
                max: f64::NAN,
                n: 0,
            };
        };
        Stats {
            median: percentile(&finite, 0.5),
            p10: percentile(&finite, 0.1),
            p90: percentile(&finite, 0.9),
            min,
            max,
            n: finite.len(),
        }
    }
}

/// `p`-quantile of sorted, non-empty `v`, interpolating linearly.
fn percentile(v: &[f64], p: f64) -> f64 {
    let pos = p * (v.len() - 1) as f64;
    let lo = pos.floor() as usize;
    let hi = pos.ceil() as usize;
    let t = pos - lo as f64;
    v[lo] + (v[hi] - v[lo]) * t
}

/// Add one frame's pass times to `passes`: passes of one name in a frame
/// count once, summed (with `PassTimes::titled`, the names the plan gives:
/// a mirror's reflection or a cube face is its own row; with
/// `PassTimes::named`, the techniques' names: all of one kind summed).
pub(crate) fn add_pass_times<'a>(
    passes: &mut Vec<(String, Vec<f64>)>,
    frame: impl IntoIterator<Item = (&'a str, f64)>,
) {
    let mut sums: Vec<(&str, f64)> = Vec::new();
    for (name, ms) in frame {
        match sums.iter_mut().find(|(n, _)| *n == name) {
            Some((_, t)) => *t += ms,
            None => sums.push((name, ms)),
        }
    }
    for (name, ms) in sums {
        match passes.iter_mut().find(|(n, _)| n == name) {
            Some((_, v)) => v.push(ms),
            None => passes.push((name.to_string(), vec![ms])),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_from_samples() {
        let mut s: Vec<f64> = (1..=11).rev().map(f64::from).collect();
        let st = Stats::from_samples(&mut s);
        assert_eq!(s[0], 1.0, "sorted in place");
        assert_eq!(
            st,
            Stats {
                median: 6.0,
                p10: 2.0,
                p90: 10.0,
                min: 1.0,
                max: 11.0,
                n: 11
            }
        );
        // Even count: interpolated.
        let st = Stats::from_samples(&mut [4.0, 1.0, 3.0, 2.0]);
        assert_eq!(st.median, 2.5);
        assert!((st.p10 - 1.3).abs() < 1e-12);
        assert!((st.p90 - 3.7).abs() < 1e-12);
        // Single sample.
        let st = Stats::from_samples(&mut [7.5]);
        assert_eq!((st.median, st.p10, st.p90, st.n), (7.5, 7.5, 7.5, 1));
        // Non-finite samples are left out.
        let st = Stats::from_samples(&mut [f64::NAN, 2.0, f64::INFINITY, 4.0]);
        assert_eq!((st.median, st.min, st.max, st.n), (3.0, 2.0, 4.0, 2));
        // Nothing to summarise.
        let st = Stats::from_samples(&mut []);
        assert!(st.median.is_nan() && st.n == 0);
    }
}
