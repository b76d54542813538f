//! Scene-file errors for billboards and the alpha test: each names the file
//! and the key, and says what was expected. Never a panic.

use crate::{solid_sprite, temp_dir};
use gloss::scene::Scene;

const BASE: &str = r#"
[camera]
eye = [0.0, 2.0, 10.0]
target = [0.0, 0.0, 0.0]

[render]
size = [32, 24]
"#;

fn fails(test: &str, extra: &str, words: &[&str]) {
    fails_text(test, &format!("{BASE}\n{extra}"), words)
}

fn fails_text(test: &str, text: &str, words: &[&str]) {
    let dir = temp_dir(test);
    solid_sprite(&dir, "white.png", 4, 4);
    let path = dir.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let msg = match Scene::load(&path) {
        Ok(_) => panic!("{test}: should be refused:\n{text}"),
        Err(e) => format!("{e:#}"),
    };
    for w in ["scene.toml"].iter().chain(words) {
        assert!(
            msg.contains(w),
            "{test}: the message should contain {w:?}:\n{msg}"
        );
    }
    // `gloss plan` says the same, cleanly: "error:", a non-zero exit, no panic.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .arg("plan")
        .arg(&path)
        .output()
        .expect("run gloss plan");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{test}: gloss plan should fail");
    assert!(stderr.starts_with("error:"), "{test}: {stderr}");
    assert!(!stderr.contains("panicked"), "{test}: {stderr}");
    for w in words {
        assert!(
            stderr.contains(w),
            "{test}: gloss plan should say {w:?}:\n{stderr}"
        );
    }
}

#[test]
fn a_valid_billboard_scene_loads() {
    let dir = temp_dir("valid");
    solid_sprite(&dir, "white.png", 4, 4);
    let text = format!(
        "{BASE}\n[[billboards]]\nsprite = \"white.png\"\ncenter = [0.0, 1.0, 0.0]\nsize = [1.0, 2.0]\n\n[[billboard_fields]]\nsprite = \"white.png\"\ncount = 10\narea = [-1.0, 1.0, -1.0, 1.0]\nheight = [1.0, 1.0]\n"
    );
    let s = Scene::parse(&text, &dir.join("scene.toml")).unwrap();
    assert_eq!(s.billboards.len(), 11);
    assert_eq!(s.sprites.len(), 1, "one sprite, used twice, loaded once");
    // Same seed, same field; on the ground: centre at half the height.
    assert!(
        s.billboards[1..]
            .iter()
            .all(|b| b.center.y == 0.5 && b.size.y == 1.0)
    );
}

#[test]
fn a_missing_sprite_is_named() {
    fails(
        "missing-sprite",
        "[[billboards]]\nsprite = \"no-such.png\"\ncenter = [0.0, 0.0, 0.0]\nsize = [1.0, 1.0]",
        &["billboards[0].sprite", "no-such.png", "does not exist"],
    );
    fails(
        "missing-field-sprite",
        "[[billboard_fields]]\nsprite = \"gone.png\"\ncount = 3\narea = [0.0, 1.0, 0.0, 1.0]\nheight = [1.0, 2.0]",
        &["billboard_fields[0].sprite", "gone.png", "does not exist"],
    );
}

#[test]
fn a_sprite_that_is_not_a_png_is_refused() {
    fails(
        "not-png",
        "[[billboards]]\nsprite = \"scene.toml\"\ncenter = [0.0, 0.0, 0.0]\nsize = [1.0, 1.0]",
        &["billboards[0].sprite", "expected an RGBA .png file"],
    );
}

#[test]
fn bad_billboard_values_name_the_key() {
    let one = |k: &str| {
        format!(
            "[[billboards]]\nsprite = \"white.png\"\ncenter = [0.0, 0.0, 0.0]\nsize = [1.0, 1.0]\n{k}"
        )
    };
    fails(
        "size",
        &one("").replace("size = [1.0, 1.0]", "size = [0.0, 1.0]"),
        &["billboards[0].size", "> 0"],
    );
    fails(
        "center",
        &one("").replace("[0.0, 0.0, 0.0]", "[0.0, nan, 0.0]"),
        &["billboards[0].center", "finite"],
    );
    fails(
        "kind",
        &one("kind = \"conical\""),
        &["kind", "spherical or cylindrical", "conical"],
    );
    fails(
        "unknown-key",
        &one("colour = 1"),
        &["unknown field", "colour"],
    );
    let field = |k: &str| {
        format!(
            "[[billboard_fields]]\nsprite = \"white.png\"\ncount = 3\narea = [0.0, 1.0, 0.0, 1.0]\nheight = [1.0, 2.0]\n{k}"
        )
    };
    fails(
        "height",
        &field("").replace("[1.0, 2.0]", "[2.0, 1.0]"),
        &["billboard_fields[0].height", "min <= max"],
    );
    fails(
        "area",
        &field("").replace("[0.0, 1.0, 0.0, 1.0]", "[1.0, 0.0, 0.0, 1.0]"),
        &["billboard_fields[0].area", "min <= max"],
    );
    fails(
        "aspect",
        &field("aspect = -1.0"),
        &["billboard_fields[0].aspect", "> 0"],
    );
    fails(
        "count",
        &field("").replace("count = 3", "count = 1000000"),
        &["billboards", "at most 100000"],
    );
}

#[test]
fn bad_modes_and_alpha_tests_name_the_key() {
    let mode = BASE.replace(
        "size = [32, 24]",
        "size = [32, 24]\nbillboards = \"sorted\"",
    );
    fails_text(
        "mode",
        &mode,
        &["billboards", "alpha_test, blend or blend_sorted", "sorted"],
    );
    let material = |k: &str| format!("[materials.leaf]\n{k}");
    fails(
        "op",
        &material("alpha_test = \">=\""),
        &["alpha_test", "gequal", "\">=\""],
    );
    fails(
        "ref",
        &material("alpha_ref = 1.5"),
        &["materials.leaf.alpha_ref", "0..=1", "1.5"],
    );
    fails(
        "ref-nan",
        &material("alpha_ref = nan"),
        &["materials.leaf.alpha_ref"],
    );
}

#[test]
fn a_malformed_sprite_is_an_error_when_the_renderer_loads_it() {
    let dir = temp_dir("malformed");
    std::fs::write(dir.join("bad.png"), b"not a png at all").unwrap();
    let text = format!(
        "{BASE}\n[[billboards]]\nsprite = \"bad.png\"\ncenter = [0.0, 0.0, 0.0]\nsize = [1.0, 1.0]\n"
    );
    let scene = Scene::parse(&text, &dir.join("scene.toml")).unwrap();
    let ctx = crate::common::context(crate::common::backend());
    let msg = match gloss::renderer::render_scene(&ctx, &scene, gloss::renderer::Output::Srgb8) {
        Ok(_) => panic!("a malformed sprite should be refused"),
        Err(e) => format!("{e:#}"),
    };
    for w in ["billboard sprite", "bad.png"] {
        assert!(msg.contains(w), "the message should contain {w:?}:\n{msg}");
    }
}

#[test]
fn the_mode_and_the_reference_are_set_keys() {
    let path = crate::common::root().join("scenes/billboards-forest.toml");
    let set = |kv: &str| Scene::load_with(&path, &[kv.to_string()]);
    let s = set("render.billboards=blend_sorted").unwrap();
    assert_eq!(
        s.render.billboards,
        gloss::scene::BillboardMode::BlendSorted
    );
    assert_eq!(
        set("render.billboard_alpha_ref=0.25")
            .unwrap()
            .render
            .billboard_alpha_ref,
        0.25
    );
    let msg = format!("{:#}", set("render.billboards=sorted").unwrap_err());
    for w in [
        "--set render.billboards=sorted",
        "alpha_test, blend or blend_sorted",
    ] {
        assert!(msg.contains(w), "{msg}");
    }
    let msg = format!("{:#}", set("render.billboard_alpha_ref=2").unwrap_err());
    assert!(
        msg.contains("render.billboard_alpha_ref: expected a number in 0..=1"),
        "{msg}"
    );
}
