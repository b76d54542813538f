//! The Pareto front of speed against error: the settings no other setting
//! beats on both frame time and error. `gloss bench` marks it on its plot
//! and prints it under its table.

use super::BenchRow;

/// The indices of the rows on the front of (frame time, `error(row)`):
/// no other row is at least as fast and at least as exact, and better in
/// one. In order of frame time. Rows with a non-finite time or error are
/// left out.
pub fn front(rows: &[BenchRow], error: impl Fn(&BenchRow) -> f64) -> Vec<usize> {
    let mut order: Vec<usize> = (0..rows.len())
        .filter(|&i| rows[i].frame.median.is_finite() && error(&rows[i]).is_finite())
        .collect();
    order.sort_by(|&a, &b| {
        (rows[a].frame.median.total_cmp(&rows[b].frame.median))
            .then(error(&rows[a]).total_cmp(&error(&rows[b])))
    });
    let mut out = Vec::new();
    let mut best = f64::INFINITY;
    for i in order {
        // Faster rows came first: this one is on the front only if it is
        // more exact than every one of them.
        if error(&rows[i]) < best {
            best = error(&rows[i]);
            out.push(i);
        }
    }
    out
}

/// "Pareto front (max error): tiled cutoff 5/256 (180 ms, 110/255) <
/// ...": the front by `what`, for the text output.
pub fn describe(rows: &[BenchRow], what: &str, error: impl Fn(&BenchRow) -> f64) -> String {
    let parts: Vec<String> = front(rows, &error)
        .into_iter()
        .map(|i| {
            let r = &rows[i];
            format!(
                "{} ({:.1} ms, {:.1}/255)",
                r.setting,
                r.frame.median,
                error(r) * 255.0
            )
        })
        .collect();
    format!(
        "Pareto front ({what}), fastest first: {}",
        parts.join(" | ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::Stats;

    fn row(name: &str, ms: f64, err: f64) -> BenchRow {
        BenchRow {
            setting: name.into(),
            frame: Stats::from_samples(&mut [ms]),
            max_abs: err,
            ..BenchRow::default()
        }
    }

    #[test]
    fn dominated_settings_are_left_out() {
        let rows = [
            row("slow exact", 100.0, 0.0),
            row("fast rough", 10.0, 0.5),
            row("dominated", 50.0, 0.6),
            row("middle", 30.0, 0.1),
            row("tie slower", 30.0, 0.2),
            row("no time", f64::NAN, 0.0),
        ];
        let f = front(&rows, |r| r.max_abs);
        let names: Vec<&str> = f.iter().map(|&i| rows[i].setting.as_str()).collect();
        assert_eq!(names, ["fast rough", "middle", "slow exact"]);
        let text = describe(&rows, "max error", |r| r.max_abs);
        assert!(
            text.starts_with(
                "Pareto front (max error), fastest first: fast rough (10.0 ms, 127.5/255) | middle"
            ),
            "{text}"
        );
    }
}
