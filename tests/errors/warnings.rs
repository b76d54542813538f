//! Keys that parse but have no effect get a warning naming the key and why
//! (src/scene/warnings.rs), printed on stderr as "warning: FILE: ..." by
//! render, plan, bench and the demo; a scene whose keys all count gets none.

use crate::{BASE, base_with, contains_all, os, temp_dir, write};
use gloss::scene::{RenderPath, Scene};

/// BASE (forward, orthographic, one point light) with keys the scene ignores.
fn ignored_keys() -> String {
    let text = base_with(
        "size = [32, 24]",
        "size = [32, 24]\nshading = \"flat\"\ncutoff = 0.01\nstencil_volumes = true\naccumulation = \"rgba32f\"\nmirror_depth = 2\nbillboard_alpha_ref = 0.25\nsort_transparent = false\npost_chain = \"cascaded\"\ntile_size = 32",
    );
    let text = text.replace("half_height = 5.0", "half_height = 5.0\nfov_y = 70.0");
    let text = text.replace(
        "intensity = 1.5",
        "intensity = 1.5\ndirection = [0.0, -1.0, 0.0]\nouter_angle = 40.0\nshadow = { fit = \"scene\" }",
    );
    let text = text.replace("shininess = 24.0", "shininess = 24.0\nalpha_ref = 0.3");
    format!(
        "{text}\n[[lights]]\ntype = \"directional\"\ndirection = [0.0, -1.0, 0.0]\nposition = [0.0, 5.0, 0.0]\nshadow = {{ cube = \"geometry_shader\" }}\n\n[materials.spare]\ndiffuse = [1.0, 0.0, 0.0]\n"
    )
}

fn load(test: &str, text: &str) -> Scene {
    let path = write(&temp_dir(test), "scene.toml", text);
    Scene::load(&path).unwrap_or_else(|e| panic!("{e:#}"))
}

#[test]
fn keys_with_no_effect_are_named_with_why() {
    let w = load("warnings_named", &ignored_keys()).warnings();
    let expected = [
        "render.cutoff = 0.01 has no effect on the forward path: only light volumes (the volumes, prepass and tiled paths) end where a light falls to it",
        "render.tile_size = 32 has no effect on the forward path: only the tiled path bins lights into tiles and slices",
        "render.stencil_volumes = true has no effect on the forward path",
        "render.accumulation = \"rgba32f\" has no effect on the forward path: it has no light accumulation target",
        "render.mirror_depth = 2 has no effect: no object is a mirror",
        "render.billboard_alpha_ref = 0.25 has no effect: the scene has no billboards",
        "render.sort_transparent = false has no effect: no object's material has opacity < 1",
        "render.post_chain = \"cascaded\" has no effect: the scene has no [[post]] passes",
        "lights[0].direction has no effect on a point light: a point light shines every way",
        "lights[0].outer_angle has no effect on a point light: only a spot light has a cone",
        "lights[0].shadow.fit has no effect on a point light",
        "lights[1].position has no effect on a directional light",
        "lights[1].shadow.cube has no effect on a directional light: only a point light's shadow map is a cube",
        "materials.floor.alpha_ref = 0.3 has no effect with alpha_test = \"always\"",
        "materials.spare has no effect: no object uses it",
        "camera.fov_y has no effect on an orthographic camera",
    ];
    for e in expected {
        assert!(
            w.iter().any(|w| w.starts_with(e)),
            "no warning starting {e:?} in:\n{}",
            w.join("\n")
        );
    }
    // Flat shading is the forward path's own: no warning for it here.
    assert!(!w.iter().any(|w| w.starts_with("render.shading")), "{w:?}");
    assert_eq!(w.len(), expected.len(), "{}", w.join("\n"));
}

#[test]
fn the_path_decides_which_render_keys_count() {
    let mut scene = load("warnings_path", &ignored_keys());
    scene.render.path = RenderPath::Volumes;
    let w = scene.warnings();
    // On the volumes path the cutoff, the stencil test and the
    // accumulation target count; flat shading does not.
    for key in [
        "render.cutoff",
        "render.stencil_volumes",
        "render.accumulation",
    ] {
        assert!(!w.iter().any(|w| w.starts_with(key)), "{key}: {w:?}");
    }
    assert!(
        w.iter()
            .any(|w| w.starts_with("render.shading = \"flat\" has no effect on the volumes path")),
        "{w:?}"
    );
    // The bench runs every path: only what holds on all of them.
    let every = scene.warnings_on_every_path();
    assert!(
        !every
            .iter()
            .any(|w| w.starts_with("render.") && w.contains(" path")),
        "{every:?}"
    );
    assert!(
        every.iter().any(|w| w.starts_with("render.mirror_depth")),
        "{every:?}"
    );
}

#[test]
fn defaults_written_out_warn_of_nothing() {
    // "save as" writes every render knob: at its default a key is no news.
    let text = base_with(
        "size = [32, 24]",
        "size = [32, 24]\nshading = \"phong\"\npath = \"deferred\"\ncutoff = 0.01953125\nmsaa = 1\nmirror_order = \"normal_first\"\nmirror_depth = 1\nbillboards = \"alpha_test\"\nbillboard_alpha_ref = 0.5\nsort_transparent = true\npost_chain = \"ping_pong\"",
    );
    let w = load("warnings_defaults", &text).warnings();
    assert!(w.is_empty(), "{w:?}");
    assert!(load("warnings_base", BASE).warnings().is_empty());
}

#[test]
fn every_shipped_scene_sets_only_keys_that_count() {
    for name in gloss::assets::shipped_scenes() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(&name);
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e:#}"));
        assert_eq!(scene.warnings(), Vec::<String>::new(), "{name}");
        // What "save as" writes of it warns of nothing either.
        let saved = Scene::parse(&scene.to_toml().unwrap(), &path).unwrap();
        assert_eq!(saved.warnings(), Vec::<String>::new(), "{name} saved");
    }
}

#[test]
fn the_cli_prints_warnings_and_goes_on() {
    let dir = temp_dir("warnings_cli");
    let path = write(&dir, "scene.toml", ignored_keys());
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([os("plan"), path.as_os_str()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    contains_all(
        &stderr,
        &[
            "warning: ",
            "scene.toml: render.cutoff = 0.01 has no effect on the forward path",
        ],
    );
    // --set counts as writing the key: a path where the cutoff counts
    // silences that warning and raises the one for flat shading.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            os("plan"),
            path.as_os_str(),
            os("--set"),
            os("render.path=volumes"),
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("render.cutoff"), "{stderr}");
    contains_all(
        &stderr,
        &["render.shading = \"flat\" has no effect on the volumes path"],
    );
}

#[test]
fn a_near_plane_that_z_fights_is_warned_about() {
    // far / near = 2e5: one depth step at the far plane is 1.2% of it.
    let text = base_with(
        "projection = \"orthographic\"",
        "projection = \"perspective\"",
    )
    .replace("half_height = 5.0\n", "")
    .replace("near = 1.0", "near = 1e-4");
    let w = load("warnings_near", &text).warnings();
    let want = "camera.near/far: one depth step at the far plane is 2.384e-1 units (1.19% of the distance): surfaces closer than that z-fight (notes 01 §4.4). Raise near to 1.192e-3 for 0.1%";
    assert_eq!(w, [want]);
}

#[test]
fn a_windowed_falloff_makes_the_cutoff_count_on_every_path() {
    let text = base_with(
        "size = [32, 24]",
        "size = [32, 24]\ncutoff = 0.05\nfalloff = \"windowed\"",
    );
    let w = load("windowed_cutoff", &text).warnings();
    assert!(!w.iter().any(|m| m.contains("render.cutoff")), "{w:?}");
    let notes = base_with("size = [32, 24]", "size = [32, 24]\ncutoff = 0.05");
    let w = load("notes_cutoff", &notes).warnings();
    assert!(
        w.iter()
            .any(|m| m.contains("render.cutoff = 0.05 has no effect")),
        "{w:?}"
    );
}
