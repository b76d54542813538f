//! The inspector's thumbnail strip scrolls: with more thumbnails than the
//! panel is wide, turning the wheel sideways over the strip brings the
//! others in (src/demo/panel/inspector.rs, a horizontal egui::ScrollArea).

use crate::{drive, shot};

/// Pixels that differ (any channel by more than 8) between `a` and `b` in
/// the rows `y0..y1` and columns `x0..x1`, and how many there are.
fn changed_in(a: &image::RgbaImage, b: &image::RgbaImage, rect: [u32; 4]) -> (usize, usize) {
    let [x0, y0, x1, y1] = rect;
    let mut n = 0;
    for y in y0..y1 {
        for x in x0..x1 {
            let (p, q) = (a.get_pixel(x, y).0, b.get_pixel(x, y).0);
            if p.iter().zip(q).take(3).any(|(&u, v)| u.abs_diff(v) > 8) {
                n += 1;
            }
        }
    }
    (n, ((x1 - x0) * (y1 - y0)) as usize)
}

#[test]
fn the_thumbnail_strip_scrolls_sideways() {
    let script = r#"
        start --window 1280x1000 deferred-shading
        scroll_to "exposure (light views)" Slider > /dev/null
        toggled "thumbnails (click one to view it)" > ticked
        sleep 1
        widget "thumbnails (click one to view it)" > box
        widget "panel" > panel
        key shift+F12; shot 1
        read -r bx0 by0 bx1 by1 < box
        xdotool mousemove 150 $((by1 + 35))
        sleep 1
        for i in 1 2 3 4 5 6 7 8 9 10; do xdotool click 7; sleep 0.2; done
        sleep 3
        key shift+F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-strip", "1280x1024x24", script) else {
        return;
    };
    let read = |name: &str| -> Vec<u32> {
        std::fs::read_to_string(dir.join(name))
            .unwrap_or_default()
            .split_whitespace()
            .filter_map(|v| v.parse::<f32>().ok().map(|v| v.max(0.0) as u32))
            .collect()
    };
    assert_eq!(
        std::fs::read_to_string(dir.join("ticked"))
            .unwrap_or_default()
            .trim(),
        "true",
        "the thumbnails are on when the demo starts"
    );
    let (cb, panel) = (read("box"), read("panel"));
    assert!(
        cb.len() == 4 && panel.len() == 4,
        "rectangles: {cb:?} {panel:?}"
    );
    let (before, after) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    // The strip: the 54-pixel-high thumbnails under the checkbox, across
    // the panel (its right edge less the scroll bar).
    let strip = [panel[0], cb[3] + 4, panel[2].saturating_sub(12), cb[3] + 60];
    let (n, area) = changed_in(&before, &after, strip);
    assert!(
        n * 4 > area,
        "the strip {strip:?} did not scroll: {n} of {area} pixels changed"
    );
    // Nothing else moved: the view beside the panel is as it was.
    let view = [panel[2] + 2, 0, before.width(), before.height()];
    let (m, view_area) = changed_in(&before, &after, view);
    assert!(
        m * 1000 < view_area,
        "the wheel over the strip changed the 3D view: {m} of {view_area} pixels"
    );
}
