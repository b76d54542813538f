//! Every setting the panel edits (src/scene/knobs.rs) is a scene-file key,
//! and gives the same image three ways: written in the scene file, given as
//! `--set KEY=VALUE` (library and command line), and changed live on a
//! running renderer as the panel does (`Renderer::set_render_settings`).

use crate::common;
use gloss::gl::program::Sources;
use gloss::renderer::{Output, Renderer, render_scene};
use gloss::scene::knobs::{self, Kind, Knob, Value};
use gloss::scene::{RenderSettings, Scene};
use std::process::Command;

const SIZE: (u32, u32) = (160, 90);

/// Values to try for a knob: every other choice, the other bool, a number, a colour.
fn values(k: &Knob, r: &RenderSettings) -> Vec<Value> {
    match (k.kind, (k.get)(r)) {
        (Kind::Bool, Value::Bool(b)) => vec![Value::Bool(!b)],
        (Kind::Number { .. }, _) => vec![Value::Number(0.01), Value::Number(0.2)],
        (Kind::Count { min, max }, _) => vec![Value::Count(min), Value::Count(max.min(min + 2))],
        (Kind::Choice(words), Value::Choice(i)) => (0..words.len())
            .filter(|&j| j != i)
            .map(Value::Choice)
            .collect(),
        (Kind::Color, _) => vec![Value::Color(glam::Vec3::new(0.1, 0.05, 0.2))],
        other => panic!("{}: unexpected {other:?}", k.key),
    }
}

#[test]
fn the_panel_edits_every_render_key_but_the_size() {
    // The scene loader's own list of [render] keys, from its unknown-key error.
    let err = Scene::parse(
        "[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n[render]\nno_such_key = 1\n",
        std::path::Path::new("t.toml"),
    )
    .unwrap_err()
    .to_string();
    let listed = err
        .split("expected one of")
        .nth(1)
        .expect("serde lists the keys");
    let mut keys: Vec<String> = listed
        .split('`')
        .skip(1)
        .step_by(2)
        .map(|k| format!("render.{k}"))
        .collect();
    keys.retain(|k| k != "render.size");
    keys.sort();
    let mut knob_keys: Vec<String> = knobs::ALL.iter().map(|k| k.key.to_string()).collect();
    knob_keys.sort();
    assert_eq!(
        knob_keys, keys,
        "a [render] key the panel cannot edit, or a knob with no key"
    );
}

#[test]
fn every_setting_gives_the_same_image_from_the_file_the_command_line_and_the_panel() {
    let ctx = common::context(common::backend());
    let path = common::root().join("scenes/mixed-lights.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut base = Scene::load(&path).unwrap();
    base.render.size = SIZE;
    // The panel's renderer: made once, then changed live.
    let mut live = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &base,
        &Sources::Embedded,
        SIZE.0 as i32,
        SIZE.1 as i32,
        Output::Srgb8,
    )
    .unwrap();
    let dir = std::env::temp_dir().join("gloss-settings-three-ways");
    std::fs::create_dir_all(&dir).unwrap();
    for k in knobs::ALL {
        for v in values(k, &base.render) {
            // 1. The panel.
            let mut settings = base.render.clone();
            (k.set)(&mut settings, v);
            let value = k.toml(&settings);
            let what = format!("{}={value}", k.key);
            live.set_render_settings(settings.clone()).unwrap();
            live.render(&base.camera).unwrap();
            let panel = live.read_image();
            // 2. `--set` through the library.
            let mut set = Scene::load_with(&path, std::slice::from_ref(&what)).unwrap();
            set.render.size = SIZE;
            assert_eq!(
                set.render, settings,
                "{what}: --set reads the value the panel set"
            );
            let set_image = render_scene(&ctx, &set, Output::Srgb8)
                .unwrap()
                .read_image();
            // 3. Written in the scene file.
            let mut table: toml::Table = toml::from_str(&text).unwrap();
            let (_, key) = k.key.split_once('.').unwrap();
            let parsed: toml::Table = toml::from_str(&format!("v = {value}")).unwrap();
            table["render"]
                .as_table_mut()
                .unwrap()
                .insert(key.to_string(), parsed["v"].clone());
            let file = dir.join("scene.toml");
            std::fs::write(&file, toml::to_string(&table).unwrap()).unwrap();
            let mut written = Scene::load(&file).unwrap();
            written.render.size = SIZE;
            assert_eq!(
                written.render, settings,
                "{what}: the file gives the panel's value"
            );
            let file_image = render_scene(&ctx, &written, Output::Srgb8)
                .unwrap()
                .read_image();
            assert!(
                panel.as_raw() == set_image.as_raw(),
                "{what}: panel != --set"
            );
            assert!(
                panel.as_raw() == file_image.as_raw(),
                "{what}: panel != scene file"
            );
            // 4. `--set` on the command line.
            let png = dir.join("cli.png");
            let out = Command::new(env!("CARGO_BIN_EXE_gloss"))
                .args([
                    "render",
                    "mixed-lights",
                    "--size",
                    "160x90",
                    "--set",
                    &what,
                    "-o",
                ])
                .arg(&png)
                .current_dir(&dir)
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{what}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            let cli = image::open(&png).unwrap().to_rgba8();
            assert!(
                cli.as_raw() == panel.as_raw(),
                "{what}: command line != panel"
            );
        }
    }
    ctx.debug.check(&ctx.gl, "changing settings").unwrap();
}

#[test]
fn edited_lights_materials_and_objects_give_the_image_of_a_scene_made_with_them() {
    // The panel's path: values changed on a running renderer. The reference:
    // a new renderer for the edited scene.
    let ctx = common::context(common::backend());
    let mut scene = common::scene("default.toml");
    scene.render.size = SIZE;
    let mut live = Renderer::new(
        &ctx.gl,
        &ctx.debug,
        &scene,
        &Sources::Embedded,
        SIZE.0 as i32,
        SIZE.1 as i32,
    )
    .unwrap();
    live.render(&scene.camera).unwrap();
    let before = live.read_image();
    scene.lights[0].color = glam::Vec3::new(0.2, 1.0, 0.3);
    scene.lights[1].position.y += 1.0;
    scene.lights[1].kl = 0.0;
    scene.materials[1].diffuse = glam::Vec3::new(1.0, 0.1, 0.1);
    scene.materials[1].shininess = 5.0;
    // Move and turn the box: its child, the rock, follows (notes 01 §6.4).
    let boxed = scene.objects.iter().position(|o| o.name == "box").unwrap();
    let rock = scene.objects.iter().position(|o| o.name == "rock").unwrap();
    assert_eq!(scene.objects[rock].parent, Some(boxed));
    let rock_before = scene.objects[rock].model;
    scene.objects[boxed].position.x += 0.5;
    scene.objects[boxed].rotation.y += 30.0;
    gloss::scene::update_models(&mut scene.objects);
    assert_ne!(
        scene.objects[rock].model, rock_before,
        "the child moves with its parent"
    );
    live.set_scene_values(&scene).unwrap();
    live.render(&scene.camera).unwrap();
    let edited = live.read_image();
    let fresh = render_scene(&ctx, &scene, Output::Srgb8)
        .unwrap()
        .read_image();
    assert!(
        edited.as_raw() == fresh.as_raw(),
        "live edits != a scene made with them"
    );
    assert!(
        edited.as_raw() != before.as_raw(),
        "the edits change the image"
    );
}
