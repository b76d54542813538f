//! The depth test per material (notes 05, "Depth Test and Operation": "Always,
//! Never, <, <=, =, !=, >, >="): a red pane in front, drawn first with the
//! default GL_LESS, then a blue pane behind it with the function under test.
//! The blue pane shows where the CPU twin `DepthFunc::passes` says its depth
//! passes against the red pane's, in the forward and deferred paths.

use crate::common;
use gloss::renderer::Output;
use gloss::scene::{DepthFunc, RenderPath, Scene};
use std::path::Path;

fn panes(func: DepthFunc) -> Scene {
    panes_at(
        func,
        "position = [0.0, 0.0, -1.0]\nrotation = [90.0, 0.0, 0.0]",
        "rotation = [90.0, 0.0, 0.0]",
    )
}

/// The red pane (placed by `front`) drawn first with GL_LESS, then the
/// blue pane (placed by `back`) with `func`, in the file's order.
fn panes_at(func: DepthFunc, back: &str, front: &str) -> Scene {
    let text = format!(
        r#"
[camera]
projection = "orthographic"
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
half_height = 3.0
near = 1.0
far = 20.0

[render]
size = [48, 36]
ambient = [0.6, 0.6, 0.6]
sort_opaque = false

[materials.red]
diffuse = [0.9, 0.1, 0.05]

[materials.blue]
diffuse = [0.05, 0.2, 0.9]
depth_func = "{}"

[[objects]]
name = "front"
mesh = "plane"
material = "red"
{front}
scale = [2.0, 1.0, 2.0]

[[objects]]
name = "back"
mesh = "plane"
material = "blue"
{back}
scale = [2.0, 1.0, 2.0]
"#,
        func.name()
    );
    Scene::parse(&text, Path::new("panes.toml")).unwrap()
}

#[test]
fn every_depth_function_per_material_as_the_cpu_predicts() {
    // Window depths of an orthographic camera: linear, (z - near) / (far - near).
    let (d_front, d_back) = (9.0 / 19.0, 10.0 / 19.0);
    for &func in DepthFunc::ALL {
        let blue_wins = func.passes(d_back, d_front);
        for path in [
            RenderPath::Forward,
            RenderPath::Deferred,
            RenderPath::Volumes,
        ] {
            let mut scene = panes(func);
            scene.render.path = path;
            let img = common::render(&scene, Output::Srgb8).image;
            let p = img.get_pixel(24, 18);
            let shows_blue = p[2] > p[0];
            if shows_blue != blue_wins {
                let out = common::out_dir().join(format!("depth-func-{func}-{}.png", path.name()));
                img.save(&out).unwrap();
                panic!(
                    "{func} ({path:?}): the back pane {} but d = {d_back:.4} {} D = {d_front:.4}; image {}",
                    if shows_blue { "shows" } else { "is hidden" },
                    if blue_wins {
                        "passes against"
                    } else {
                        "fails against"
                    },
                    out.display()
                );
            }
        }
    }
}

#[test]
fn a_second_pass_at_equal_depth_passes_with_lequal_and_not_with_less() {
    // Notes 01 §4.4 / 05: a second pass over the same surface meets depths
    // equal to its own. Both panes are the same slanted plane (the same
    // vertices through the same matrices, so the same window depth at
    // every pixel, varying across it): the blue one drawn second shows
    // where func.passes(d, d), i.e. for <=, =, >= and always, and is
    // hidden for <, >, != and never. Every pixel of the pane is checked,
    // forward and deferred.
    let slant = "rotation = [60.0, 25.0, 0.0]";
    for &func in DepthFunc::ALL {
        let blue_wins = func.passes(0.5, 0.5);
        for path in [RenderPath::Forward, RenderPath::Deferred] {
            let mut scene = panes_at(func, slant, slant);
            scene.render.path = path;
            let img = common::render(&scene, Output::Srgb8).image;
            let (mut pane, mut wrong) = (0, 0);
            for p in img.pixels() {
                let (red, blue) = (
                    p[0] as i32 > p[2] as i32 + 60,
                    p[2] as i32 > p[0] as i32 + 60,
                );
                if red || blue {
                    pane += 1;
                    wrong += usize::from(blue != blue_wins);
                }
            }
            if pane < 300 || wrong > 0 {
                let out =
                    common::out_dir().join(format!("depth-coplanar-{func}-{}.png", path.name()));
                img.save(&out).unwrap();
                panic!(
                    "{func} ({path:?}): {wrong} of {pane} pane pixels show the wrong pane; equal depths {} (image {})",
                    if blue_wins { "pass" } else { "fail" },
                    out.display()
                );
            }
        }
    }
}

#[test]
fn per_material_depth_functions_leave_gl_less_behind() {
    let ctx = common::context(common::backend());
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Prepass,
    ] {
        let mut scene = panes(DepthFunc::Always);
        scene.render.path = path;
        let changed = common::state_left_changed(&ctx, &scene, 48, 36);
        assert!(changed.is_empty(), "{path:?}:\n  {}", changed.join("\n  "));
    }
}

#[test]
fn old_scene_files_keep_their_depth_words() {
    // The two words scene files had before the other six: unchanged.
    for (word, func) in [("less", DepthFunc::Less), ("lequal", DepthFunc::Lequal)] {
        let text = std::fs::read_to_string(common::root().join("scenes/plane.toml")).unwrap();
        let text = text.replace("[render]", &format!("[render]\ndepth_func = \"{word}\""));
        let s = Scene::parse(&text, Path::new("plane.toml")).unwrap();
        assert_eq!(s.render.depth_func, func);
        assert_eq!(
            func.gl(),
            if word == "less" {
                glow::LESS
            } else {
                glow::LEQUAL
            }
        );
    }
    assert_eq!(DepthFunc::ALL.len(), 8);
}
