//! Presentation of `gloss bench` results as a plain-text table, and the
//! rows that the table, the CSV file and the plot are made from.
//!
//! Times are in milliseconds. Image errors are measured against the
//! reference rendering in `0..1` units per channel and shown x255, i.e. in
//! 8-bit steps.

use super::stats::Stats;

/// One measured configuration of `gloss bench`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BenchRow {
    /// Human-readable name of the configuration.
    pub setting: String,
    /// Rendering path, e.g. "forward", "deferred", "deferred-volumes".
    pub path: String,
    pub lights: usize,
    /// Light-volume cutoff, if the path uses one.
    pub cutoff: Option<f32>,
    /// Per-pass timings, in frame order.
    pub passes: Vec<(String, Stats)>,
    /// Whole-frame timing (ms).
    pub frame: Stats,
    /// GPU-side whole-frame timing (ms), if timer queries were available.
    pub gpu_frame_ms: Option<Stats>,
    /// Which clock produced the timings (e.g. "GL_TIME_ELAPSED", "CPU+glFinish").
    pub clock: String,
    /// RMSE against the reference image, `0..1` units per channel.
    pub rmse: f64,
    /// Largest per-channel difference against the reference, `0..1` units.
    pub max_abs: f64,
    /// Percentage (`0..=100`) of pixels with any channel off by more than 1/255.
    pub pct_over_1: f64,
    /// Mean FLIP error against the reference (src/image_compare/flip.rs),
    /// where one was measured.
    pub flip: Option<f64>,
    /// The far field's analytic error bound (src/bench/bound.rs), where the
    /// setting has one.
    pub bound: Option<super::bound::FrameBound>,
    /// Samples that passed the depth test in one frame, over its pixels
    /// (GL_SAMPLES_PASSED): the overdraw.
    pub fragments_per_pixel: Option<f64>,
    /// For a scene whose lights cast: its shadows against the exact ones
    /// (src/bench/shadows.rs).
    pub shadow: Option<crate::image_compare::shadow_metrics::ShadowErrors>,
}

/// Pass names over all rows, in order of first appearance.
pub(super) fn pass_names(rows: &[BenchRow]) -> Vec<&str> {
    let mut names: Vec<&str> = Vec::new();
    for r in rows {
        for (n, _) in &r.passes {
            if !names.contains(&n.as_str()) {
                names.push(n);
            }
        }
    }
    names
}

pub(super) fn pass_stats<'a>(row: &'a BenchRow, name: &str) -> Option<&'a Stats> {
    row.passes.iter().find(|(n, _)| n == name).map(|(_, s)| s)
}

/// Speed-up of `row` over the first row whose path is "forward" with the same
/// light count: forward median / row median. `None` if there is no such row
/// or either median is not a positive finite number.
pub fn speedup_vs_forward(rows: &[BenchRow], row: &BenchRow) -> Option<f64> {
    let reference = rows
        .iter()
        .find(|r| r.path == "forward" && r.lights == row.lights)?;
    let (f, m) = (reference.frame.median, row.frame.median);
    (f.is_finite() && m.is_finite() && f > 0.0 && m > 0.0).then(|| f / m)
}

const DASH: &str = "—";

fn num(v: f64, decimals: usize) -> String {
    if v.is_finite() {
        format!("{v:.decimals$}")
    } else {
        DASH.to_string()
    }
}

/// Milliseconds with about four significant digits.
fn ms(v: f64) -> String {
    let d = if !v.is_finite() || v.abs() >= 100.0 {
        1
    } else if v.abs() >= 10.0 {
        2
    } else {
        3
    };
    num(v, d)
}

/// "5/256" for cutoffs that are a whole number of 256ths, else `decimals`
/// decimals ("0.0100": the table's column and the plot's labels) or, with
/// `None`, the shortest form that reads back as the same `f32` ("0.01": the
/// setting names, "volumes cutoff 0.01"). "—" if not finite.
pub(super) fn cutoff_label(c: f32, decimals: Option<usize>) -> String {
    let k = f64::from(c) * 256.0;
    if !k.is_finite() {
        DASH.to_string()
    } else if (k - k.round()).abs() < 1e-3 {
        format!("{}/256", k.round())
    } else if let Some(d) = decimals {
        format!("{c:.d$}")
    } else {
        format!("{c}")
    }
}

/// An aligned plain-text table, one line per row: setting, path, light
/// count, cutoff, frame median and p10–p90 spread (ms), GPU frame median
/// (only if some row has one), each pass's median (ms), speed-up against the
/// first "forward" row with the same light count, RMSE and max abs error
/// (x255, in 8-bit steps), % of pixels off by more than 1/255, and the clock.
/// Missing values are "—".
pub fn table(rows: &[BenchRow]) -> String {
    let passes = pass_names(rows);
    let any_gpu = rows.iter().any(|r| r.gpu_frame_ms.is_some());

    // (header, right-aligned)
    let mut header: Vec<(String, bool)> = vec![
        ("setting".into(), false),
        ("path".into(), false),
        ("lights".into(), true),
        ("cutoff".into(), true),
        ("frame ms".into(), true),
        ("p10–p90 ms".into(), true),
    ];
    if any_gpu {
        header.push(("gpu ms".into(), true));
    }
    for p in &passes {
        header.push((format!("{p} ms"), true));
    }
    for h in ["speed-up", "RMSE×255", "max×255", "% >1/255"] {
        header.push((h.into(), true));
    }
    let any_flip = rows.iter().any(|r| r.flip.is_some());
    if any_flip {
        header.push(("FLIP".into(), true));
    }
    let any_fragments = rows.iter().any(|r| r.fragments_per_pixel.is_some());
    if any_fragments {
        header.push(("frags/px".into(), true));
    }
    let any_bound = rows.iter().any(|r| r.bound.is_some());
    if any_bound {
        for h in ["bound max×255", "bound %>1/255"] {
            header.push((h.into(), true));
        }
    }
    let any_shadow = rows.iter().any(|r| r.shadow.is_some());
    if any_shadow {
        for h in ["misclass %", "acne %", "gap"] {
            header.push((h.into(), true));
        }
    }
    header.push(("clock".into(), false));

    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let mut cells = vec![
                r.setting.clone(),
                r.path.clone(),
                r.lights.to_string(),
                r.cutoff
                    .map_or_else(|| DASH.to_string(), |c| cutoff_label(c, Some(4))),
                ms(r.frame.median),
                if r.frame.p10.is_finite() && r.frame.p90.is_finite() {
                    format!("{}–{}", ms(r.frame.p10), ms(r.frame.p90))
                } else {
                    DASH.to_string()
                },
            ];
            if any_gpu {
                cells.push(
                    r.gpu_frame_ms
                        .map_or_else(|| DASH.to_string(), |s| ms(s.median)),
                );
            }
            for p in &passes {
                cells.push(pass_stats(r, p).map_or_else(|| DASH.to_string(), |s| ms(s.median)));
            }
            cells.push(
                speedup_vs_forward(rows, r)
                    .map_or_else(|| DASH.to_string(), |s| format!("{s:.2}×")),
            );
            cells.push(num(r.rmse * 255.0, 3));
            cells.push(num(r.max_abs * 255.0, 1));
            cells.push(num(r.pct_over_1, 3));
            if any_flip {
                cells.push(r.flip.map_or_else(|| DASH.into(), |f| num(f, 4)));
            }
            if any_fragments {
                cells.push(
                    r.fragments_per_pixel
                        .map_or_else(|| DASH.into(), |f| num(f, 2)),
                );
            }
            if any_bound {
                let b = r.bound.as_ref();
                cells.push(b.map_or_else(|| DASH.into(), |b| num(b.max * 255.0, 1)));
                cells.push(b.map_or_else(|| DASH.into(), |b| num(b.pct_over_1, 3)));
            }
            if any_shadow {
                let s = r.shadow.as_ref();
                cells.push(s.map_or_else(|| DASH.into(), |s| num(s.misclassified * 100.0, 3)));
                cells.push(s.map_or_else(|| DASH.into(), |s| num(s.acne * 100.0, 3)));
                let gap = s.and_then(|s| s.peter_panning);
                cells.push(gap.map_or_else(|| DASH.into(), |g| num(g.into(), 4)));
            }
            cells.push(r.clock.clone());
            cells
        })
        .collect();

    let width = |i: usize| {
        body.iter()
            .map(|c| c[i].chars().count())
            .chain(std::iter::once(header[i].0.chars().count()))
            .max()
            .unwrap_or(0)
    };
    let widths: Vec<usize> = (0..header.len()).map(width).collect();

    let line = |cells: &mut dyn Iterator<Item = &str>| -> String {
        let mut s = String::new();
        for (i, c) in cells.enumerate() {
            if i > 0 {
                s.push_str("  ");
            }
            let pad = widths[i].saturating_sub(c.chars().count());
            if header[i].1 {
                s.extend(std::iter::repeat_n(' ', pad));
                s.push_str(c);
            } else {
                s.push_str(c);
                s.extend(std::iter::repeat_n(' ', pad));
            }
        }
        s.trim_end().to_string()
    };

    let mut out = String::new();
    out.push_str(&line(&mut header.iter().map(|h| h.0.as_str())));
    out.push('\n');
    let total = widths.iter().sum::<usize>() + 2 * widths.len().saturating_sub(1);
    out.extend(std::iter::repeat_n('-', total));
    out.push('\n');
    for cells in &body {
        out.push_str(&line(&mut cells.iter().map(String::as_str)));
        out.push('\n');
    }
    out
}

#[cfg(test)]
#[path = "table_tests.rs"]
pub(super) mod tests;
