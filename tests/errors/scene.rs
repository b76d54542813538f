//! Scene files: missing, TOML syntax, unknown keys, wrong types, NaN/inf,
//! bad attenuation, unknown names, bad references, camera eye == target.

use crate::{BASE, base_with, cli_fails, contains_all, os, render_fails, temp_dir, write};
use gloss::scene::Scene;
use std::path::Path;

/// Write `text` as `scene.toml` in a fresh directory, check that both
/// `Scene::load` and `gloss plan` refuse it with a message holding `words`
/// (and the file name); return the library's message.
pub fn scene_fails(test: &str, text: &str, words: &[&str]) -> String {
    let dir = temp_dir(test);
    scene_in_dir_fails(&dir, text, words)
}

fn scene_in_dir_fails(dir: &Path, text: &str, words: &[&str]) -> String {
    let path = write(dir, "scene.toml", text);
    let msg = match Scene::load(&path) {
        Ok(_) => panic!(
            "{test}: the scene should be refused:\n{text}",
            test = dir.display()
        ),
        Err(e) => format!("{e:#}"),
    };
    contains_all(&msg, &["scene.toml"]);
    contains_all(&msg, words);
    let stderr = cli_fails(&[os("plan"), path.as_os_str()]);
    contains_all(&stderr, &["scene.toml"]);
    contains_all(&stderr, words);
    msg
}

#[test]
fn base_scene_is_valid() {
    let dir = temp_dir("base_scene_is_valid");
    let path = write(&dir, "scene.toml", BASE);
    Scene::load(&path).expect("BASE loads");
}

#[test]
fn scene_file_missing() {
    let dir = temp_dir("scene_file_missing");
    let path = dir.join("no-such-scene.toml");
    let msg = format!("{:#}", Scene::load(&path).unwrap_err());
    contains_all(&msg, &["cannot read scene file", "no-such-scene.toml"]);
    let out = dir.join("out.png");
    let stderr = render_fails(&path, &out);
    contains_all(&stderr, &["cannot read scene file", "no-such-scene.toml"]);
    assert!(!out.exists(), "no output written for a missing scene");
}

#[test]
fn scene_toml_syntax_error_names_the_line() {
    let text = base_with("near = 1.0", "near = 1.0.0");
    // "near = 1.0" is line 9 of BASE.
    scene_fails(
        "scene_toml_syntax_error_names_the_line",
        &text,
        &["TOML parse error", "line 9", "near = 1.0.0"],
    );
}

#[test]
fn scene_unknown_top_level_key() {
    let text = format!("colour = \"red\"\n{BASE}");
    scene_fails(
        "scene_unknown_top_level_key",
        &text,
        &[
            "unknown field `colour`",
            "line 1",
            "expected one of",
            "camera",
        ],
    );
}

#[test]
fn scene_unknown_key_in_light() {
    let text = base_with("intensity = 1.5", "intensity = 1.5\nradius = 3.0");
    scene_fails(
        "scene_unknown_key_in_light",
        &text,
        &[
            "unknown field `radius`",
            "line 22",
            "intensity",
            "attenuation",
        ],
    );
}

#[test]
fn scene_unknown_key_in_camera() {
    let text = base_with("half_height = 5.0", "half_height = 5.0\nzoom = 2.0");
    scene_fails(
        "scene_unknown_key_in_camera",
        &text,
        &["unknown field `zoom`", "line 9", "half_height", "fov_y"],
    );
}

#[test]
fn scene_wrong_type() {
    let text = base_with("intensity = 1.5", "intensity = \"bright\"");
    scene_fails(
        "scene_wrong_type",
        &text,
        &[
            "line 21",
            "intensity = \"bright\"",
            "invalid type: string \"bright\"",
            "expected f32",
        ],
    );
}

#[test]
fn scene_nan_color() {
    let text = base_with("color = [1.0, 0.9, 0.8]", "color = [nan, 1, 1]");
    scene_fails(
        "scene_nan_color",
        &text,
        &["lights[0].color", "expected finite numbers", "NaN"],
    );
}

#[test]
fn scene_inf_values() {
    let dir = temp_dir("scene_inf_values");
    let text = base_with("intensity = 1.5", "intensity = inf");
    scene_in_dir_fails(
        &dir,
        &text,
        &["lights[0].intensity", "expected finite numbers", "inf"],
    );
    let text = base_with("eye = [0.0, 10.0, 0.0]", "eye = [0.0, -inf, 0.0]");
    scene_in_dir_fails(
        &dir,
        &text,
        &["camera.eye", "expected finite numbers", "-inf"],
    );
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, nan, 0.032]",
    );
    scene_in_dir_fails(
        &dir,
        &text,
        &["lights[0].attenuation", "Kl (linear)", "finite", "NaN"],
    );
}

#[test]
fn scene_negative_attenuation() {
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, -0.09, 0.032]",
    );
    scene_fails(
        "scene_negative_attenuation",
        &text,
        &[
            "lights[0].attenuation",
            "Kl (linear)",
            "must be >= 0",
            "-0.09",
        ],
    );
}

#[test]
fn scene_all_zero_attenuation() {
    let text = base_with(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [0.0, 0.0, 0.0]",
    );
    scene_fails(
        "scene_all_zero_attenuation",
        &text,
        &["lights[0].attenuation", "all 0", "infinitely bright"],
    );
}

#[test]
fn scene_unknown_light_type() {
    let text = base_with("type = \"point\"", "type = \"area\"");
    scene_fails(
        "scene_unknown_light_type",
        &text,
        &[
            "lights[0].type",
            "expected directional, point or spot",
            "\"area\"",
        ],
    );
}

#[test]
fn scene_unknown_render_path() {
    let text = base_with("size = [32, 24]", "size = [32, 24]\npath = \"raytraced\"");
    scene_fails(
        "scene_unknown_render_path",
        &text,
        &[
            // The TOML error quotes the line: the key and its value.
            "path = \"raytraced\"",
            "expected forward, deferred, volumes, prepass or tiled",
            "\"raytraced\"",
        ],
    );
}

#[test]
fn scene_spot_inner_wider_than_outer() {
    let text = base_with(
        "type = \"point\"",
        "type = \"spot\"\ndirection = [0.0, -1.0, 0.0]\ninner_angle = 40.0\nouter_angle = 30.0",
    );
    scene_fails(
        "scene_spot_inner_wider_than_outer",
        &text,
        &[
            "lights[0].inner_angle/outer_angle",
            "inner_angle <= outer_angle",
            "40",
            "30",
        ],
    );
}

#[test]
fn scene_camera_eye_equals_target() {
    let text = base_with("target = [0.0, 0.0, 0.0]", "target = [0.0, 10.0, 0.0]");
    scene_fails(
        "scene_camera_eye_equals_target",
        &text,
        &["camera", "eye and target are the same point"],
    );
}

#[test]
fn scene_missing_mesh_file() {
    let text = base_with("mesh = \"plane\"", "mesh = \"models/missing.obj\"");
    scene_fails(
        "scene_missing_mesh_file",
        &text,
        &["objects[0].mesh", "missing.obj", "does not exist"],
    );
}

#[test]
fn scene_missing_texture_file() {
    let text = base_with(
        "shininess = 24.0",
        "shininess = 24.0\ndiffuse_texture = \"textures/missing.png\"",
    );
    scene_fails(
        "scene_missing_texture_file",
        &text,
        &[
            "materials.floor.diffuse_texture",
            "missing.png",
            "does not exist",
        ],
    );
}

#[test]
fn scene_unknown_material() {
    let text = base_with("material = \"floor\"", "material = \"marble\"");
    scene_fails(
        "scene_unknown_material",
        &text,
        &["objects[0].material", "no material named \"marble\""],
    );
}

#[test]
fn scene_parent_cycle() {
    let text = format!(
        "{}\n[[objects]]\nname = \"b\"\nmesh = \"cube\"\nparent = \"floor\"\n",
        base_with(
            "material = \"floor\"",
            "material = \"floor\"\nparent = \"b\""
        )
    );
    scene_fails("scene_parent_cycle", &text, &["objects[0].parent", "cycle"]);
}

#[test]
fn scene_unknown_parent() {
    let text = base_with(
        "material = \"floor\"",
        "material = \"floor\"\nparent = \"table\"",
    );
    scene_fails(
        "scene_unknown_parent",
        &text,
        &["objects[0].parent", "no object named \"table\""],
    );
}

#[test]
fn material_opacity_out_of_range() {
    for (bad, test) in [
        ("nan", "material_opacity_nan"),
        ("-0.25", "material_opacity_negative"),
        ("1.5", "material_opacity_above_one"),
    ] {
        let text = base_with(
            "shininess = 24.0",
            &format!("shininess = 24.0\nopacity = {bad}"),
        );
        scene_fails(
            test,
            &text,
            &["materials.floor.opacity", "expected a number in [0, 1]"],
        );
    }
}

#[test]
fn microfacet_keys_on_the_wrong_model_or_out_of_range() {
    // BASE's floor is Phong with specular [0.5, 0.5, 0.5] and shininess 24.
    let phong = "specular = [0.5, 0.5, 0.5]\nshininess = 24.0";
    let cases: [(&str, &str, &[&str]); 7] = [
        (
            "microfacet_alpha_on_phong",
            "specular = [0.5, 0.5, 0.5]\nshininess = 24.0\nalpha = 0.3",
            &["materials.floor.alpha", "model = \"microfacet\""],
        ),
        (
            "microfacet_with_shininess",
            "specular = [0.3, 0.3, 0.3]\nshininess = 24.0\nmodel = \"microfacet\"",
            &[
                "materials.floor.shininess",
                "a microfacet material has no shininess",
            ],
        ),
        (
            "microfacet_with_specular",
            "specular = [0.5, 0.5, 0.5]\nmodel = \"microfacet\"",
            &["materials.floor.specular", "alpha, eta and k_s"],
        ),
        (
            "microfacet_alpha_zero",
            "model = \"microfacet\"\nalpha = 0.0",
            &[
                "materials.floor.alpha",
                "expected a number in 0.001..=1000, found 0",
            ],
        ),
        (
            "microfacet_eta_nan",
            "model = \"microfacet\"\neta = nan",
            &[
                "materials.floor.eta",
                "expected a number in 1..=10, found NaN",
            ],
        ),
        (
            "microfacet_k_s_negative",
            "model = \"microfacet\"\nk_s = -1.0",
            &[
                "materials.floor.k_s",
                "expected a number in 0..=10, found -1",
            ],
        ),
        (
            "microfacet_unknown_model",
            "model = \"ward\"",
            &["model", "expected phong or microfacet, found \"ward\""],
        ),
    ];
    for (test, material, words) in cases {
        scene_fails(test, &base_with(phong, material), words);
    }
}

#[test]
fn material_depth_func_unknown_word() {
    let text = base_with(
        "shininess = 24.0",
        "shininess = 24.0\ndepth_func = \"lesser\"",
    );
    scene_fails(
        "material_depth_func_unknown_word",
        &text,
        &[
            "depth_func",
            "never, less, equal, lequal, greater, notequal, gequal or always",
            "lesser",
        ],
    );
}

/// A number beyond f32's range is named as such, not as the "inf" it
/// would become.
#[test]
fn scene_float_out_of_f32_range() {
    let msg = scene_fails(
        "scene_float_out_of_f32_range",
        &base_with("[camera]", "[camera]\nfov_y = 1e39"),
        &["camera.fov_y", "1e39", "out of range of a 32-bit float"],
    );
    assert!(!msg.contains("inf"), "{msg}");
    scene_fails(
        "scene_float_out_of_f32_range_in_an_array",
        &base_with(
            "position = [1.0, 2.0, -0.5]",
            "position = [1.0, -1e300, -0.5]",
        ),
        &["lights[0].position[1]", "out of range of a 32-bit float"],
    );
}

/// A hostile file whose offending line is huge (deep nesting) gets a
/// message of bounded length, not the whole line quoted back.
#[test]
fn scene_parse_error_message_is_capped() {
    let deep = format!(
        "{BASE}\nx = {}{}\n",
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    let msg = scene_fails("scene_parse_error_message_is_capped", &deep, &["left out"]);
    assert!(msg.len() < 3000, "{} characters", msg.len());
}

#[test]
fn scene_near_plane_past_the_depth_buffer() {
    // near 1e-7 with far 20 drew a wrong image (a mean of 63.8 instead of
    // 180.8 on this plane); 1e-30 drew nothing on three paths.
    let perspective = |near: &str| {
        base_with(
            "projection = \"orthographic\"",
            "projection = \"perspective\"",
        )
        .replace("half_height = 5.0\n", "")
        .replace("near = 1.0", &format!("near = {near}"))
    };
    scene_fails(
        "scene_near_plane_past_the_depth_buffer",
        &perspective("1e-7"),
        &[
            "camera.near/far",
            "24-bit depth buffer",
            "notes 01 §4.4",
            "Raise near to at least 2.384e-5",
        ],
    );
    scene_fails(
        "scene_near_plane_underflows",
        &perspective("1e-30"),
        &["camera.near = 1e-30", "underflows f32"],
    );
}

#[test]
fn scene_orthographic_view_below_f32() {
    let text = base_with("half_height = 5.0", "half_height = 1e-30");
    scene_fails(
        "scene_orthographic_view_below_f32",
        &text,
        &["camera.half_height = 1e-30 is too small to draw", "f32"],
    );
}

#[test]
fn scene_object_scaled_past_the_world() {
    let text = base_with("scale = [10.0, 1.0, 10.0]", "scale = [1e13, 1.0, 1e13]");
    scene_fails(
        "scene_object_scaled_past_the_world",
        &text,
        &[
            "objects[0].scale: 1e13 is past 1e9 scene units",
            "clipping in f32",
        ],
    );
}

#[test]
fn scene_far_field_scale_out_of_range() {
    let text = base_with(
        "size = [32, 24]",
        "size = [32, 24]\npath = \"tiled\"\nfar_field = 33",
    );
    scene_fails(
        "scene_far_field_scale_out_of_range",
        &text,
        &["render.far_field", "expected 0 (off)", "1..=32", "found 33"],
    );
}

#[test]
fn animation_tracks_that_cannot_be_played_are_refused() {
    let track =
        |body: &str| format!("{BASE}\n[animation]\ntime = 0.5\n\n[[animation.tracks]]\n{body}\n");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "anim_unknown_object",
            "object = \"nothing\"\ntimes = [0.0]\nposition = [[0, 0, 0]]",
            &["animation.tracks[0].object", "no object named \"nothing\""],
        ),
        (
            "anim_count",
            "object = \"floor\"\ntimes = [0.0, 1.0]\nposition = [[0, 0, 0]]",
            &["animation.tracks[0].position", "2 times but 1 values"],
        ),
        (
            "anim_interpolation",
            "object = \"floor\"\ninterpolation = \"bezier\"\ntimes = [0.0]\nscale = [[1, 1, 1]]",
            &[
                "animation.tracks[0].interpolation",
                "\"step\", \"linear\" or \"cubic\"",
                "\"bezier\"",
            ],
        ),
        (
            "anim_no_channel",
            "object = \"floor\"\ntimes = [0.0]",
            &["animation.tracks[0]", "give position, rotation or scale"],
        ),
        (
            "anim_zero_rotation",
            "object = \"floor\"\ntimes = [0.0]\nrotation = [[0, 0, 0, 0]]",
            &["animation.tracks[0].rotation", "zero"],
        ),
    ];
    for (name, body, words) in cases {
        scene_fails(name, &track(body), words);
    }
    let twice = format!(
        "{}\n[[animation.tracks]]\nobject = \"floor\"\ntimes = [0.0]\nscale = [[2, 2, 2]]\n",
        track("object = \"floor\"\ntimes = [0.0]\nscale = [[1, 1, 1]]")
    );
    scene_fails(
        "anim_twice",
        &twice,
        &[
            "animation.tracks[1].object",
            "already moved by animation.tracks[0]",
        ],
    );
    let weight = format!(
        "{}\n[animation.weights]\nwalk = 1.0\n",
        track("object = \"floor\"\ntimes = [0.0]\nscale = [[1, 1, 1]]")
    );
    scene_fails(
        "anim_weight_no_clip",
        &weight,
        &[
            "animation.weights.walk",
            "no track belongs to a clip named \"walk\"",
        ],
    );
    let negative = format!(
        "{}\n[animation.weights]\nmain = -1.0\n",
        track("object = \"floor\"\ntimes = [0.0]\nscale = [[1, 1, 1]]")
    );
    scene_fails(
        "anim_weight_negative",
        &negative,
        &["animation.weights.main", "expected a weight >= 0"],
    );
    let inf = BASE.to_string() + "\n[animation]\ntime = inf\n";
    scene_fails(
        "anim_time_inf",
        &inf,
        &["animation.time", "finite number of seconds"],
    );
}

#[test]
fn tessellation_tables_that_cannot_be_drawn_are_refused() {
    let with = |body: &str| format!("{BASE}\n[tessellation]\n{body}\n");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "tess_levels",
            "displacement = \"grey.png\"\nlevels = [8.0, 2.0]",
            &["tessellation.levels", "1 <= far <= near <= 64"],
        ),
        (
            "tess_patches",
            "displacement = \"grey.png\"\npatches = 0",
            &["tessellation.patches", "1..=256"],
        ),
        (
            "tess_edges",
            "displacement = \"grey.png\"\nedges = \"sometimes\"",
            &[
                "tessellation.edges",
                "\"shared\" or \"per_patch\"",
                "\"sometimes\"",
            ],
        ),
        (
            "tess_missing_map",
            "displacement = \"no-such-map.png\"",
            &["tessellation.displacement", "no-such-map.png"],
        ),
        (
            "tess_distances",
            "displacement = \"grey.png\"\ndistances = [5.0, 5.0]",
            &["tessellation.distances", "near < far"],
        ),
    ];
    for (name, body, words) in cases {
        let dir = crate::temp_dir(name);
        image::GrayImage::new(4, 4)
            .save(dir.join("grey.png"))
            .unwrap();
        let path = crate::write(&dir, "scene.toml", with(body));
        let msg = format!("{:#}", Scene::load(&path).unwrap_err());
        contains_all(&msg, words);
    }
}

#[test]
fn particle_tables_that_cannot_be_simulated_are_refused() {
    let with = |body: &str| format!("{BASE}\n[particles]\n{body}\n");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "particles_count",
            "count = 0",
            &["particles.count", "found 0"],
        ),
        (
            "particles_rate",
            "rate = -1.0",
            &["particles.rate", "expected a number > 0"],
        ),
        (
            "particles_spread",
            "spread = 200.0",
            &["particles.spread", "0..=180"],
        ),
        (
            "particles_direction",
            "direction = [0, 0, 0]",
            &["particles.direction", "expected a direction"],
        ),
        (
            "particles_expand",
            "expand = \"gpu\"",
            &[
                "particles.expand",
                "\"geometry_shader\" or \"cpu\"",
                "\"gpu\"",
            ],
        ),
        ("particles_unknown", "colour = [1, 1, 1]", &["colour"]),
    ];
    for (name, body, words) in cases {
        scene_fails(name, &with(body), words);
    }
}
