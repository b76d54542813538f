//! Presentation of `gloss bench` results: a plain-text table, a CSV file and
//! a PNG plot of error against frame time.
//!
//! Times are in milliseconds. Image errors are measured against the
//! reference rendering in `0..1` units per channel and shown x255, i.e. in
//! 8-bit steps.

use std::fmt::Write as _;
use std::path::Path;
use std::sync::OnceLock;

use anyhow::{Context, anyhow, bail};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use plotters::style::FontStyle;

/// Summary of timing samples, in milliseconds.
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// One measured configuration of `gloss bench`.
#[derive(Debug, Clone, PartialEq)]
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
}

/// Pass names over all rows, in order of first appearance.
fn pass_names(rows: &[BenchRow]) -> Vec<&str> {
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

fn pass_stats<'a>(row: &'a BenchRow, name: &str) -> Option<&'a Stats> {
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

/// "5/256" for cutoffs that are a whole number of 256ths, else 4 decimals.
fn cutoff_label(c: f32) -> String {
    let k = f64::from(c) * 256.0;
    if !k.is_finite() {
        DASH.to_string()
    } else if (k - k.round()).abs() < 1e-3 {
        format!("{}/256", k.round())
    } else {
        format!("{c:.4}")
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
    header.push(("clock".into(), false));

    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let mut cells = vec![
                r.setting.clone(),
                r.path.clone(),
                r.lights.to_string(),
                r.cutoff.map_or_else(|| DASH.to_string(), cutoff_label),
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

/// A CSV field: quoted (with doubled quotes) if it holds a comma, quote or
/// line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A number for CSV: shortest round-trip form, empty if not finite.
fn csv_num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        String::new()
    }
}

/// The CSV text that [`write_csv`] writes.
pub fn csv(rows: &[BenchRow]) -> String {
    let passes = pass_names(rows);
    let mut header: Vec<String> = [
        "setting",
        "path",
        "lights",
        "cutoff",
        "frame_median_ms",
        "frame_p10_ms",
        "frame_p90_ms",
        "frame_min_ms",
        "frame_max_ms",
        "frame_n",
        "gpu_frame_median_ms",
        "gpu_frame_p10_ms",
        "gpu_frame_p90_ms",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for p in &passes {
        for q in ["median", "p10", "p90"] {
            header.push(format!("pass_{p}_{q}_ms"));
        }
    }
    for h in [
        "speedup_vs_forward",
        "rmse",
        "max_abs",
        "rmse_x255",
        "max_abs_x255",
        "pct_over_1",
        "clock",
    ] {
        header.push(h.to_string());
    }

    let mut out = String::new();
    let join = |cells: Vec<String>| {
        cells
            .iter()
            .map(|c| csv_field(c))
            .collect::<Vec<_>>()
            .join(",")
    };
    out.push_str(&join(header));
    out.push('\n');
    for r in rows {
        let mut c = vec![
            r.setting.clone(),
            r.path.clone(),
            r.lights.to_string(),
            r.cutoff.map_or_else(String::new, |c| csv_num(f64::from(c))),
            csv_num(r.frame.median),
            csv_num(r.frame.p10),
            csv_num(r.frame.p90),
            csv_num(r.frame.min),
            csv_num(r.frame.max),
            r.frame.n.to_string(),
        ];
        match &r.gpu_frame_ms {
            Some(g) => c.extend([csv_num(g.median), csv_num(g.p10), csv_num(g.p90)]),
            None => c.extend([String::new(), String::new(), String::new()]),
        }
        for p in &passes {
            match pass_stats(r, p) {
                Some(s) => c.extend([csv_num(s.median), csv_num(s.p10), csv_num(s.p90)]),
                None => c.extend([String::new(), String::new(), String::new()]),
            }
        }
        c.push(speedup_vs_forward(rows, r).map_or_else(String::new, csv_num));
        c.push(csv_num(r.rmse));
        c.push(csv_num(r.max_abs));
        c.push(csv_num(r.rmse * 255.0));
        c.push(csv_num(r.max_abs * 255.0));
        c.push(csv_num(r.pct_over_1));
        c.push(r.clock.clone());
        let _ = writeln!(out, "{}", join(c));
    }
    out
}

fn create_parent(path: &Path) -> anyhow::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("creating directory {}", dir.display()))?;
    }
    Ok(())
}

/// Writes [`csv`]`(rows)` to `path`: a header and one line per row, with
/// median/p10/p90 columns for every pass any row has (empty where a row lacks
/// it). Creates the parent directory.
pub fn write_csv(rows: &[BenchRow], path: &Path) -> anyhow::Result<()> {
    create_parent(path)?;
    std::fs::write(path, csv(rows)).with_context(|| format!("writing {}", path.display()))
}

/// Size of the PNG that [`plot`] writes.
pub const PLOT_SIZE: (u32, u32) = (1000, 640);

const FONT: &str = "sans-serif";

/// Registers the embedded Ubuntu Light as "sans-serif" (no system fonts on
/// the build machines).
fn ensure_font() -> anyhow::Result<()> {
    static OK: OnceLock<bool> = OnceLock::new();
    let ok = *OK.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT)
            .is_ok()
    });
    if ok {
        Ok(())
    } else {
        bail!("the embedded plot font could not be loaded")
    }
}

const COLORS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// One plotted series: a path's points (x ms, y RMSE x255, label).
struct Series {
    path: String,
    points: Vec<(f64, f64, String)>,
}

fn series(rows: &[BenchRow]) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for r in rows {
        let i = match out.iter().position(|s| s.path == r.path) {
            Some(i) => i,
            None => {
                out.push(Series {
                    path: r.path.clone(),
                    points: Vec::new(),
                });
                out.len() - 1
            }
        };
        let (x, y) = (r.frame.median, r.rmse * 255.0);
        if !(x.is_finite() && x > 0.0 && y.is_finite()) {
            continue;
        }
        // Label with the cutoff where the path has one light count (a cutoff
        // sweep), else with the light count.
        let one_light_count = rows
            .iter()
            .filter(|o| o.path == r.path)
            .all(|o| o.lights == r.lights);
        let label = match r.cutoff {
            Some(c) if one_light_count => format!("cutoff {}", cutoff_label(c)),
            _ => format!("{} lights", r.lights),
        };
        out[i].points.push((x, y, label));
    }
    for s in &mut out {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    out
}

/// `m * 10^k` for each `m` in `mantissas`, every decade, within `lo..=hi`.
fn decade_ticks(lo: f64, hi: f64, mantissas: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    if !(lo > 0.0 && hi >= lo && hi.is_finite()) {
        return out;
    }
    let (first, last) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    for k in first..=last.min(first + 40) {
        for m in mantissas {
            let v = m * 10f64.powi(k);
            if (lo..=hi).contains(&v) {
                out.push(v);
            }
        }
    }
    out
}

/// Axis tick label: up to 3 decimals, trailing zeros trimmed ("10", "2.5").
fn fmt_ms_axis(v: &f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s.is_empty() || s == "-" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Writes a PNG plot ([`PLOT_SIZE`]) of image error against speed: x = frame
/// time median (ms; log scale when the times span more than 4x), y = RMSE
/// against the reference x255; one coloured line+points series per path,
/// each point labelled with its light count (or cutoff, for a cutoff sweep).
/// Rows with a non-finite or non-positive time, or a non-finite RMSE, are
/// left out. Creates the parent directory.
pub fn plot(rows: &[BenchRow], path: &Path) -> anyhow::Result<()> {
    ensure_font()?;
    let series = series(rows);
    let xs = series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
    let (xmin, xmax) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    let ymax = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0f64, f64::max);
    let (xmin, xmax) = if xmin.is_finite() && xmax.is_finite() {
        (xmin, xmax)
    } else {
        (1.0, 10.0)
    };
    let log = xmax / xmin > 4.0;
    let y_range = 0.0..if ymax > 0.0 { ymax * 1.15 } else { 1.0 };

    let (w, h) = PLOT_SIZE;
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        if log {
            let (lo, hi) = (xmin / 1.5, xmax * 1.5);
            let x = (lo..hi)
                .log_scale()
                .with_key_points(decade_ticks(lo, hi, &[1.0, 2.0, 5.0]))
                .with_light_points(decade_ticks(lo, hi, &[3.0, 4.0, 6.0, 7.0, 8.0, 9.0]));
            draw(&root, x, y_range, &series, "log scale")?;
        } else {
            let pad = ((xmax - xmin) * 0.15).max(xmax * 0.1);
            let x = (xmin - pad).max(0.0)..(xmax + pad);
            draw(&root, x, y_range, &series, "linear")?;
        }
        root.present().map_err(|e| anyhow!("drawing plot: {e}"))?;
    }
    let img = image::RgbImage::from_raw(w, h, buf)
        .ok_or_else(|| anyhow!("plot buffer has the wrong size"))?;
    create_parent(path)?;
    img.save_with_format(path, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))
}

fn draw<X>(
    root: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    x_spec: X,
    y_range: std::ops::Range<f64>,
    series: &[Series],
    x_scale: &str,
) -> anyhow::Result<()>
where
    X: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
{
    let err = |e: &dyn std::fmt::Display| anyhow!("drawing plot: {e}");
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(root)
        .caption(
            "Image error vs frame time (lower left is better)",
            (FONT, 26),
        )
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x_spec, y_range)
        .map_err(|e| err(&e))?;
    let x_desc = format!("frame time, median (ms, {x_scale})");
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("RMSE vs reference (8-bit steps)")
        .x_label_formatter(&fmt_ms_axis)
        .y_label_formatter(&|v| format!("{v:.2}"))
        .label_style((FONT, 15))
        .axis_desc_style((FONT, 17))
        .draw()
        .map_err(|e| err(&e))?;

    for (i, s) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let pts: Vec<(f64, f64)> = s.points.iter().map(|p| (p.0, p.1)).collect();
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(s.path.as_str())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 4, color.filled())))
            .map_err(|e| err(&e))?;
        chart
            .draw_series(s.points.iter().map(|(x, y, label)| {
                EmptyElement::at((*x, *y))
                    + Text::new(
                        label.clone(),
                        (6, -16),
                        (FONT, 13).into_font().color(&color),
                    )
            }))
            .map_err(|e| err(&e))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT, 15))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(|e| err(&e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stats(median: f64) -> Stats {
        Stats {
            median,
            p10: median * 0.9,
            p90: median * 1.2,
            min: median * 0.8,
            max: median * 1.5,
            n: 100,
        }
    }

    fn rows() -> Vec<BenchRow> {
        let row = |setting: &str, path: &str, lights, cutoff, frame: f64, rmse: f64| BenchRow {
            setting: setting.into(),
            path: path.into(),
            lights,
            cutoff,
            passes: vec![
                ("geometry".into(), stats(1.25)),
                ("lighting".into(), stats(frame - 1.25)),
            ],
            frame: stats(frame),
            gpu_frame_ms: None,
            clock: "GL_TIME_ELAPSED".into(),
            rmse,
            max_abs: rmse * 4.0,
            pct_over_1: rmse * 1000.0,
        };
        let mut v = vec![
            row("forward 64", "forward", 64, None, 8.0, 0.0),
            row("forward 256", "forward", 256, None, 30.0, 0.0),
            row("deferred 256", "deferred", 256, None, 6.0, 0.0005),
            row(
                "volumes 256 5/256",
                "volumes",
                256,
                Some(5.0 / 256.0),
                2.5,
                0.002,
            ),
            row(
                "volumes 256 1/256",
                "volumes",
                256,
                Some(1.0 / 256.0),
                3.75,
                0.0008,
            ),
            row(
                "volumes 1024",
                "volumes",
                1024,
                Some(5.0 / 256.0),
                9.0,
                0.002,
            ),
        ];
        v[0].passes.truncate(1);
        v[0].passes[0].0 = "forward".into();
        v[3].gpu_frame_ms = Some(stats(2.25));
        v
    }

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

    #[test]
    fn speedup_uses_first_forward_row_with_same_lights() {
        let r = rows();
        assert_eq!(speedup_vs_forward(&r, &r[1]), Some(1.0));
        assert_eq!(speedup_vs_forward(&r, &r[2]), Some(5.0));
        assert_eq!(speedup_vs_forward(&r, &r[3]), Some(12.0));
        assert_eq!(speedup_vs_forward(&r, &r[5]), None);
    }

    #[test]
    fn table_contains_the_values() {
        let t = table(&rows());
        println!("{t}");
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 2 + 6);
        for h in [
            "setting",
            "frame ms",
            "p10–p90 ms",
            "gpu ms",
            "geometry ms",
            "lighting ms",
            "forward ms",
            "speed-up",
            "RMSE×255",
            "max×255",
            "% >1/255",
            "clock",
        ] {
            assert!(lines[0].contains(h), "header lacks {h}: {}", lines[0]);
        }
        let vol = lines
            .iter()
            .find(|l| l.starts_with("volumes 256 5/256"))
            .unwrap();
        for v in [
            "5/256",
            "2.500",
            "2.250–3.000",
            "2.250",
            "1.250",
            "12.00×",
            "0.510",
            "2.0",
            "2.000",
            "GL_TIME_ELAPSED",
        ] {
            assert!(vol.contains(v), "row lacks {v}: {vol}");
        }
        let fwd = lines.iter().find(|l| l.starts_with("forward 256")).unwrap();
        assert!(fwd.contains("30.00") && fwd.contains("1.00×"), "{fwd}");
        let v1024 = lines
            .iter()
            .find(|l| l.starts_with("volumes 1024"))
            .unwrap();
        assert!(v1024.contains(DASH), "{v1024}");
        // Aligned: every data line has the same width as the header when
        // padded (measured in chars; trailing spaces trimmed).
        let col = lines[0].chars().count() - "clock".len();
        for l in &lines[2..] {
            let clock: String = l.chars().skip(col).collect();
            assert_eq!(clock, "GL_TIME_ELAPSED", "misaligned: {l}");
        }
        // No rows: just the header.
        assert_eq!(table(&[]).lines().count(), 2);
    }

    #[test]
    fn csv_has_every_pass_column() {
        let r = rows();
        let text = csv(&r);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 7);
        let header: Vec<&str> = lines[0].split(',').collect();
        for h in [
            "pass_forward_median_ms",
            "pass_geometry_median_ms",
            "pass_lighting_p90_ms",
            "gpu_frame_median_ms",
            "rmse_x255",
            "clock",
        ] {
            assert!(header.contains(&h), "missing {h}");
        }
        for l in &lines[1..] {
            assert_eq!(l.split(',').count(), header.len(), "{l}");
        }
        let vol: Vec<&str> = lines[4].split(',').collect();
        let col = |h: &str| vol[header.iter().position(|x| *x == h).unwrap()];
        assert_eq!(col("setting"), "volumes 256 5/256");
        assert_eq!(col("cutoff"), "0.01953125");
        assert_eq!(col("frame_median_ms"), "2.5");
        assert_eq!(col("gpu_frame_median_ms"), "2.25");
        assert_eq!(col("pass_forward_median_ms"), "");
        assert_eq!(col("speedup_vs_forward"), "12");
        assert_eq!(col("rmse"), "0.002");
        // Quoting.
        let mut q = r[..1].to_vec();
        q[0].setting = "a, \"b\"".into();
        assert!(csv(&q).contains("\"a, \"\"b\"\"\","));

        let dir = std::env::temp_dir().join(format!("gloss-report-csv-{}", std::process::id()));
        let p = dir.join("bench.csv");
        write_csv(&r, &p).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), text);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn plot_writes_a_png() {
        let dir = std::env::temp_dir().join(format!("gloss-report-plot-{}", std::process::id()));
        let p = dir.join("sub").join("bench.png");
        plot(&rows(), &p).unwrap();
        let img = image::open(&p).unwrap();
        assert_eq!((img.width(), img.height()), PLOT_SIZE);
        // Something besides the white background was drawn.
        let rgb = img.to_rgb8();
        assert!(rgb.pixels().filter(|px| px.0 != [255, 255, 255]).count() > 1000);

        // Degenerate inputs still give a plot: no rows, one point, linear x,
        // and non-finite values.
        let mut one = rows()[..1].to_vec();
        plot(&[], &dir.join("empty.png")).unwrap();
        plot(&one, &dir.join("one.png")).unwrap();
        plot(&rows()[2..4], &dir.join("linear.png")).unwrap();
        one[0].frame.median = f64::NAN;
        one[0].rmse = f64::INFINITY;
        plot(&one, &dir.join("nan.png")).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }
}
