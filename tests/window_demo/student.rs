//! Issue 29's list walked through as a student would, each item read back
//! from the window (its screenshots and the panel's layout, src/demo/layout.rs):
//! Tab in a text field stays egui's and a click in the view gives the keys
//! back; `--no-panel` then Tab shows the panel; the window's size; passes
//! named by what they draw; a status message moves no widget; logarithmic
//! sliders and colour pickers; the frame time shown; particles play.

use crate::{differing, drive, layout_rect, shot};
use std::path::Path;

fn layout(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap_or_default()
}

/// The window's size in a layout file's first line.
fn window(layout: &str) -> (u32, u32) {
    let first = layout.lines().next().unwrap_or_default();
    let size = first.split("\"window\":[").nth(1).unwrap_or_default();
    let v: Vec<u32> = size
        .trim_end_matches(['}', ']'])
        .split(',')
        .filter_map(|n| n.parse().ok())
        .collect();
    assert_eq!(v.len(), 2, "no window size in {first}");
    (v[0], v[1])
}

/// The input widgets of a layout: each line's label, kind and rectangle.
fn inputs(layout: &str) -> Vec<String> {
    layout
        .lines()
        .filter(|l| l.contains("\"input\":true"))
        .map(|l| l.split(",\"toggled\"").next().unwrap_or(l).to_string())
        .map(|l| l.split(",\"value\"").next().unwrap_or(&l).to_string())
        .map(|l| l.split(",\"text\"").next().unwrap_or(&l).to_string())
        .collect()
}

#[test]
fn tab_in_a_text_field_is_egui_s_and_a_click_in_the_view_gives_the_keys_back() {
    let script = r#"
        start --window 1280x720 default
        click_widget "scene path"
        p=$(layout_pass); key Tab; next_pass "$p"; next_pass "$((p + 1))"
        cp layout.jsonl editing.jsonl
        # A click in the view takes the focus from the field: Tab is the demo's.
        xdotool mousemove 900 400 click 1
        sleep 0.5
        p=$(layout_pass); key Tab; next_pass "$p"; next_pass "$((p + 1))"
        cp layout.jsonl clicked.jsonl
        quit
    "#;
    let Some((dir, _)) = drive("gloss-window-student-tab", "1280x720x24", script) else {
        return;
    };
    assert!(
        layout_rect(&layout(&dir, "editing.jsonl"), "panel").is_some(),
        "Tab while the scene path is edited hid the panel"
    );
    assert_eq!(
        layout_rect(&layout(&dir, "clicked.jsonl"), "panel"),
        None,
        "after a click in the view, Tab did not hide the panel"
    );
    let script = r#"
        start --window 1280x720 --no-panel default
        cp layout.jsonl no-panel.jsonl
        p=$(layout_pass); key Tab; next_pass "$p"; next_pass "$((p + 1))"
        cp layout.jsonl tab.jsonl
        quit
    "#;
    let Some((dir, _)) = drive("gloss-window-student-no-panel", "1280x720x24", script) else {
        return;
    };
    assert_eq!(
        layout_rect(&layout(&dir, "no-panel.jsonl"), "panel"),
        None,
        "--no-panel shows the panel"
    );
    assert!(
        layout_rect(&layout(&dir, "tab.jsonl"), "panel").is_some(),
        "with --no-panel, Tab did not bring the panel"
    );
}

#[test]
fn the_window_opens_at_the_scenes_size_fitted_to_the_screen_or_as_asked() {
    let mut layouts = Vec::new();
    for (name, args) in [
        ("default", "default"),
        ("mirror", "mirror-covered"),
        ("asked", "--window 1000x600 default"),
    ] {
        let script = format!("start {args}\nsleep 2\ncp layout.jsonl out.jsonl\nquit\n");
        let Some((dir, _)) = drive(
            &format!("gloss-window-student-size-{name}"),
            "1280x720x24",
            &script,
        ) else {
            return;
        };
        layouts.push(layout(&dir, "out.jsonl"));
    }
    // default: render.size 1280x720 and the 340-pixel panel, 1620x720,
    // scaled by 1280 / 1620 to fit the 1280x720 screen.
    let s = 1280.0 / 1620.0_f64;
    let fitted = ((1620.0 * s).floor() as u32, (720.0 * s).floor() as u32);
    assert_eq!(window(&layouts[0]), fitted);
    // mirror-covered: 640x360 and the panel fit as they are.
    assert_eq!(window(&layouts[1]), (980, 360));
    assert_eq!(window(&layouts[2]), (1000, 600));
    // The mirror frame's timing rows are named by what they draw.
    let mirror = &layouts[1];
    assert!(
        mirror.contains("forward (reflection in mirror"),
        "no timing row names the reflection's pass:\n{mirror}"
    );
}

#[test]
fn a_status_message_moves_no_widget_and_sliders_and_colours_are_as_promised() {
    let script = r#"
        start --window 1280x720 --set render.path=volumes mixed-lights
        # Once the head shows the frame time and the timings have their rows.
        wait_layout() {
            for _ in $(seq 600); do grep -qF "$1" layout.jsonl && return 0; sleep 0.1; done
            echo "no '$1' in the layout" >&2; return 1
        }
        wait_layout " fps)"; sleep 3; next_pass "$(layout_pass)"
        cp layout.jsonl before.jsonl
        key F12; shot 1
        next_pass "$(layout_pass)"; next_pass "$(layout_pass)"
        cp layout.jsonl after.jsonl
        # A slider takes the value where the button is held down.
        read -r x0 y0 x1 y1 <<< "$(scroll_to "light-volume cutoff" Slider)"
        xdotool mousemove $(( (x0 + x1) / 2 )) $(( (y0 + y1) / 2 )); took
        xdotool mousedown 1; took
        xdotool mouseup 1; took; next_pass "$(layout_pass)"
        cp layout.jsonl slider.jsonl
        quit
    "#;
    let Some((dir, _)) = drive("gloss-window-student-panel", "1280x720x24", script) else {
        return;
    };
    let (before, after) = (layout(&dir, "before.jsonl"), layout(&dir, "after.jsonl"));
    assert!(
        after.contains("gloss-screenshot-1.png"),
        "the screenshot's path is not shown:\n{after}"
    );
    assert_eq!(
        inputs(&before),
        inputs(&after),
        "a status message moved the panel's widgets"
    );
    // The cutoff's slider is logarithmic: its middle is the geometric
    // mean of 1e-5 and 0.5 (2.2e-3), not the arithmetic one (0.25).
    let slider = layout(&dir, "slider.jsonl");
    let value: f64 = slider
        .lines()
        .find(|l| l.starts_with("{\"label\":\"light-volume cutoff\",\"kind\":\"Slider\""))
        .and_then(|l| l.split("\"value\":").nth(1))
        .and_then(|v| v.trim_end_matches('}').parse().ok())
        .expect("the cutoff slider's value");
    let mean = (1e-5_f64 * 0.5).sqrt();
    assert!(
        value / mean > 0.6 && value / mean < 1.6,
        "the cutoff's slider at its middle: {value}, the geometric mean {mean}"
    );
    // A colour within 0..1 has a colour picker beside its numbers.
    assert!(
        before.contains("{\"label\":\"ambient\",\"kind\":\"ColorWell\""),
        "no colour picker for the ambient colour"
    );
    // The frame time and frames per second in the panel's head.
    assert!(
        before
            .lines()
            .any(|l| l.contains(" ms (") && l.contains(" fps)")),
        "no frame time shown"
    );
}

#[test]
fn particles_start_playing_and_keep_playing() {
    let script = r#"
        start --window 1280x720 particles
        sleep 2
        toggled play > playing
        key F12; shot 1
        sleep 2
        toggled play >> playing
        key F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-student-play", "1280x720x24", script) else {
        return;
    };
    let playing = std::fs::read_to_string(dir.join("playing")).unwrap_or_default();
    assert_eq!(playing, "true\ntrue\n", "play is not ticked");
    let (a, b) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    assert!(
        differing(&a, &b, 4) > 0.001,
        "the fountain stood still: {:.4} changed",
        differing(&a, &b, 4)
    );
}
