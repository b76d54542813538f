//! The CSV file of `gloss bench` results: every figure unrounded, times in
//! milliseconds, image errors in `0..1` units per channel and x255.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Context;

use super::create_parent;
use super::table::{BenchRow, pass_names, pass_stats, speedup_vs_forward};

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
        "flip_mean",
        "fragments_per_pixel",
        "bound_max_x255",
        "bound_pct_over_1",
        "shadow_misclassified_pct",
        "shadow_acne_pct",
        "shadow_peter_panning",
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
        c.push(r.flip.map_or_else(String::new, csv_num));
        c.push(r.fragments_per_pixel.map_or_else(String::new, csv_num));
        let b = r.bound.as_ref();
        c.push(b.map_or_else(String::new, |b| csv_num(b.max * 255.0)));
        c.push(b.map_or_else(String::new, |b| csv_num(b.pct_over_1)));
        let s = r.shadow.as_ref();
        c.push(s.map_or_else(String::new, |s| csv_num(s.misclassified * 100.0)));
        c.push(s.map_or_else(String::new, |s| csv_num(s.acne * 100.0)));
        let gap = s.and_then(|s| s.peter_panning);
        c.push(gap.map_or_else(String::new, |g| csv_num(g.into())));
        c.push(r.clock.clone());
        let _ = writeln!(out, "{}", join(c));
    }
    out
}

/// Writes [`csv`]`(rows)` to `path`: a header and one line per row, with
/// median/p10/p90 columns for every pass any row has (empty where a row lacks
/// it). Creates the parent directory.
pub fn write_csv(rows: &[BenchRow], path: &Path) -> anyhow::Result<()> {
    create_parent(path)?;
    std::fs::write(path, csv(rows)).with_context(|| format!("writing {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::table::tests::rows;

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
        assert_eq!(col("flip_mean"), "0.004");
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
}

#[cfg(test)]
mod shadow_tests {
    use super::*;
    use crate::bench::table::{table, tests::rows};
    use crate::image_compare::shadow_metrics::ShadowErrors;

    #[test]
    fn shadow_errors_get_their_columns_in_the_table_and_the_csv() {
        let mut r = rows();
        assert!(!table(&r).contains("acne %"));
        r[0].shadow = Some(ShadowErrors {
            misclassified: 0.0125,
            acne: 0.5,
            peter_panning: Some(0.25),
            judged: 100,
            judged_lit: 50,
        });
        let t = table(&r);
        assert!(
            t.contains("misclass %") && t.contains("1.250") && t.contains("50.000"),
            "{t}"
        );
        let text = csv(&r);
        let lines: Vec<&str> = text.lines().collect();
        let header: Vec<&str> = lines[0].split(',').collect();
        let at = |h: &str| header.iter().position(|x| *x == h).unwrap();
        let first: Vec<&str> = lines[1].split(',').collect();
        assert_eq!(first[at("shadow_misclassified_pct")], "1.25");
        assert_eq!(first[at("shadow_peter_panning")], "0.25");
        let second: Vec<&str> = lines[2].split(',').collect();
        assert_eq!(second[at("shadow_acne_pct")], "");
    }
}
