//! `gloss bench` runs end to end and writes its table, CSV and plot. (It
//! measures speed; no test here asserts a time, only that the error column
//! is right: forward against itself is exact, light volumes with a cutoff
//! are not.)

use std::process::Command;

#[path = "common/mod.rs"]
mod common;

#[test]
fn bench_writes_table_csv_and_plot() {
    let out = std::env::temp_dir().join("gloss-bench-test");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            "bench",
            "scenes/many-lights.toml",
            "--paths",
            "forward,volumes",
            "--lights",
            "4,16",
        ])
        .args([
            "--cutoffs",
            "5/256",
            "--frames",
            "2",
            "--warmup",
            "1",
            "--size",
            "96x54",
            "--out",
        ])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("forward") || l.starts_with("volumes"))
        .collect();
    assert_eq!(rows.len(), 4, "{stdout}");
    // forward is the reference: zero error, speed-up 1.00x.
    for r in rows.iter().filter(|r| r.starts_with("forward")) {
        assert!(r.contains("1.00×") && r.contains("0.000"), "{r}");
    }
    assert!(
        stdout.contains("cpu+glFinish"),
        "the clock is named: {stdout}"
    );
    let csv = std::fs::read_to_string(out.join("bench.csv")).unwrap();
    assert_eq!(csv.lines().count(), 5, "{csv}");
    let png = image::open(out.join("bench.png")).unwrap();
    assert!(png.width() > 100 && png.height() > 100);
}

#[test]
fn bench_rejects_bad_arguments() {
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            "bench",
            "scenes/plane.toml",
            "--lights",
            "16",
            "--frames",
            "1",
            "--size",
            "32x32",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains("has no [light_grid]"), "{err}");
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "--cutoffs", "2"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("expected a fraction in (0, 1)"));
    // --paths with --vary would be ignored: it is refused instead.
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "--paths", "forward", "--vary", "render.cutoff=0.1"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("'--paths <PATHS>' cannot be used with '--vary"),
        "{err}"
    );
}

#[test]
fn bench_varies_any_scene_key_against_a_reference() {
    // The mirror's recursion depths against the deepest reflection: the
    // error falls as the depth grows, and the reference's own setting is exact.
    let out = std::env::temp_dir().join("gloss-bench-vary");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "scenes/mirrors-recursive.toml"])
        .args(["--vary", "render.mirror_depth=1,3,8"])
        .args(["--reference", "render.mirror_depth=8"])
        .args([
            "--frames", "1", "--warmup", "0", "--size", "160x90", "--out",
        ])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rmse: Vec<f64> = stdout
        .lines()
        .filter(|l| l.starts_with("render.mirror_depth="))
        .map(|l| {
            // RMSE is the fifth column from the end (RMSE, max, %, frags/px, clock).
            let cols: Vec<&str> = l.split_whitespace().collect();
            cols[cols.len() - 5].parse().unwrap()
        })
        .collect();
    assert_eq!(rmse.len(), 3, "{stdout}");
    assert!(rmse[0] > rmse[1] && rmse[1] > rmse[2], "{rmse:?}\n{stdout}");
    assert_eq!(rmse[2], 0.0, "{stdout}");
    assert!(
        stdout.contains("mirror mark"),
        "mirror passes are timed: {stdout}"
    );
    // A bad key is refused before anything is measured.
    let bad = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            "bench",
            "scenes/mirrors-recursive.toml",
            "--vary",
            "render.no_such=1",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no_such"));
}

#[test]
fn the_post_floor_counts_each_pass_at_the_size_it_draws() {
    // Bloom's blurs run in mip levels 1-4: at 160x90 they fill 80x45,
    // 40x22, 20x11 and 10x5 pixels, 0.330 of a screen a direction; its
    // merge and the tone map fill one screen each.
    let out = std::env::temp_dir().join("gloss-bench-post-floor");
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "scenes/bloom.toml"])
        .args(["--vary", "render.post_chain=ping_pong"])
        .args(["--reference", "render.post_chain=ping_pong"])
        .args([
            "--frames", "1", "--warmup", "0", "--size", "160x90", "--out",
        ])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let row = |name: &str| -> (usize, f64) {
        let l = (stdout.lines())
            .find(|l| l.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("no row {name}:\n{stdout}"));
        let cols: Vec<&str> = l[name.len() + 2..].split_whitespace().collect();
        (cols[0].parse().unwrap(), cols[1].parse().unwrap())
    };
    let level = 80.0 * 45.0 + 40.0 * 22.0 + 20.0 * 11.0 + 10.0 * 5.0;
    let want = format!("{:.3}", level / (160.0 * 90.0));
    for name in ["bloom downsample", "bloom blur h", "bloom blur v"] {
        let (steps, screens) = row(name);
        assert_eq!(steps, 4, "{name}\n{stdout}");
        assert_eq!(format!("{screens:.3}"), want, "{name}\n{stdout}");
    }
    assert_eq!(row("bloom merge"), (1, 1.0), "{stdout}");
    assert_eq!(row("tone mapping"), (1, 1.0), "{stdout}");
}

#[test]
fn bench_applies_set_to_every_setting() {
    // With --vary, --set comes first and the varied keys after it: every
    // row is on the tiled path, and the reference (forward) is exact.
    let out = std::env::temp_dir().join("gloss-bench-set");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "scenes/many-lights.toml"])
        .args(["--set", "render.path=tiled"])
        .args(["--vary", "render.depth_slices=1,4"])
        .args(["--reference", "render.path=forward"])
        .args(["--frames", "1", "--warmup", "0", "--size", "96x54", "--out"])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows: Vec<&str> = (stdout.lines())
        .filter(|l| l.starts_with("render.depth_slices="))
        .collect();
    assert_eq!(rows.len(), 2, "{stdout}");
    for r in rows {
        assert_eq!(r.split_whitespace().nth(1), Some("tiled"), "{stdout}");
    }
    // Without --vary, --set reaches the scene too: a bad value is refused.
    let bad = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "scenes/many-lights.toml", "--paths", "tiled"])
        .args(["--set", "render.depth_slices=0"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(!bad.status.success());
    assert!(
        String::from_utf8_lossy(&bad.stderr).contains("render.depth_slices"),
        "{}",
        String::from_utf8_lossy(&bad.stderr)
    );
}

#[test]
fn bench_scaling_measures_lights_and_pixels() {
    let out = std::env::temp_dir().join("gloss-bench-scaling");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "--scaling", "--frames", "1", "--warmup", "1"])
        .args(["--size", "64x36", "--out"])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // 16 to 4096 lights: radius halves for every fourfold count, about as
    // many lights reach a pixel at every count, and only the tiled path
    // takes more lights than the uniform block holds.
    let rows: Vec<Vec<&str>> = (stdout.lines())
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|c| c.len() >= 4 && ["16", "64", "256", "1024", "4096"].contains(&c[0]))
        .collect();
    assert_eq!(rows.len(), 5, "{stdout}");
    let radius: Vec<f64> = rows.iter().map(|c| c[1].parse().unwrap()).collect();
    for pair in radius.windows(2) {
        // Printed to 3 decimals.
        assert!((pair[0] / pair[1] - 2.0).abs() < 3e-3, "{radius:?}");
    }
    let reach: Vec<f64> = rows.iter().map(|c| c[2].parse().unwrap()).collect();
    assert!(reach.iter().all(|&r| r > 1.0), "{reach:?}\n{stdout}");
    assert!(rows[4].join(" ").contains("uniform block"), "{stdout}");
    // The tiled cell: frame ms, then in brackets ns per light and pixel,
    // the frame over 4096 lights x 64 x 36 pixels.
    let n = rows[4].len();
    let tiled: f64 = rows[4][n - 2].parse().unwrap();
    assert!(tiled > 0.0, "{stdout}");
    let ns: f64 = (rows[4][n - 1].trim_matches(|c| c == '(' || c == ')'))
        .parse()
        .unwrap();
    let expect = tiled * 1e6 / (4096.0 * 64.0 * 36.0);
    assert!(
        (ns - expect).abs() <= 5e-4 + expect * 1e-3,
        "{ns} {expect}\n{stdout}"
    );
    // Four frame sizes, half to twice the measured one.
    for size in ["32x18", "64x36", "96x54", "128x72"] {
        assert!(
            stdout.lines().any(|l| l.trim_start().starts_with(size)),
            "{stdout}"
        );
    }
    for png in ["scaling-lights.png", "scaling-pixels.png"] {
        let img = image::open(out.join(png)).unwrap();
        assert_eq!((img.width(), img.height()), gloss::bench::PLOT_SIZE);
    }
}

#[test]
fn bench_prints_the_far_fields_bound_and_every_pass_against_the_floor() {
    let out = std::env::temp_dir().join("gloss-bench-far-field");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "scenes/far-field.toml"])
        .args(["--vary", "render.far_field=1,4"])
        .args(["--reference", "render.far_field=1"])
        .args([
            "--frames", "1", "--warmup", "0", "--size", "160x90", "--out",
        ])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("bound max×255"), "{stdout}");
    // k = 1 samples every pixel itself: its bound is the stored values'
    // rounding, under one 8-bit step; k = 4 has a bound of its own.
    let bound_max = |prefix: &str| -> f64 {
        let line = stdout.lines().find(|l| l.starts_with(prefix)).unwrap();
        let cols: Vec<&str> = line.split_whitespace().collect();
        // bound max, bound %, clock are the last three columns.
        cols[cols.len() - 3].parse().unwrap()
    };
    assert!(bound_max("render.far_field=1 ") < 1.0, "{stdout}");
    assert!(bound_max("render.far_field=4 ") > 0.0, "{stdout}");
    assert!(
        stdout.contains("each pass against the fill-rate floor at 160x90"),
        "{stdout}"
    );
    for pass in ["gbuffer", "far field", "lighting", "composite"] {
        assert!(
            stdout.lines().any(|l| l.contains("render.far_field=4")
                && l.split_whitespace()
                    .collect::<Vec<_>>()
                    .join(" ")
                    .contains(&format!(" {pass} "))),
            "{pass}: {stdout}"
        );
    }
    let csv = std::fs::read_to_string(out.join("bench.csv")).unwrap();
    assert!(
        csv.lines().next().unwrap().contains("bound_max_x255"),
        "{csv}"
    );
}

#[test]
fn bench_measures_the_particles_both_ways() {
    let stdout = common::gloss(&[
        "bench",
        "--particles",
        "200",
        "--frames",
        "1",
        "--warmup",
        "0",
        "--size",
        "96x54",
    ]);
    let rows: Vec<&str> = stdout
        .lines()
        .filter(|l| l.trim_start().starts_with("200 ") && l.contains(" gl"))
        .collect();
    assert_eq!(rows.len(), 4, "{stdout}");
    // Points: 16 bytes a particle; CPU quads: 144.
    assert!(rows[0].contains("3200"), "{stdout}");
    assert!(rows[2].contains("28800"), "{stdout}");
    assert!(
        stdout.contains("200 particles: the geometry shader sends 89% fewer bytes"),
        "{stdout}"
    );
}

#[test]
fn bench_measures_instancing_both_ways_with_equal_images() {
    let stdout = common::gloss(&[
        "bench",
        "--instancing",
        "300",
        "--frames",
        "1",
        "--warmup",
        "0",
        "--size",
        "96x54",
    ]);
    let rows: Vec<&str> = (stdout.lines())
        .filter(|l| l.trim_start().starts_with("300 ") && !l.contains("rocks:"))
        .collect();
    assert_eq!(rows.len(), 2, "{stdout}");
    // Instanced: no transforms a frame; one draw per rock: 64 bytes each.
    assert!(
        rows[0].contains("instanced") && rows[0].contains(" 0 "),
        "{stdout}"
    );
    assert!(rows[1].contains("19200"), "{stdout}");
    assert!(
        stdout.contains("images differ by at most 0/255"),
        "{stdout}"
    );
}

#[test]
fn front_to_back_shades_fewer_fragments_a_pixel() {
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            "bench",
            "scenes/many-lights.toml",
            "--set",
            "light_grid.count=4",
        ])
        .args(["--vary", "render.sort_opaque=false,true"])
        .args([
            "--reference",
            "render.path=forward",
            "--set",
            "render.path=forward",
        ])
        .args(["--frames", "1", "--warmup", "0", "--size", "160x90"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let frags = |prefix: &str| -> f64 {
        let line = stdout.lines().find(|l| l.starts_with(prefix)).unwrap();
        let cols: Vec<&str> = line.split_whitespace().collect();
        // frags/px, then the clock.
        cols[cols.len() - 2].parse().unwrap()
    };
    let (unsorted, sorted) = (
        frags("render.sort_opaque=false"),
        frags("render.sort_opaque=true"),
    );
    assert!(
        sorted < unsorted,
        "front to back {sorted} against the file's order {unsorted}\n{stdout}"
    );
    assert!(sorted > 0.1, "{stdout}");
}

/// `gloss bench --filtering` (src/bench/filtering.rs): one row a filter,
/// each with its error against the 64-sample reference. Mip mapping is what
/// removes the far floor's aliasing: the filters that read a mip level are
/// closer to the reference than those that read level 0 alone, and
/// anisotropic filtering is no farther than trilinear.
#[test]
fn bench_measures_texture_filters_against_a_supersampled_reference() {
    let out = std::env::temp_dir().join("gloss-bench-filtering");
    let o = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["bench", "--filtering", "--frames", "1", "--warmup", "0"])
        .args(["--size", "320x180", "--out"])
        .arg(&out)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rmse = |filter: &str| -> f64 {
        let row = (stdout.lines())
            .find(|l| l.split_whitespace().next() == Some(filter))
            .unwrap_or_else(|| panic!("no row for {filter}: {stdout}"));
        row.split_whitespace().last().unwrap().parse().unwrap()
    };
    let (nearest, bilinear) = (rmse("nearest"), rmse("bilinear"));
    let (trilinear, anisotropic) = (rmse("trilinear"), rmse("anisotropic"));
    assert!(nearest.is_finite() && nearest > 0.0, "{stdout}");
    assert!(trilinear < 0.8 * nearest.min(bilinear), "{stdout}");
    assert!(rmse("bilinear_mip") < nearest.min(bilinear), "{stdout}");
    assert!(anisotropic <= trilinear + 0.1, "{stdout}");
    assert!(out.join("filtering.csv").is_file());
}
