//! The screenshots of docs/demo.md, each made here (written to
//! docs/images/ under GLOSS_BLESS=1) and, blessing or not, checked for what
//! the page says it shows: the panel beside the 3D view, the view filling
//! the window with the panel hidden, and the inspector's views equal to
//! `gloss render --target` at the view's size (the floor's normal checked
//! against (0, 1, 0), and the depth view against the floor's depth worked
//! out on the CPU).

use crate::{bless, differing, drive, headless_render, layout_rect, panel_pixels, shot};
use std::path::Path;

/// `inspect WORDS`: press I until the inspector shows the view whose
/// label holds WORDS (the drop-down's text in the layout).
const INSPECT: &str = r#"
inspect() {
    for _ in $(seq 40); do
        widget_line "inspector view" | grep -qF "$1" && return 0
        p=$(layout_pass); key i; next_pass "$p"; next_pass "$((p + 1))"
    done
    echo "no inspector view '$1'" >&2; return 1
}
"#;

fn layout(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap_or_default()
}

/// docs/images/demo-panel.png and demo-hidden.png: mixed-lights on the
/// light-volume path with the panel, then hidden (Tab) at render scale 1/2.
#[test]
fn the_panel_beside_the_view_and_the_view_alone() {
    let script = r#"
        start --window 1280x720 --set render.path=volumes mixed-lights
        sleep 1
        key shift+F12; shot 1
        key F12; shot 2
        cp layout.jsonl shown.jsonl
        p=$(layout_pass); key Tab; next_pass "$p"
        key F2
        sleep 1
        key shift+F12; shot 3
        key F12; shot 4
        cp layout.jsonl hidden.jsonl
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-pictures", "1280x720x24", script) else {
        return;
    };
    let (window, view) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    let shown = layout(&dir, "shown.jsonl");
    let panel = layout_rect(&shown, "panel").expect("the panel in the layout");
    let r = layout_rect(&shown, "3D view").expect("the view in the layout");
    // The panel at its opening width on the left, the view beside it,
    // the window's height.
    assert!(
        panel[0] == 0 && (300..=380).contains(&panel[2]),
        "panel {panel:?}"
    );
    assert!(
        (r[0] - panel[2]).abs() <= 4 && r[1] == 0 && r[2] == 1280 && r[3] == 720,
        "the view {r:?} beside the panel {panel:?}"
    );
    assert_eq!(
        (i64::from(view.width()), i64::from(view.height())),
        (r[2] - r[0], r[3] - r[1]),
        "F12 saves the view's rectangle"
    );
    // The window's pixels right of the panel are the view's (the panel's
    // few pixels of resize handle aside), and its left columns the panel's.
    let right = image::imageops::crop_imm(&window, r[0] as u32 + 4, 0, view.width() - 4, 720);
    let view_right = image::imageops::crop_imm(&view, 4, 0, view.width() - 4, 720);
    let d = differing(&right.to_image(), &view_right.to_image(), 2);
    assert!(
        d < 0.001,
        "{d:.4} of the window beside the panel is not the view"
    );
    let fill = panel_pixels(&window, 0, panel[2] as u32);
    assert!(
        fill > (panel[2] * 720 / 3) as usize,
        "only {fill} pixels of the panel's background"
    );
    bless(&window, "demo-panel.png", 960);

    let (window, view) = (shot(&dir, &log, 3), shot(&dir, &log, 4));
    let hidden = layout(&dir, "hidden.jsonl");
    assert_eq!(layout_rect(&hidden, "panel"), None, "the panel is hidden");
    assert_eq!(
        layout_rect(&hidden, "3D view"),
        Some([0, 0, 1280, 720]),
        "hidden, the view fills the window"
    );
    assert_eq!(view.dimensions(), (1280, 720));
    let fill = panel_pixels(&window, 0, 300);
    assert!(
        fill < 300 * 720 / 50,
        "{fill} panel pixels with the panel hidden"
    );
    // The note in the corner names the scale and the way back.
    assert!(
        hidden
            .lines()
            .any(|l| l.contains("render scale 1/2") && l.contains("Tab: panel")),
        "no note with the render scale and Tab:\n{hidden}"
    );
    bless(&window, "demo-hidden.png", 960);
}

/// docs/images/demo-normals.png, demo-albedo.png, demo-depth.png,
/// demo-light.png: mixed-lights on the deferred path, each G-buffer view
/// chosen with I; normals, albedo and light equal to `gloss render
/// --target` of that attachment at the view's size; the floor's normal is
/// (0, 1, 0), and the depth view the floor's depth from the camera.
#[test]
fn the_inspectors_views_are_the_targets() {
    let script = format!(
        "{INSPECT}{}",
        r#"
        start --window 1280x720 --set render.path=deferred mixed-lights
        inspect "gbuffer.normal_shininess"; key F12; shot 1
        inspect "gbuffer.albedo"; key F12; shot 2
        inspect "gbuffer.depth"; key F12; shot 3
        inspect "light_accumulation.light"; key F12; shot 4
        quit
    "#
    );
    let Some((dir, log)) = drive("gloss-window-inspector-pictures", "1280x720x24", &script) else {
        return;
    };
    let views = [
        (1, "gbuffer.normal_shininess", "demo-normals.png"),
        (2, "gbuffer.albedo", "demo-albedo.png"),
        (4, "light_accumulation.light", "demo-light.png"),
    ];
    for (n, target, picture) in views {
        let view = shot(&dir, &log, n);
        let args = ["--path", "deferred", "--target", target];
        let reference = headless_render(&dir, "mixed-lights", &args, view.dimensions());
        let d = differing(&view, &reference, 3);
        assert!(
            d < 0.005,
            "{target}: {d:.4} of the view differs from gloss render --target"
        );
        bless(&view, picture, 640);
    }
    // The floor (the bottom middle of the view) faces up: n x 0.5 + 0.5.
    let normals = shot(&dir, &log, 1);
    let (w, h) = normals.dimensions();
    let p = normals.get_pixel(w / 2, h - 10).0;
    assert!(
        p[0].abs_diff(128) <= 2 && p[1] >= 253 && p[2].abs_diff(128) <= 2,
        "the floor's normal shows as {p:?}, not (128, 255, 128)"
    );
    // The depth view there: the distance along the view direction to the
    // point where the pixel's ray meets the floor (y = 0), from the scene's
    // camera (eye (0, 7, 9) looking at the origin, 50 degrees, near 0.2,
    // far 50), mapped from near..far to 0..1.
    let depth = shot(&dir, &log, 3);
    bless(&depth, "demo-depth.png", 640);
    for (x, y) in [(w / 2, h - 10), (w / 4, h / 2 + 80), (w * 3 / 4, h * 3 / 4)] {
        let want = floor_depth(x, y, (w, h));
        let got = f64::from(depth.get_pixel(x, y).0[0]) / 255.0;
        assert!(
            (got - want).abs() <= 2.5 / 255.0,
            "depth view at ({x}, {y}): {got:.4}, the floor's linearised depth {want:.4}"
        );
    }
}

/// mixed-lights' floor's depth at pixel (x, y) of a view `size` large,
/// linearised over near..far as docs/demo.md says.
fn floor_depth(x: u32, y: u32, (w, h): (u32, u32)) -> f64 {
    use glam::DVec3;
    let (eye, near, far) = (DVec3::new(0.0, 7.0, 9.0), 0.2, 50.0);
    let f = (-eye).normalize();
    let right = f.cross(DVec3::Y).normalize();
    let up = right.cross(f);
    let t = (50.0_f64.to_radians() / 2.0).tan();
    let nx = 2.0 * (f64::from(x) + 0.5) / f64::from(w) - 1.0;
    let ny = 1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(h);
    let ray = f + up * (ny * t) + right * (nx * t * f64::from(w) / f64::from(h));
    let point = eye + ray * (-eye.y / ray.y);
    ((point - eye).dot(f) - near) / (far - near)
}

/// docs/images/demo-overdraw.png: many-lights on the light-volume path,
/// the overdraw view (how many volumes cover each pixel, as a heat map).
/// tests/demo/volumes.rs checks the counts against the CPU; here the
/// window shows the view, with the hottest colour (red: the number of
/// volumes or more) where the grid's volumes pile up and black where none
/// reaches.
#[test]
fn the_overdraw_view_in_the_window() {
    let script = format!(
        "{INSPECT}{}",
        r#"
        start --window 1280x720 --set render.path=volumes many-lights
        inspect "how many cover each pixel"; key F12; shot 1
        quit
    "#
    );
    let Some((dir, log)) = drive("gloss-window-overdraw-picture", "1280x720x24", &script) else {
        return;
    };
    let view = shot(&dir, &log, 1);
    let share = |f: &dyn Fn(&[u8]) -> bool| {
        view.pixels().filter(|p| f(&p.0)).count() as f64 / view.pixels().len() as f64
    };
    let red = share(&|p| p[0] >= 250 && p[1] <= 5 && p[2] <= 5);
    let black = share(&|p| p[0] <= 3 && p[1] <= 3 && p[2] <= 3);
    assert!(red > 0.05 && black > 0.01, "red {red:.3}, black {black:.3}");
    bless(&view, "demo-overdraw.png", 640);
}
