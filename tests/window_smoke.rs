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
