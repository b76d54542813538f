//! The window backend, end to end: the demo runs 30 frames under Xvfb and exits cleanly.
//!
//! Needs `xvfb-run` (apt-get install xvfb; .ci/run installs it). Where a
//! machine cannot have it, GLOSS_SKIP_WINDOW_TEST=1 skips the Xvfb test.

use std::path::Path;
use std::process::{Command, Output};

const GLOSS: &str = env!("CARGO_BIN_EXE_gloss");

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn xvfb_run_installed() -> bool {
    // Only whether it can be started: a missing program is NotFound.
    Command::new("xvfb-run").arg("--help").output().is_ok()
}

fn describe(out: &Output) -> String {
    format!(
        "status: {}\n--- stdout ---\n{}\n--- stderr ---\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

#[test]
fn demo_runs_30_frames_under_xvfb() {
    if std::env::var("GLOSS_SKIP_WINDOW_TEST").as_deref() == Ok("1") {
        eprintln!("skipped: GLOSS_SKIP_WINDOW_TEST=1");
        return;
    }
    assert!(
        xvfb_run_installed(),
        "xvfb-run is not installed: apt-get install xvfb (CI installs it through .ci/run), \
         or set GLOSS_SKIP_WINDOW_TEST=1 to skip this test"
    );
    // `-a`: take a free display number (other test runs may hold :99).
    // `timeout` bounds a hung demo; xvfb-run then still stops its Xvfb.
    let out = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1280x720x24", "timeout", "120"])
        .arg(GLOSS)
        .args([
            "--backend",
            "window",
            "--frames",
            "30",
            "scenes/default.toml",
        ])
        .current_dir(crate_dir())
        .output()
        .expect("could not start xvfb-run");
    assert!(
        out.status.success(),
        "the demo did not exit 0 under Xvfb\n{}",
        describe(&out)
    );
    let stderr = String::from_utf8_lossy(&out.stderr).to_lowercase();
    assert!(
        !stderr.contains("error") && !stderr.contains("panicked"),
        "the demo reported an error\n{}",
        describe(&out)
    );
}

/// Asking for a window where there is no display is an error that says so, not a panic.
#[test]
fn window_without_display_fails_cleanly() {
    let out = Command::new(GLOSS)
        .args([
            "--backend",
            "window",
            "--frames",
            "1",
            "scenes/default.toml",
        ])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .current_dir(crate_dir())
        .output()
        .expect("could not run gloss");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success(),
        "expected a failure\n{}",
        describe(&out)
    );
    assert!(
        stderr.contains("no display") && !stderr.contains("panicked"),
        "expected a clear 'no display' error\n{}",
        describe(&out)
    );
}

/// A display that is named but cannot be reached (no X server there): the
/// window backend's own reason is printed, then the scene is rendered
/// headless as without a display; never a bare "no display".
#[test]
fn an_unreachable_display_is_reported_in_the_backends_words_then_headless() {
    let dir = std::env::temp_dir().join("gloss-unreachable-display");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out = Command::new(GLOSS)
        .args(["--frames", "1", "plane"])
        .env("DISPLAY", ":9731")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .current_dir(&dir)
        .output()
        .expect("could not run gloss");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(out.status.success(), "{}", describe(&out));
    assert!(
        stderr.contains("cannot open a window: could not connect to the display (")
            && !stderr.contains("no display"),
        "{}",
        describe(&out)
    );
    assert!(stdout.contains("headless"), "{}", describe(&out));
    assert!(dir.join("gloss-plane.png").exists(), "{}", describe(&out));
}

/// The demo driven as a student would, with synthetic X input (xdotool):
/// switch to light volumes (3), turn on the stencil test (V), open the pass
/// inspector on the first view (I: the G-buffer's normals), take a
/// screenshot (F12) and one with the panel (Shift+F12), quit (Esc). The
/// screenshots are checked: the floor's normal (0, 1, 0) shows as
/// (128, 255, 128) in the view (F12), and the panel's rectangle holds text
/// in the whole window (Shift+F12).
#[test]
fn demo_driven_by_keys_switches_inspects_and_screenshots() {
    // Each key is pressed, then the script waits for the frame that shows it.
    let script = format!(
        r#"
        "{GLOSS}" --backend window --debug --frames 200000 --window 1280x720 mixed-lights > gloss.log 2>&1 &
        pid=$!
        wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
        xdotool windowfocus --sync "$wid"
        sleep 3
        for k in 3 v i F12 shift+F12; do xdotool key --clearmodifiers "$k"; sleep 2; done
        xdotool key Escape
        wait $pid
        "#
    );
    let Some((dir, log)) = drive("gloss-demo-keys", "1280x720x24", &script) else {
        return;
    };
    let shot = |n: u32| {
        let p = dir.join(format!("gloss-screenshot-{n}.png"));
        image::open(&p)
            .unwrap_or_else(|e| panic!("{}: {e}\n--- gloss.log ---\n{log}", p.display()))
            .to_rgba8()
    };
    let (normals, with_panel) = (shot(1), shot(2));
    // F12: the 3D view beside the panel, the window's height.
    let (w, h) = normals.dimensions();
    assert!(h == 720 && w < 1280 - 200, "{w}x{h}");
    assert_eq!(with_panel.dimensions(), (1280, 720));
    // The floor fills the bottom middle of mixed-lights' view.
    let floor = normals.get_pixel(w / 2, 690).0;
    for (c, want) in floor[..3].iter().zip([128u8, 255, 128]) {
        assert!(
            c.abs_diff(want) <= 3,
            "inspector's normal view at the floor: {floor:?}, expected about (128, 255, 128)"
        );
    }
    // The panel (left, about 340 px wide) is dark with light text; the
    // frame without it has none of that text.
    let light = |img: &image::RgbaImage| {
        let mut n = 0;
        for y in 100..700 {
            for x in 10..300 {
                let p = img.get_pixel(x, y).0;
                if p[..3].iter().all(|&c| c > 170) {
                    n += 1;
                }
            }
        }
        n
    };
    assert!(
        light(&with_panel) > 500,
        "text pixels in the panel: {}",
        light(&with_panel)
    );
    assert!(
        log.contains("gloss-screenshot-1.png") && log.contains("gloss-screenshot-2.png"),
        "the demo says where its screenshots went:\n{log}"
    );
}

/// The stencil inspector in the window: the mirrors scene, the pass
/// inspector stepped to its third view (I three times: output colour,
/// depth, stencil), a screenshot (F12). Each mirror's own stencil value
/// shows in its own colour.
#[test]
fn demo_shows_the_mirrors_stencil_in_the_inspector() {
    let script = format!(
        r#"
        "{GLOSS}" --backend window --debug --frames 200000 --window 1280x720 mirrors-several > gloss.log 2>&1 &
        pid=$!
        wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
        xdotool windowfocus --sync "$wid"
        sleep 3
        for k in i i i F12; do xdotool key --clearmodifiers "$k"; sleep 2; done
        xdotool key Escape
        wait $pid
        "#
    );
    let Some((dir, log)) = drive("gloss-demo-stencil", "1280x720x24", &script) else {
        return;
    };
    let p = dir.join("gloss-screenshot-1.png");
    let shot = image::open(&p)
        .unwrap_or_else(|e| panic!("{}: {e}\n--- gloss.log ---\n{log}", p.display()))
        .to_rgba8();
    // mirror_depth 1: the left mirror holds 1, the right one 1 + 2 = 3.
    for v in [1u8, 3] {
        let c = gloss::renderer::stencil_color(v);
        let n = shot.pixels().filter(|p| p.0 == c).count();
        assert!(
            n > 5_000,
            "stencil value {v}: {n} pixels of its colour in {}",
            p.display()
        );
    }
}

/// The shadow-map inspector in the window: shadows-point, the pass
/// inspector on its first view (I: the point light's cube map, listed
/// first as its pass runs first), a screenshot (F12). The six faces lie in
/// the cross (+y above; -x +z +x -z; -y below), each in grey with its
/// depth varying over it, and the rest is the view's background.
#[test]
fn demo_shows_a_point_lights_shadow_cube_unfolded() {
    use gloss::demo::shadow_views::{BACKGROUND, layout_rect};
    let script = format!(
        r#"
        "{GLOSS}" --backend window --debug --frames 200000 --window 1280x720 shadows-point > gloss.log 2>&1 &
        pid=$!
        wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
        xdotool windowfocus --sync "$wid"
        sleep 3
        for k in i F12; do xdotool key --clearmodifiers "$k"; sleep 2; done
        xdotool key Escape
        wait $pid
        "#
    );
    let Some((dir, log)) = drive("gloss-demo-shadow-map", "1280x720x24", &script) else {
        return;
    };
    let p = dir.join("gloss-screenshot-1.png");
    let shot = image::open(&p)
        .unwrap_or_else(|e| panic!("{}: {e}\n--- gloss.log ---\n{log}", p.display()))
        .to_rgba8();
    let (w, h) = shot.dimensions();
    let [x0, y0, lw, _] = layout_rect(true, w as i32, h as i32);
    let face = (lw / 4) as u32;
    // A cell of the cross (column, row from the top) and its pixels.
    let cell = |c: u32, r: u32| {
        let (x, y) = (x0 as u32 + c * face, (h - y0 as u32 - 3 * face) + r * face);
        (y + 2..y + face - 2)
            .flat_map(move |y| (x + 2..x + face - 2).map(move |x| (x, y)))
            .map(|(x, y)| shot.get_pixel(x, y).0)
    };
    for (c, r) in [(0, 0), (2, 0), (3, 0), (0, 2), (2, 2), (3, 2)] {
        assert!(
            cell(c, r).all(|p| p[..3] == BACKGROUND),
            "cell ({c}, {r}) of {} is outside the cross",
            p.display()
        );
    }
    for (c, r) in [(1, 0), (0, 1), (1, 1), (2, 1), (3, 1), (1, 2)] {
        let greys: Vec<u8> = cell(c, r).map(|p| p[0]).collect();
        assert!(
            cell(c, r).all(|p| p[0] == p[1] && p[1] == p[2]),
            "face ({c}, {r}) of {} is grey",
            p.display()
        );
        let spread = greys.iter().max().unwrap() - greys.iter().min().unwrap();
        assert!(
            spread >= 16,
            "face ({c}, {r}): depth varies over it ({spread} levels)"
        );
    }
}

/// The post chain's last inner image in the window's inspector:
/// post-effects (tone map, sharpen, gamma 2.2), a screenshot of the frame
/// (F12), the inspector stepped to `post_ping_pong.pong` ("after step 2 of
/// 3, kernel", shown as sRGB at exposure 1), a second screenshot. The
/// output is that texture with gamma 2.2, so the output decoded by 2.2 and
/// sRGB-encoded is the inspector's picture, to one 8-bit step.
#[test]
fn demo_shows_the_post_chains_ping_pong_texture() {
    use gloss::frame::lights::FrameLights;
    use gloss::frame::plan::FramePlan;
    let scene = gloss::scene::Scene::load(&crate_dir().join("scenes/post-effects.toml")).unwrap();
    let plan = FramePlan::new(&scene, &FrameLights::new(&scene), gloss::techniques::ALL);
    let views = gloss::demo::inspector::views(&plan, false, &[]);
    let pong = (views.iter())
        .position(|v| v.target == "post_ping_pong" && v.attachment == "pong")
        .expect("the ping-pong pair's second texture is a view");
    let script = format!(
        r#"
        "{GLOSS}" --backend window --debug --frames 200000 --window 1280x720 post-effects > gloss.log 2>&1 &
        pid=$!
        wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
        xdotool windowfocus --sync "$wid"
        sleep 3
        # A frame may take seconds on a loaded machine: each screenshot is
        # waited for, so that no key reaches the demo before it is taken.
        xdotool key --clearmodifiers F12
        while [ ! -f gloss-screenshot-1.png ]; do sleep 0.2; done
        for i in $(seq {presses}); do xdotool key --clearmodifiers i; sleep 0.3; done
        xdotool key --clearmodifiers F12
        while [ ! -f gloss-screenshot-2.png ]; do sleep 0.2; done
        sleep 1
        xdotool key Escape
        wait $pid
        "#,
        presses = pong + 1
    );
    let Some((dir, log)) = drive("gloss-demo-post-chain", "1280x720x24", &script) else {
        return;
    };
    let shot = |n: u32| {
        let p = dir.join(format!("gloss-screenshot-{n}.png"));
        image::open(&p)
            .unwrap_or_else(|e| panic!("{}: {e}\n--- gloss.log ---\n{log}", p.display()))
            .to_rgba8()
    };
    let (output, inspected) = (shot(1), shot(2));
    assert_eq!(output.dimensions(), inspected.dimensions());
    let (mut far, mut lit) = (0, 0);
    for (o, s) in output.pixels().zip(inspected.pixels()) {
        for c in 0..3 {
            let linear = (f32::from(o.0[c]) / 255.0).powf(2.2);
            let want = gloss::lighting::srgb_encode(linear) * 255.0;
            far += usize::from((f32::from(s.0[c]) - want).abs() > 1.0);
            lit += usize::from(s.0[c] > 20);
        }
    }
    let n = 3 * output.pixels().len();
    // The ping texture, before the sharpen, is about 1% off.
    assert!(far * 1000 < n, "{far} of {n} channels more than 1 step off");
    assert!(
        lit * 4 > n,
        "the inspected texture is mostly dark: {lit} of {n}"
    );
}

/// The window resized by the X server: very large (3840 x 2160), 1 x 1,
/// unmapped and mapped again, and back to 1280 x 720, with GL debug output
/// on: no GL error, no panic, and the last screenshot (the view, the whole
/// window with the panel hidden) has the last size.
#[test]
fn demo_survives_huge_tiny_and_hidden_windows() {
    // --frames only bounds a demo that Esc failed to stop: at 1 x 1 a frame
    // takes well under a millisecond, so a small cap would end the demo
    // before the keys arrive.
    let script = format!(
        r#"
        "{GLOSS}" --backend window --debug --frames 200000 --no-panel plane > gloss.log 2>&1 &
        pid=$!
        wid=$(xdotool search --sync --onlyvisible --name "gloss" | head -n 1)
        xdotool windowfocus --sync "$wid"
        sleep 2
        for s in "3840 2160" "1 1" "1280 720"; do xdotool windowsize "$wid" $s; sleep 3; done
        xdotool windowunmap "$wid"; sleep 2; xdotool windowmap "$wid"; sleep 2
        xdotool windowfocus --sync "$wid"
        xdotool key F12; sleep 2
        xdotool key Escape
        wait $pid
        "#
    );
    let Some((dir, log)) = drive("gloss-demo-sizes", "3840x2160x24", &script) else {
        return;
    };
    let shot = image::open(dir.join("gloss-screenshot-1.png"))
        .unwrap_or_else(|e| panic!("screenshot: {e}\n--- gloss.log ---\n{log}"));
    assert_eq!((shot.width(), shot.height()), (1280, 720), "{log}");
}

/// Run `script` under Xvfb (a `screen` such as "1280x720x24") in a fresh
/// directory `name` under the temp dir, where the script starts gloss with
/// its output in gloss.log and drives it with xdotool. Asserts that it exits
/// 0 and that gloss reported no error; returns the directory and the log.
/// None when GLOSS_SKIP_WINDOW_TEST=1.
fn drive(name: &str, screen: &str, body: &str) -> Option<(std::path::PathBuf, String)> {
    if std::env::var("GLOSS_SKIP_WINDOW_TEST").as_deref() == Ok("1") {
        eprintln!("skipped: GLOSS_SKIP_WINDOW_TEST=1");
        return None;
    }
    assert!(
        xvfb_run_installed() && Command::new("xdotool").arg("version").output().is_ok(),
        "xvfb-run and xdotool are needed (.ci/run installs them), \
         or set GLOSS_SKIP_WINDOW_TEST=1 to skip this test"
    );
    let dir = std::env::temp_dir().join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out = Command::new("xvfb-run")
        .args([
            "-a",
            "-s",
            &format!("-screen 0 {screen}"),
            "timeout",
            "300",
            "bash",
            "-c",
        ])
        .arg(body)
        .current_dir(&dir)
        .output()
        .expect("could not start xvfb-run");
    let log = std::fs::read_to_string(dir.join("gloss.log")).unwrap_or_default();
    assert!(
        out.status.success(),
        "the driven demo failed\n{}\n--- gloss.log ---\n{log}",
        describe(&out)
    );
    assert!(
        !log.to_lowercase().contains("error") && !log.contains("panicked"),
        "the demo reported an error:\n{log}"
    );
    Some((dir, log))
}
