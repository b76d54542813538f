//! The 3D view in its own rectangle: with the panel shown, the frame is the
//! scene rendered at the view's size (every object of the default scene
//! visible beside the panel), equal to a headless render at that size.

use crate::{differing, drive, headless_render, shot};

#[test]
fn the_view_beside_the_panel_is_the_scene_at_the_views_size() {
    let script = r#"
        start --window 1280x720 default
        key F12; shot 1
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-view", "1280x720x24", script) else {
        return;
    };
    let view = shot(&dir, &log, 1);
    let (w, h) = view.dimensions();
    assert!(
        w < 1280 - 200 && h == 720,
        "{w}x{h}: the view is beside the panel"
    );
    let reference = headless_render(&dir, "default", &[], (w, h));
    let d = differing(&view, &reference, 3);
    assert!(
        d < 0.002,
        "{d:.4} of the view differs from the headless render at {w}x{h}"
    );
}

/// F2 twice: the view rendered at 1/4 of its pixels each way, shown scaled
/// up: every 4 x 4 block of the view (from its bottom left, where GL
/// starts) is one colour, and the picture is the 1/4 frame's: the headless
/// render at that size, each pixel a block.
#[test]
fn render_scale_a_quarter_shows_each_rendered_pixel_as_a_block() {
    let script = r#"
        start --window 1280x720 default
        # A pause after each key: on a loaded machine a frame can take a second.
        key F2; sleep 2; key F2; sleep 4; key F12; shot 1
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-scale", "1280x720x24", script) else {
        return;
    };
    let view = shot(&dir, &log, 1);
    let (w, h) = view.dimensions();
    assert_eq!(h, 720);
    let (qw, qh) = (w.div_ceil(4), h.div_ceil(4));
    let quarter = headless_render(&dir, "default", &[], (qw, qh));
    // The view's pixel (x, y from the top) is the quarter frame's pixel
    // (x / 4, counted from the bottom in GL: the rows line up from there).
    let mut off = 0;
    for y in 0..h {
        for x in 0..w {
            let from_bottom = h - 1 - y;
            let q = quarter.get_pixel(x / 4, qh - 1 - from_bottom / 4).0;
            let p = view.get_pixel(x, y).0;
            off += usize::from((0..3).any(|c| p[c].abs_diff(q[c]) > 3));
        }
    }
    let share = off as f64 / f64::from(w * h);
    assert!(
        share < 0.002,
        "{share:.4} of the view is not its quarter frame's block"
    );
}
