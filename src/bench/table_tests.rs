//! Tests of src/bench/table.rs, and the rows the CSV and plot tests share.

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

pub(crate) fn rows() -> Vec<BenchRow> {
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
        flip: Some(rmse * 2.0),
        bound: None,
        fragments_per_pixel: None,
        shadow: None,
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
        "FLIP",
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
        "0.0040",
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
fn cutoff_labels() {
    assert_eq!(cutoff_label(5.0 / 256.0, Some(4)), "5/256");
    assert_eq!(cutoff_label(5.0 / 256.0, None), "5/256");
    assert_eq!(cutoff_label(0.01, Some(4)), "0.0100");
    assert_eq!(cutoff_label(0.01, None), "0.01");
    assert_eq!(cutoff_label(f32::NAN, None), DASH);
}
