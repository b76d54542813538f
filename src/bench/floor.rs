//! Every pass of every measured setting against the fill-rate floor: the
//! time the opaque full-screen rate of this machine (one `invert` step,
//! measured in the same run, src/bench/post.rs) gives for one screen of
//! pixels. A pass near 1x is bound by filling pixels; a pass far above does
//! work of its own per pixel (a lighting pass: its lights; the G-buffer
//! pass: its triangles and overdraw), and docs/many-lights.md works through
//! the arithmetic for each.

use super::BenchRow;
use std::fmt::Write as _;

/// The table: for each row, each pass's median, the floor and the ratio.
pub fn table(rows: &[BenchRow], floor_ms: f64, size: (u32, u32)) -> String {
    let (w, h) = size;
    let rate = f64::from(w) * f64::from(h) / 1e6 / (floor_ms / 1e3);
    let mut s = format!(
        "each pass against the fill-rate floor at {w}x{h}: one opaque full-screen pass {floor_ms:.2} ms ({rate:.0} Mpixel/s)\n"
    );
    let _ = writeln!(
        s,
        "  {:<28} {:<16} {:>10} {:>8}",
        "setting", "pass", "ms", "x floor"
    );
    for r in rows {
        for (name, stats) in &r.passes {
            let _ = writeln!(
                s,
                "  {:<28} {:<16} {:>10.2} {:>8.2}",
                r.setting,
                name,
                stats.median,
                stats.median / floor_ms
            );
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::Stats;

    #[test]
    fn ratios_are_against_the_floor() {
        let row = BenchRow {
            setting: "tiled".into(),
            passes: vec![
                ("gbuffer".into(), Stats::from_samples(&mut [6.0])),
                ("composite".into(), Stats::from_samples(&mut [3.0])),
            ],
            ..BenchRow::default()
        };
        let t = table(&[row], 2.0, (100, 100));
        assert!(t.contains("(5 Mpixel/s)"), "{t}");
        let ratios: Vec<&str> = (t.lines().skip(2))
            .map(|l| l.split_whitespace().last().unwrap())
            .collect();
        assert_eq!(ratios, ["3.00", "1.50"], "{t}");
    }
}
