//! Every pass of every measured setting against the fill-rate floor: the
//! time the opaque full-screen rate of this machine (one `invert` step,
//! measured in the same run, src/bench/post.rs) gives for one screen of
//! pixels. A pass near 1x is bound by filling pixels; a pass far above does
//! work of its own per pixel (a lighting pass: its lights; the G-buffer
//! pass: its triangles and overdraw), and docs/many-lights.md works through
//! the arithmetic for each.
//!
//! A pass that shades every light at every pixel (a deferred or forward
//! `lighting` pass, `forward`) also gets its cost per light and pixel:
//! its median over lights x width x height, in ns, the figure that compares
//! one light evaluation across paths, shader variants (`render.specialize`,
//! src/frame/variant.rs) and scenes.

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
        "  {:<28} {:<16} {:>10} {:>8} {:>14}",
        "setting", "pass", "ms", "x floor", "ns/light/px"
    );
    let pixels = f64::from(w) * f64::from(h);
    for r in rows {
        for (name, stats) in &r.passes {
            let per_light = if per_light_pass(name) && r.lights > 0 {
                let ns = stats.median * 1e6 / (r.lights as f64 * pixels);
                format!("{ns:.2}")
            } else {
                "—".to_string()
            };
            let _ = writeln!(
                s,
                "  {:<28} {:<16} {:>10.2} {:>8.2} {:>14}",
                r.setting,
                name,
                stats.median,
                stats.median / floor_ms,
                per_light
            );
        }
    }
    s
}

/// The passes whose work is a light loop at every pixel.
fn per_light_pass(name: &str) -> bool {
    matches!(name, "lighting" | "forward")
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
            .map(|l| l.split_whitespace().nth(3).unwrap())
            .collect();
        assert_eq!(ratios, ["3.00", "1.50"], "{t}");
    }

    #[test]
    fn a_lighting_pass_costs_its_median_over_lights_and_pixels() {
        // 32 lights at 800x600 in 49.92 ms: 49.92e6 ns / (32 x 480000) = 3.25 ns.
        let row = BenchRow {
            setting: "deferred".into(),
            lights: 32,
            passes: vec![
                ("gbuffer".into(), Stats::from_samples(&mut [12.0])),
                ("lighting".into(), Stats::from_samples(&mut [49.92])),
            ],
            ..BenchRow::default()
        };
        let t = table(&[row], 2.0, (800, 600));
        let last: Vec<&str> = (t.lines().skip(2))
            .map(|l| l.split_whitespace().last().unwrap())
            .collect();
        assert_eq!(last, ["—", "3.25"], "{t}");
    }
}
