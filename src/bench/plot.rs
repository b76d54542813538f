//! The PNG plot of `gloss bench` results: image error against frame time,
//! one series per render path.

use std::path::Path;
use std::sync::OnceLock;

use anyhow::{Context, anyhow, bail};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use plotters::style::FontStyle;

use super::create_parent;
use super::table::{BenchRow, cutoff_label};

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
            Some(c) if one_light_count => format!("cutoff {}", cutoff_label(c, Some(4))),
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
/// each point labelled with its light count (or cutoff, for a cutoff sweep);
/// the Pareto front (src/bench/pareto.rs) as a dashed black line.
/// Rows with a non-finite or non-positive time, or a non-finite RMSE, are
/// left out. Creates the parent directory.
pub fn plot(rows: &[BenchRow], path: &Path) -> anyhow::Result<()> {
    ensure_font()?;
    let series = series(rows);
    let front: Vec<(f64, f64)> = (super::pareto::front(rows, |r| r.rmse).into_iter())
        .map(|i| (rows[i].frame.median, rows[i].rmse * 255.0))
        .filter(|&(x, _)| x > 0.0)
        .collect();
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
            draw(&root, x, y_range, &series, &front, "log scale")?;
        } else {
            let pad = ((xmax - xmin) * 0.15).max(xmax * 0.1);
            let x = (xmin - pad).max(0.0)..(xmax + pad);
            draw(&root, x, y_range, &series, &front, "linear")?;
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
    front: &[(f64, f64)],
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
    // Over the series: the Pareto front by RMSE, a dashed black line
    // through the settings no other beats on both time and error.
    if front.len() > 1 {
        chart
            .draw_series(DashedLineSeries::new(
                front.iter().copied(),
                8,
                5,
                BLACK.stroke_width(2),
            ))
            .map_err(|e| err(&e))?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
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

/// One path's points for [`plot_scaling`]: (x, frame ms).
pub struct ScalingSeries {
    pub path: String,
    pub points: Vec<(f64, f64)>,
}

impl ScalingSeries {
    pub fn new(path: &str) -> ScalingSeries {
        ScalingSeries {
            path: path.to_string(),
            points: Vec::new(),
        }
    }
}

/// Writes a log-log PNG plot ([`PLOT_SIZE`]) of frame time (y, ms) against
/// `x_desc` (light count, Mpixels): one line per path. Points that are not
/// finite and positive are left out. Creates the parent directory.
pub fn plot_scaling(
    series: &[ScalingSeries],
    title: &str,
    x_desc: &str,
    path: &Path,
) -> anyhow::Result<()> {
    ensure_font()?;
    let ok = |p: &&(f64, f64)| p.0.is_finite() && p.0 > 0.0 && p.1.is_finite() && p.1 > 0.0;
    let pts = || series.iter().flat_map(|s| s.points.iter().filter(ok));
    let range = |v: Vec<f64>| {
        let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        if lo.is_finite() && hi.is_finite() {
            (lo / 1.5, hi * 1.5)
        } else {
            (1.0, 10.0)
        }
    };
    let (x0, x1) = range(pts().map(|p| p.0).collect());
    let (y0, y1) = range(pts().map(|p| p.1).collect());
    let err = |e: &dyn std::fmt::Display| anyhow!("drawing plot: {e}");
    let (w, h) = PLOT_SIZE;
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, (FONT, 22))
            .margin(20)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (x0..x1)
                    .log_scale()
                    .with_key_points(decade_ticks(x0, x1, &[1.0, 2.0, 4.0])),
                (y0..y1)
                    .log_scale()
                    .with_key_points(decade_ticks(y0, y1, &[1.0, 2.0, 5.0])),
            )
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc("frame time, median (ms, log scale)")
            .x_label_formatter(&fmt_ms_axis)
            .y_label_formatter(&fmt_ms_axis)
            .label_style((FONT, 15))
            .axis_desc_style((FONT, 17))
            .draw()
            .map_err(|e| err(&e))?;
        for (i, s) in series.iter().enumerate() {
            let color = COLORS[i % COLORS.len()];
            let p: Vec<(f64, f64)> = s.points.iter().filter(ok).copied().collect();
            chart
                .draw_series(LineSeries::new(p.iter().copied(), color.stroke_width(2)))
                .map_err(|e| err(&e))?
                .label(s.path.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            chart
                .draw_series(p.iter().map(|&q| Circle::new(q, 4, color.filled())))
                .map_err(|e| err(&e))?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 15))
            .position(SeriesLabelPosition::UpperLeft)
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    let img = image::RgbImage::from_raw(w, h, buf)
        .ok_or_else(|| anyhow!("plot buffer has the wrong size"))?;
    create_parent(path)?;
    img.save_with_format(path, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::table::tests::rows;

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
