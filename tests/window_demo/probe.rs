//! The pixel probe in the window: a click in the 3D view probes the pixel
//! under the pointer (the view starts right of the panel, where the demo's
//! layout says), and what the demo reads there equals what
//! `gloss probe` reads at that pixel of a headless frame of the view's size
//! (tests/demo/probe.rs checks `gloss probe` against the CPU's geometry).
//! With GLOSS_BLESS=1 the test writes its window, the probe shown in the
//! panel, to docs/images/demo-probe.png.

use crate::{GLOSS, crate_dir, drive, shot};
use std::process::Command;

/// The read-outs the demo printed, each between "gloss: probe" and
/// "gloss: probe end".
fn printed(log: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current: Option<String> = None;
    for line in log.lines() {
        match line {
            "gloss: probe" => current = Some(String::new()),
            "gloss: probe end" => out.extend(current.take()),
            _ => {
                if let Some(c) = current.as_mut() {
                    c.push_str(line);
                    c.push('\n');
                }
            }
        }
    }
    out
}

/// The numbers of a line, and the line with each number replaced by "#".
fn numbers(line: &str) -> (String, Vec<f64>) {
    let mut words = String::new();
    let mut values = Vec::new();
    let mut number = String::new();
    let flush = |number: &mut String, words: &mut String, values: &mut Vec<f64>| {
        if number.is_empty() {
            return;
        }
        match number.parse::<f64>() {
            Ok(v) => {
                values.push(v);
                words.push('#');
            }
            Err(_) => words.push_str(number),
        }
        number.clear();
    };
    for c in line.chars() {
        let starts = c == '-' && number.is_empty();
        if c.is_ascii_digit() || c == '.' || starts {
            number.push(c);
        } else {
            flush(&mut number, &mut words, &mut values);
            words.push(c);
        }
    }
    flush(&mut number, &mut words, &mut values);
    (words, values)
}

/// Two read-outs say the same: the same lines, each number within a few
/// thousandths (the window's orbit camera rebuilds the eye from angles;
/// an 8-bit colour step is 0.0039).
fn assert_same(demo: &str, cli: &str) {
    let (a, b): (Vec<&str>, Vec<&str>) = (demo.lines().collect(), cli.lines().collect());
    assert_eq!(
        a.len(),
        b.len(),
        "the demo's probe:\n{demo}\ngloss probe:\n{cli}"
    );
    for (x, y) in a.iter().zip(&b) {
        let ((wx, vx), (wy, vy)) = (numbers(x), numbers(y));
        assert_eq!(wx, wy, "the demo's probe:\n{demo}\ngloss probe:\n{cli}");
        for (p, q) in vx.iter().zip(&vy) {
            assert!(
                (p - q).abs() <= 5e-3 * p.abs().max(1.0),
                "{x}\n{y}\nthe demo's probe:\n{demo}\ngloss probe:\n{cli}"
            );
        }
    }
}

#[test]
fn a_click_in_the_view_probes_the_pixel_gloss_probe_reads() {
    let script = r#"
        start --window 1280x720 shadows-directional
        read -r x0 y0 x1 y1 <<< "$(widget "3D view")"
        echo "$x0" > view_x
        xdotool mousemove --window "$wid" $((x0 + 460)) 500 click 1
        wait_log "gloss: probe end"
        xdotool mousemove --window "$wid" $((x0 + 530)) 400 click 1
        for _ in $(seq 1200); do
            [ "$(grep -c 'gloss: probe end' gloss.log)" -ge 2 ] && break; sleep 0.1
        done
        key shift+F12; shot 1
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-probe", "1280x720x24", script) else {
        return;
    };
    let probes = printed(&log);
    assert_eq!(probes.len(), 2, "two clicks, two read-outs:\n{log}");
    // Where the 3D view starts (the panel's edge), from the demo's layout.
    let x0: u32 = std::fs::read_to_string(dir.join("view_x"))
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    assert!(
        (300..400).contains(&x0),
        "the view beside a panel of about 340 px starts at {x0}"
    );
    for (probe, (x, y)) in probes.iter().zip([(460, 500), (530, 400)]) {
        // The pixel under the pointer, counted in the view.
        let first = probe.lines().next().unwrap();
        let want = format!("pixel ({x}, {y}) of the ");
        assert!(first.starts_with(&want), "{first}: wanted {want}");
        let size = first.split(" of the ").nth(1).unwrap();
        let size = size.split(' ').next().unwrap();
        let out = Command::new(GLOSS)
            .args(["--debug", "probe", "shadows-directional"])
            .args([x.to_string(), y.to_string()])
            .args(["--size", size])
            .current_dir(crate_dir())
            .output()
            .unwrap();
        let cli = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert_same(probe, &cli);
    }
    // The second click lands in the ball's shadow on the floor.
    assert!(
        probes[1].contains(": in shadow at the centre texel")
            && probes[1].contains("visibility 0.0000"),
        "the ball's shadow:\n{}",
        probes[1]
    );
    let window = shot(&dir, &log, 1);
    if std::env::var("GLOSS_BLESS").as_deref() == Ok("1") {
        let small = image::imageops::resize(&window, 960, 540, image::imageops::Triangle);
        small
            .save(crate_dir().join("docs/images/demo-probe.png"))
            .unwrap();
    }
}
