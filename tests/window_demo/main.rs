//! The demo's window driven as a student drives it (src/demo/): Xvfb, keys
//! and the mouse from xdotool, the window's own screenshots (F12: the 3D
//! view; Shift+F12: the whole window with the panel) read back as pixels.
//!
//! Every wait polls for the file or the log line it needs, with a deadline,
//! so that a loaded machine is slow but not wrong; the whole script runs
//! under `timeout`. Needs `xvfb-run` and `xdotool` (.ci/run installs them);
//! GLOSS_SKIP_WINDOW_TEST=1 skips these tests where a machine cannot have them.

mod area_lights;
mod input;
mod layout;
mod panel_fit;
mod pictures;
mod probe;
mod strip;
mod student;
mod switches;
mod techniques;

use std::path::{Path, PathBuf};
use std::process::Command;

pub const GLOSS: &str = env!("CARGO_BIN_EXE_gloss");

pub fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Shell functions the scripts use: `start ARGS` starts gloss (its output
/// in gloss.log, its panel's layout in layout.jsonl) and focuses its window;
/// `shot N` waits until the demo says it wrote gloss-screenshot-N.png; `key
/// K` presses a key; `quit` ends it.
///
/// Widgets are found by name, never by coordinates: the demo writes where
/// every named widget is after each time egui lays the panel out
/// (`GLOSS_DEMO_LAYOUT`, src/demo/layout.rs). `widget LABEL [ABOUT]` prints the
/// rectangle `x0 y0 x1 y1` (window pixels) of the input widget named LABEL
/// (a choice's word ABOUT the knob so labelled, or of that kind: `Slider`,
/// `SpinButton`, `CheckBox` ...), or of the one label or area
/// so named when no input is; more than one match, or none, is an error
/// that lists the layout. `scroll_to LABEL [ABOUT]` turns the mouse wheel
/// over the panel until the widget is inside its scrolling part and has
/// stopped moving, and prints its rectangle; `click_widget LABEL [ABOUT]`
/// scrolls to it, then presses and releases the left button on its centre, and waits
/// until the panel shows what the click did. `toggled LABEL
/// [ABOUT]` prints a checkbox's or choice's state (true / false).
const PRELUDE: &str = r#"
set -e
wait_log() {
    for _ in $(seq 1200); do grep -q "$1" gloss.log 2>/dev/null && return 0; sleep 0.1; done
    echo "timed out waiting for '$1' in gloss.log" >&2; cat gloss.log >&2; return 1
}
layout_pass() { head -n 1 layout.jsonl 2>/dev/null | sed -n 's/^{"pass":\([0-9]*\),.*/\1/p'; }
next_pass() {
    for _ in $(seq 600); do
        p=$(layout_pass); [ -n "$p" ] && [ "$p" -gt "$1" ] && return 0; sleep 0.1
    done
    echo "the demo wrote no layout after pass $1" >&2; return 1
}
json_str() { printf '%s' "$1" | sed 's/\\/\\\\/g; s/"/\\"/g'; }
widget_line() {
    local lines inputs n
    lines=$(grep -F "{\"label\":\"$(json_str "$1")\"," layout.jsonl || true)
    if [ -n "${2:-}" ]; then
        lines=$(printf '%s\n' "$lines" \
            | grep -F -e "\"about\":\"$(json_str "$2")\"" -e "\"kind\":\"$(json_str "$2")\"" || true)
    fi
    inputs=$(printf '%s\n' "$lines" | grep -F '"input":true' || true)
    [ -n "$inputs" ] && lines=$inputs
    n=$(printf '%s' "$lines" | grep -c . || true)
    if [ "$n" != 1 ]; then
        echo "widget '$1'${2:+ ($2)}: $n matches in the panel's layout:" >&2
        cut -c1-160 layout.jsonl >&2
        return 1
    fi
    printf '%s\n' "$lines"
}
widget() {
    local l; l=$(widget_line "$@") || return 1
    printf '%s\n' "$l" | sed -n 's/.*"rect":\[\([-0-9]*\),\([-0-9]*\),\([-0-9]*\),\([-0-9]*\)\].*/\1 \2 \3 \4/p'
}
toggled() {
    local l; l=$(widget_line "$@") || return 1
    printf '%s\n' "$l" | sed -n 's/.*"toggled":\([a-z]*\).*/\1/p'
}
# Wait until egui has run on the events sent so far: the pass being laid
# out as they were sent may have taken its input before them; the one
# after it has them (and the demo has carried out what they asked).
took() { local p; p=$(layout_pass); next_pass $((p + 1)); }
# A click: the pointer arrives and egui sees the hover, then the button
# goes down and up at once (egui's clock is its passes': a press held over
# passes a second apart on a loaded machine is a long press, not a click),
# and egui takes the click.
press_at() {
    xdotool mousemove "$1" "$2"; took
    xdotool mousedown 1 sleep 0.05 mouseup 1; took
    # The pointer then rests in the window's bottom right corner, where no
    # tooltip it raises can cover the next widget.
    read -r ww wh <<< "$(head -n 1 layout.jsonl | sed 's/.*"window":\[\([0-9]*\),\([0-9]*\)\].*/\1 \2/')"
    xdotool mousemove $((ww - 3)) $((wh - 3))
}
# The rectangle of widget "$@" once it stands still (the same in two
# passes in a row: a turn of the wheel scrolls over a few passes).
settled() {
    local a b
    a=$(widget "$@")
    for _ in $(seq 50); do
        next_pass "$(layout_pass)"
        b=$(widget "$@")
        [ "$a" = "$b" ] && { printf '%s\n' "$b"; return 0; }
        a=$b
    done
    echo "widget '$1' never stops moving" >&2; return 1
}
scroll_to() {
    local r x0 y0 x1 y1 cx cy sx0 sy0 sx1 sy1 wheel moved ww wh
    for _ in $(seq 60); do
        r=$(settled "$@")
        read -r x0 y0 x1 y1 <<< "$r"
        cx=$(( (x0 + x1) / 2 )); cy=$(( (y0 + y1) / 2 ))
        wheel=""
        if grep -q '"label":"panel scroll"' layout.jsonl; then
            read -r sx0 sy0 sx1 sy1 <<< "$(widget "panel scroll")"
            if [ "$cy" -lt $((sy0 + 3)) ]; then wheel="click 4"
            elif [ "$cy" -gt $((sy1 - 3)) ]; then wheel="click 5"
            elif [ "$cx" -gt $((sx1 - 3)) ]; then wheel="keydown shift click 5 keyup shift"
            elif [ "$cx" -lt $((sx0 + 3)) ]; then wheel="keydown shift click 4 keyup shift"
            fi
        fi
        if [ -n "$wheel" ]; then
            xdotool mousemove $(( (sx0 + sx1) / 2 )) $(( (sy0 + sy1) / 2 )) $wheel
            moved=""
            for _ in 1 2 3 4; do
                next_pass "$(layout_pass)"
                [ "$(widget "$@")" != "$r" ] && { moved=1; break; }
            done
            [ -n "$moved" ] && continue
            # The wheel does not move it: a widget outside the scrolling
            # part (the panel's head), or one past the end of the scroll.
            read -r ww wh <<< "$(head -n 1 layout.jsonl | sed 's/.*"window":\[\([0-9]*\),\([0-9]*\)\].*/\1 \2/')"
            if [ "$cx" -lt 0 ] || [ "$cy" -lt 0 ] || [ "$cx" -ge "$ww" ] || [ "$cy" -ge "$wh" ]; then
                echo "widget '$1' at ($cx, $cy) cannot be scrolled into the window" >&2; return 1
            fi
        fi
        printf '%s\n' "$r"
        return 0
    done
    echo "could not bring '$1' into the panel's view" >&2; return 1
}
click_widget() {
    local r x0 y0 x1 y1
    r=$(scroll_to "$@")
    read -r x0 y0 x1 y1 <<< "$r"
    press_at $(( (x0 + x1) / 2 )) $(( (y0 + y1) / 2 ))
    # A pass that shows the click's effect.
    next_pass "$(layout_pass)"
}
start() {
    rm -f layout.jsonl
    GLOSS_DEMO_LAYOUT="$PWD/layout.jsonl" "$GLOSS" --backend window --debug --frames 2000000 "$@" > gloss.log 2>&1 &
    pid=$!
    wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
    xdotool windowfocus --sync "$wid"
    wait_log "OpenGL"
    next_pass 0
}
key() { xdotool key --clearmodifiers "$@"; }
shot() { wait_log "gloss-screenshot-$1.png"; }
quit() { key Escape; wait $pid; }
"#;

/// Run `body` (after `PRELUDE`) under Xvfb with a `screen` such as
/// "1280x720x24", in a fresh directory `name` under the temp dir. Asserts
/// that it exits 0 and that gloss reported no error; returns the directory
/// and gloss's log. None when GLOSS_SKIP_WINDOW_TEST=1.
pub fn drive(name: &str, screen: &str, body: &str) -> Option<(PathBuf, String)> {
    if std::env::var("GLOSS_SKIP_WINDOW_TEST").as_deref() == Ok("1") {
        eprintln!("skipped: GLOSS_SKIP_WINDOW_TEST=1");
        return None;
    }
    assert!(
        Command::new("xvfb-run").arg("--help").output().is_ok()
            && Command::new("xdotool").arg("version").output().is_ok(),
        "xvfb-run and xdotool are needed (.ci/run installs them), \
         or set GLOSS_SKIP_WINDOW_TEST=1 to skip this test"
    );
    let dir = std::env::temp_dir().join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out = Command::new("xvfb-run")
        .args(["-a", "-s", &format!("-screen 0 {screen}")])
        .args(["timeout", "240", "bash", "-c"])
        .arg(format!("{PRELUDE}\n{body}"))
        .env("GLOSS", GLOSS)
        .current_dir(&dir)
        .output()
        .expect("could not start xvfb-run");
    let log = std::fs::read_to_string(dir.join("gloss.log")).unwrap_or_default();
    assert!(
        out.status.success(),
        "the driven demo failed ({})\n--- stdout ---\n{}\n--- stderr ---\n{}\n--- gloss.log ---\n{log}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        !log.to_lowercase().contains("error") && !log.contains("panicked"),
        "the demo reported an error:\n{log}"
    );
    Some((dir, log))
}

/// Screenshot `n` of a driven demo.
pub fn shot(dir: &Path, log: &str, n: u32) -> image::RgbaImage {
    let p = dir.join(format!("gloss-screenshot-{n}.png"));
    image::open(&p)
        .unwrap_or_else(|e| panic!("{}: {e}\n--- gloss.log ---\n{log}", p.display()))
        .to_rgba8()
}

/// `gloss render SCENE ARGS --size WxH` headless, written to
/// DIR/reference.png and read back: what the window's view should show.
pub fn headless_render(
    dir: &Path,
    scene: &str,
    args: &[&str],
    (w, h): (u32, u32),
) -> image::RgbaImage {
    let out_path = dir.join("reference.png");
    let out = Command::new(GLOSS)
        .args(["render", scene, "--size", &format!("{w}x{h}"), "-o"])
        .arg(&out_path)
        .args(args)
        .current_dir(crate_dir())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "gloss render {scene} {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    image::open(&out_path).unwrap().to_rgba8()
}

/// The share of pixels of `a` and `b` (of one size) that differ by more
/// than `tolerance` in some channel.
pub fn differing(a: &image::RgbaImage, b: &image::RgbaImage, tolerance: u8) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions());
    let n = (a.pixels().zip(b.pixels()))
        .filter(|(p, q)| (0..3).any(|c| p.0[c].abs_diff(q.0[c]) > tolerance))
        .count();
    n as f64 / a.pixels().len() as f64
}

/// Pixels of egui's panel background (dark theme) in columns `x0..x1`.
pub fn panel_pixels(img: &image::RgbaImage, x0: u32, x1: u32) -> usize {
    let fill = egui::Visuals::dark().panel_fill;
    (0..img.height())
        .flat_map(|y| (x0..x1).map(move |x| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[..3] == [fill.r(), fill.g(), fill.b()])
        .count()
}

/// The rectangle `[x0, y0, x1, y1]` (window pixels) of the first line of a
/// layout file (src/demo/layout.rs) whose label is `label`.
pub fn layout_rect(layout: &str, label: &str) -> Option<[i64; 4]> {
    let start = format!("{{\"label\":\"{label}\",");
    let line = layout.lines().find(|l| l.starts_with(&start))?;
    let rect = line.split("\"rect\":[").nth(1)?.split(']').next()?;
    let v: Vec<i64> = rect.split(',').filter_map(|n| n.parse().ok()).collect();
    v.try_into().ok()
}

/// Under GLOSS_BLESS=1: `img` written to docs/images/`name`, scaled to
/// `width` pixels wide when it is wider.
pub fn bless(img: &image::RgbaImage, name: &str, width: u32) {
    if std::env::var("GLOSS_BLESS").as_deref() != Ok("1") {
        return;
    }
    let (w, h) = img.dimensions();
    let out = crate_dir().join("docs/images").join(name);
    if w > width {
        let h2 = (u64::from(h) * u64::from(width) / u64::from(w)) as u32;
        image::imageops::resize(img, width, h2, image::imageops::Triangle)
            .save(&out)
            .unwrap();
    } else {
        img.save(&out).unwrap();
    }
}
