//! The demo switches of the techniques beyond the notes, clicked as a
//! student clicks them, each widget found by its label in the panel's
//! layout (`click_widget`, tests/window_demo/main.rs), and each checked on
//! the 3D view's screenshots (F12) for the change it should make: cascade
//! colours (docs/shadows/cascaded_shadow_maps.md), image-based lighting (docs/sky/image_based_lighting.md), parallax mapping
//! (docs/lighting/parallax_mapping.md), order-independent transparency
//! (docs/blending/order_independent_transparency.md) and exploding objects
//! (docs/vertex_geometry/exploding_objects.md). Outlines, instancing and the
//! normals are in switches.rs.

use crate::{differing, drive, shot};

/// Mean (R, G, B) of the rows `y0..y1` of an image, columns in the middle half.
fn mean(img: &image::RgbaImage, y0: u32, y1: u32) -> [f64; 3] {
    let (x0, x1) = (img.width() / 4, 3 * img.width() / 4);
    let mut sum = [0.0; 3];
    for y in y0..y1 {
        for x in x0..x1 {
            let p = img.get_pixel(x, y);
            for c in 0..3 {
                sum[c] += f64::from(p[c]);
            }
        }
    }
    let n = f64::from((y1 - y0) * (x1 - x0));
    sum.map(|s| s / n)
}

#[test]
fn the_cascade_colours_checkbox_tints_near_red_and_further_green() {
    let script = r#"
        start --window 1280x1000 cascaded-shadows
        sleep 2
        key F12; shot 1
        sleep 2
        click_widget "Lights (1)"
        sleep 1
        click_widget "light 0: directional"
        sleep 1
        click_widget "cascade colours"
        sleep 1
        key F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-cascade-colours", "1280x1024x24", script) else {
        return;
    };
    let (plain, tinted) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    let h = plain.height();
    // The bottom rows: the field at the camera's feet, in the first
    // cascade (red, (1, 0.45, 0.45) in linear light).
    let (a, b) = (mean(&plain, h * 9 / 10, h), mean(&tinted, h * 9 / 10, h));
    eprintln!("bottom rows' mean RGB: plain {a:?}, tinted {b:?}");
    assert!(
        b[1] / b[0] < 0.8 * (a[1] / a[0]),
        "the near field did not turn red: G/R {} -> {}",
        a[1] / a[0],
        b[1] / b[0]
    );
    // Higher up the field, further away: the second cascade, green
    // (0.45, 1, 0.45): in some band of rows between half and nine tenths
    // of the height, red falls against green.
    let drop = |k: u32| {
        let rows = (h * k / 20, h * (k + 1) / 20);
        let (c, d) = (mean(&plain, rows.0, rows.1), mean(&tinted, rows.0, rows.1));
        (d[0] / d[1]) / (c[0] / c[1])
    };
    let drops: Vec<f64> = (10..18).map(drop).collect();
    eprintln!("R/G tinted over plain, bands of rows from half the height down: {drops:.3?}");
    assert!(
        drops.iter().any(|&r| r < 0.8),
        "no band of the field further away turned green: {drops:.3?}"
    );
}

#[test]
fn the_image_based_lighting_checkbox_darkens_the_metal_spheres() {
    // Off takes the technique out of the frame, and its checkbox with it.
    let script = r#"
        start --window 1280x1000 ibl
        sleep 2
        key F12; shot 1
        sleep 2
        click_widget "image-based lighting"
        sleep 1
        key F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-ibl", "1280x1024x24", script) else {
        return;
    };
    let (on, off) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    let changed = differing(&on, &off, 3);
    // The metal spheres mirror the environment with IBL; with the constant
    // ambient term they keep only their highlights: the image darkens.
    let h = on.height();
    let (a, b) = (mean(&on, 0, h), mean(&off, 0, h));
    let (la, lb) = (a.iter().sum::<f64>() / 3.0, b.iter().sum::<f64>() / 3.0);
    eprintln!("IBL off changes {changed:.3} of the view; mean level {la:.1} -> {lb:.1}");
    assert!(
        changed > 0.02,
        "switching IBL off changed only {changed:.4} of the view"
    );
    assert!(
        lb < 0.9 * la,
        "switching IBL off did not darken the view: {la:.1} -> {lb:.1}"
    );
}

#[test]
fn the_parallax_choice_off_flattens_the_relief() {
    // Off takes parallax mapping out of the frame, and its knobs with it
    // (the panel lists its technique among those not in the frame).
    let script = r#"
        start --window 1280x1000 parallax
        sleep 2
        key F12; shot 1
        sleep 2
        click_widget "off" "parallax"
        sleep 1
        key F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-parallax", "1280x1024x24", script) else {
        return;
    };
    let (occlusion, off) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    // Off draws the flat, normal-mapped plane: the relief's steps and
    // self-shadows go, over much of the view.
    let b = differing(&occlusion, &off, 3);
    eprintln!("occlusion -> off changes {b:.4} of the view");
    assert!(b > 0.02, "parallax off changed only {b:.4} of the view");
}

#[test]
fn the_transparency_choice_sorted_orders_the_crossed_panes_wrong() {
    let script = r#"
        start --window 1280x1000 oit
        sleep 2
        key F12; shot 1
        sleep 2
        click_widget "sorted" "transparency"
        sleep 1
        key F12; shot 2
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-oit", "1280x1024x24", script) else {
        return;
    };
    let (weighted, sorted) = (shot(&dir, &log, 1), shot(&dir, &log, 2));
    // Weighted blended needs no order; sorting per object cannot order the
    // crossed panes: the glass changes where they overlap.
    let changed = differing(&weighted, &sorted, 3);
    eprintln!("weighted blended -> sorted changes {changed:.4} of the view");
    assert!(
        changed > 0.005,
        "sorted looks like weighted blended: {changed:.4}"
    );
}

#[test]
fn the_explode_checkbox_stops_the_pieces_and_shows_the_objects_whole() {
    let script = r#"
        start --window 1280x1000 explode
        sleep 2
        key F12; shot 1
        sleep 1
        key F12; shot 2
        sleep 2
        click_widget "explode"
        sleep 1
        key F12; shot 3
        sleep 1
        key F12; shot 4
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-explode", "1280x1024x24", script) else {
        return;
    };
    let (a, b, whole, still) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
        shot(&dir, &log, 4),
    );
    // Exploding, the pieces fly with the scene's time: two shots a second
    // apart differ. Whole, nothing moves.
    let moving = differing(&a, &b, 3);
    let (changed, held) = (differing(&b, &whole, 3), differing(&whole, &still, 1));
    eprintln!(
        "exploding frame to frame {moving:.4}; explode off {changed:.4}; whole frame to frame {held:.5}"
    );
    assert!(moving > 0.0, "the exploding pieces did not move");
    assert!(
        changed > 0.01,
        "switching explode off changed only {changed:.4}"
    );
    assert_eq!(held, 0.0, "the whole objects moved from frame to frame");
}
