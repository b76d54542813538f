//! The demo's key L switches the area lights (LTC) off and on again
//! (docs/lighting/ltc_area_lights.md), pressed as a student presses it: on
//! the forward path, and on the deferred path where one full-screen pass
//! reads the G-buffer (docs/deferred/ltc_area_lights_deferred.md).

use crate::{differing, drive, shot};

/// Pixels of the lights' own rectangles: near white (their radiance is
/// above 1 and the panel's light is warm).
fn light_pixels(img: &image::RgbaImage) -> usize {
    img.pixels()
        .filter(|p| p[0] >= 250 && p[1] >= 245 && p[2] >= 240)
        .count()
}

#[test]
fn key_l_switches_the_area_lights_off_and_on() {
    switch_off_and_on("area-lights");
}

#[test]
fn key_l_switches_the_area_lights_off_and_on_on_the_deferred_path() {
    switch_off_and_on("area-lights-deferred");
}

fn switch_off_and_on(scene: &str) {
    let script = r#"
        start --window 960x600 SCENE
        sleep 2
        key F12; shot 1
        key l; sleep 1
        key F12; shot 2
        key l; sleep 1
        key F12; shot 3
        quit
    "#
    .replace("SCENE", scene);
    let Some((dir, log)) = drive(&format!("gloss-window-{scene}"), "1280x1024x24", &script) else {
        return;
    };
    let (on, off, again) = (
        shot(&dir, &log, 1),
        shot(&dir, &log, 2),
        shot(&dir, &log, 3),
    );
    let n = light_pixels(&on);
    assert!(
        n > 500,
        "{scene}: only {n} pixels of the lights with the lights on"
    );
    assert_eq!(
        light_pixels(&off),
        0,
        "{scene}: key L did not switch the area lights off"
    );
    // Off, the scene keeps only its faint ambient light: much darker.
    let brightness = |img: &image::RgbaImage| {
        img.pixels()
            .map(|p| u64::from(p[0]) + u64::from(p[1]) + u64::from(p[2]))
            .sum::<u64>()
    };
    assert!(
        brightness(&off) * 4 < brightness(&on),
        "{scene}: off {} against on {}",
        brightness(&off),
        brightness(&on)
    );
    assert!(
        differing(&on, &again, 2) < 0.001,
        "{scene}: switched on again, the view is not what it was: {:.4} differs",
        differing(&on, &again, 2)
    );
}
