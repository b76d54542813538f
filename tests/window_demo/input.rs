//! Input that always reaches the demo: Tab hides and shows the panel and a
//! key after it still works; a press that starts on a widget belongs to
//! egui, however soon after the pointer arrived, and never turns the camera;
//! "play" plays.

use crate::{differing, drive, panel_pixels, shot};

/// Shift+F12 with the panel, Tab, Shift+F12, Tab, Shift+F12, then F12 (a
/// key after Tab): the panel's background fills the left columns in the
/// first and third, none of them in the second, and F12 still writes the
/// view. Then a text field is focused (clicked) and Tab goes to egui, not
/// to the demo: the panel stays.
#[test]
fn tab_hides_and_shows_the_panel_and_keys_work_after_it() {
    let script = r#"
        start --window 1280x720 default
        key shift+F12; shot 1
        key Tab; key shift+F12; shot 2
        key Tab; key shift+F12; shot 3
        key F12; shot 4
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-tab", "1280x720x24", script) else {
        return;
    };
    let (shown, hidden, again, view) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
        shot(&dir, &log, 4),
    );
    let strip = |img| panel_pixels(img, 0, 300);
    // Most of the strip is the panel's fill (the rest its text and widgets).
    assert!(
        strip(&shown) > 300 * 720 / 3,
        "panel shown: {}",
        strip(&shown)
    );
    assert!(
        strip(&hidden) < 300 * 720 / 50,
        "panel hidden: {}",
        strip(&hidden)
    );
    assert!(
        strip(&again) > 300 * 720 / 3,
        "panel back: {}",
        strip(&again)
    );
    // F12 after the Tabs: the view beside the panel, the window's height.
    assert_eq!(view.height(), 720);
    assert!(
        (800..1000).contains(&view.width()),
        "the view beside a panel of about 340 px: {}",
        view.width()
    );
    let _ = differing;
}

/// A press on a panel widget, the pointer moved there in the same instant,
/// dragged into the view and released: the camera has not moved (the view
/// is the same). The same drag starting in the view does turn it.
#[test]
fn a_drag_that_starts_on_a_widget_does_not_move_the_camera() {
    let script = r#"
        start --window 1280x720 default
        key F12; shot 1
        # The "Scene" section's header, a widget, pressed as the pointer
        # arrives, dragged over the view and released there.
        read -r x0 y0 x1 y1 <<< "$(widget Scene)"
        xdotool mousemove $(( (x0 + x1) / 2 )) $(( (y0 + y1) / 2 )) \
            mousedown 1 mousemove 400 300 mousemove 700 400 mouseup 1
        key F12; shot 2
        xdotool mousemove 700 300 mousedown 1 mousemove 800 320 mousemove 900 340 mouseup 1
        key F12; shot 3
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-drag", "1280x720x24", script) else {
        return;
    };
    let (before, widget, view) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
    );
    assert!(
        differing(&before, &widget, 2) < 0.001,
        "a drag from a widget moved the camera: {:.3} of the view changed",
        differing(&before, &widget, 2)
    );
    assert!(
        differing(&before, &view, 2) > 0.05,
        "a drag in the view turns the camera: {:.3} of the view changed",
        differing(&before, &view, 2)
    );
}

/// A scene with keyframes starts playing and keeps playing: two drawn
/// frames (after the first ones, when a spurious pause would have come:
/// the time slider's rounding once paused it) differ where the animated
/// objects move.
#[test]
fn play_plays() {
    let script = r#"
        start --window 1280x720 animated-hierarchy
        key F12; shot 1
        key F12; shot 2
        # Time to pass: the frames drawn meanwhile advance the animation.
        sleep 2
        key F12; shot 3
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-play", "1280x720x24", script) else {
        return;
    };
    let (a, b) = (shot(&dir, &log, 2), shot(&dir, &log, 3));
    assert!(
        differing(&a, &b, 4) > 0.002,
        "the animation stood still between two frames: {:.4} changed",
        differing(&a, &b, 4)
    );
}
