//! The 3D view in its own rectangle: with the panel shown, the frame is the
//! scene rendered at the view's size (every object of the default scene
//! visible beside the panel), equal to a headless render at that size.

use crate::{GLOSS, crate_dir, differing, drive, shot};
use std::process::Command;

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
    let reference = dir.join("reference.png");
    let out = Command::new(GLOSS)
        .args(["render", "default", "--size", &format!("{w}x{h}"), "-o"])
        .arg(&reference)
        .current_dir(crate_dir())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let reference = image::open(&reference).unwrap().to_rgba8();
    let d = differing(&view, &reference, 3);
    assert!(
        d < 0.002,
        "{d:.4} of the view differs from the headless render at {w}x{h}"
    );
}
