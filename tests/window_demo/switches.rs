//! The panel's switches of object outlines, instancing and the normals, clicked as a
//! student clicks them (docs/stencil/object_outlines.md,
//! docs/vertex_geometry/instancing.md). Each checkbox is found by its label
//! in the panel's layout (`click_widget`, tests/window_demo/main.rs): under
//! the forward pass's knobs while its technique runs, and, once switched
//! off, below the list of techniques not in the frame.

use crate::{differing, drive, shot};

/// Pixels of the outline's colour (render of [1.0, 0.55, 0.05], sRGB).
fn outline_pixels(img: &image::RgbaImage) -> usize {
    img.pixels()
        .filter(|p| p[0] >= 250 && (185..=200).contains(&p[1]) && p[2] >= 55 && p[2] <= 75)
        .count()
}

/// The lines of `name` in a driven demo's directory.
fn lines(dir: &std::path::Path, name: &str) -> Vec<String> {
    std::fs::read_to_string(dir.join(name))
        .unwrap_or_default()
        .lines()
        .map(str::to_string)
        .collect()
}

#[test]
fn the_outlines_checkbox_switches_outlines_off_and_on() {
    let script = r#"
        start --window 1280x1000 outlines
        sleep 2
        toggled "object outlines" >> states
        key F12; shot 1
        click_widget "object outlines"
        toggled "object outlines" >> states
        sleep 1
        key F12; shot 2
        click_widget "object outlines"
        toggled "object outlines" >> states
        sleep 1
        key F12; shot 3
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-outlines", "1280x1024x24", script) else {
        return;
    };
    assert_eq!(
        lines(&dir, "states"),
        ["true", "false", "true"],
        "the checkbox's state in the panel: on, off, on"
    );
    let (on, off, again) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
    );
    let n = outline_pixels(&on);
    assert!(n > 2000, "only {n} outline pixels with outlines on");
    assert_eq!(
        outline_pixels(&off),
        0,
        "the checkbox did not switch the outlines off"
    );
    // Off changes the outline's band only.
    let changed = differing(&on, &off, 3) * f64::from(on.width() * on.height());
    assert!(
        changed < 1.3 * n as f64,
        "switching outlines off changed {changed} pixels, the outline has {n}"
    );
    assert!(
        differing(&on, &again, 2) < 0.001,
        "switched on again, the view is not what it was: {:.4} differs",
        differing(&on, &again, 2)
    );
}

#[test]
fn the_instancing_checkbox_switches_to_one_draw_per_rock_and_the_same_image() {
    let script = r#"
        sed 's/count = 100000/count = 3000/' "$SCENES/instancing.toml" > rocks.toml
        start --window 1280x1000 rocks.toml
        sleep 2
        key F12; shot 1
        widget "instanced draw" > box
        key shift+F12; shot 2
        click_widget "instanced draw"
        sleep 1
        key F12; shot 3
        key shift+F12; shot 4
        quit
    "#;
    let scenes = crate::crate_dir().join("scenes");
    let script = script.replace("$SCENES", &scenes.display().to_string());
    let Some((dir, log)) = drive("gloss-window-instancing", "1280x1024x24", &script) else {
        return;
    };
    let (instanced, per_rock) = (shot(&dir, &log, 1), shot(&dir, &log, 3));
    // The checkbox (its box, where the layout said it was) lost its tick.
    let r: Vec<u32> = lines(&dir, "box")[0]
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    let (before, after) = (shot(&dir, &log, 2), shot(&dir, &log, 4));
    let ticked = |img: &image::RgbaImage| {
        (r[1]..r[3])
            .flat_map(|y| (r[0]..r[2]).map(move |x| (x, y)))
            .filter(|&(x, y)| img.get_pixel(x, y)[0] > 180)
            .count()
    };
    assert!(
        ticked(&before) > 5 && ticked(&after) < ticked(&before) / 3,
        "the instanced draw checkbox did not switch off: {} light pixels in its box {r:?} before, {} after",
        ticked(&before),
        ticked(&after)
    );
    assert!(
        differing(&instanced, &per_rock, 1) == 0.0,
        "one draw per rock does not give the instanced image: {:.5} differs",
        differing(&instanced, &per_rock, 1)
    );
    let lit = instanced.pixels().filter(|p| p[0] > 60).count();
    assert!(lit > 5000, "only {lit} lit pixels: no field of rocks");
}

#[test]
fn the_show_normals_checkbox_switches_the_lines_off_and_on() {
    let script = r#"
        start --window 1280x1000 normals
        sleep 2
        key F12; shot 1
        click_widget "show normals"
        sleep 1
        key F12; shot 2
        click_widget "show normals"
        sleep 1
        key F12; shot 3
        quit
    "#;
    let Some((dir, log)) = drive("gloss-window-normals", "1280x1024x24", script) else {
        return;
    };
    let yellow = |img: &image::RgbaImage| {
        img.pixels()
            .filter(|p| p[0] >= 250 && p[1] >= 250 && p[2] <= 5)
            .count()
    };
    let (on, off, again) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
    );
    assert!(yellow(&on) > 2000, "only {} line pixels", yellow(&on));
    assert_eq!(
        yellow(&off),
        0,
        "the checkbox did not switch the normals off"
    );
    assert!(
        differing(&on, &again, 2) < 0.001,
        "switched on again, the view is not what it was: {:.4} differs",
        differing(&on, &again, 2)
    );
}
