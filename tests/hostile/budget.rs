//! The frame's budget (src/frame/budget.rs): render targets, shadow maps,
//! cube maps and light maps against GL's limits and the memory budget, and
//! the light maps' bake against its work limit, in `plan` as in `render`,
//! before anything is allocated.

use crate::{BASE, contains_all, gloss_in, temp_dir, write};
use gloss::frame::budget::{GlLimits, MAX_BAKE_WORK, check};

/// Both commands refuse with the same line; returns it.
fn refused(dir: &std::path::Path, scene: &str, extra: &[&str]) -> String {
    let mut plan = vec!["plan", scene];
    plan.extend(extra);
    let mut render = vec!["render", scene, "-o", "out.png"];
    render.extend(extra);
    let a = gloss_in(dir, &plan, &[]).failed().to_string();
    let b = gloss_in(dir, &render, &[]).failed().to_string();
    assert_eq!(a, b, "plan and render refuse alike");
    a
}

#[test]
fn a_huge_frame_on_tiled_with_ao_and_bloom_is_refused_before_allocating() {
    let dir = temp_dir("budget_size");
    write(&dir, "scene.toml", BASE);
    // 8192 x 8192 on the tiled path with AO and bloom: 5.2 GB of targets.
    let msg = refused(
        &dir,
        "scene.toml",
        &[
            "--set",
            "render.size=[8192, 8192]",
            "--set",
            "render.path=tiled",
            "--set",
            "ambient_occlusion.radius=0.5",
            "--set",
            "post=[{ pass = \"bloom\" }, { pass = \"gamma\" }]",
        ],
    );
    contains_all(
        &msg,
        &[
            "scene.toml",
            "render.size = 8192x8192",
            "over gloss's budget of 2.00 GiB (MEMORY_BUDGET)",
        ],
    );
    // The same frame at 1024 x 1024 is 64 times smaller and renders.
    gloss_in(
        &dir,
        &[
            "render",
            "scene.toml",
            "-o",
            "out.png",
            "--set",
            "render.size=[1024, 1024]",
            "--set",
            "render.path=tiled",
        ],
        &["out.png"],
    )
    .succeeded();
}

#[test]
fn a_point_lights_8192_shadow_cube_names_the_key_and_the_limit() {
    let dir = temp_dir("budget_cube");
    let scene = BASE.replace(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, 0.09, 0.032]\nshadow = { resolution = 8192 }",
    );
    write(&dir, "scene.toml", scene);
    let msg = refused(&dir, "scene.toml", &[]);
    contains_all(
        &msg,
        &[
            "lights[0].shadow.resolution = 8192",
            "shadow cube map (6 faces of 8192x8192",
            "takes 1.50 GiB",
            "MAX_TEXTURE_BYTES",
        ],
    );
    // 4096 a face is 384 MiB: drawn.
    gloss_in(
        &dir,
        &[
            "render",
            "scene.toml",
            "-o",
            "out.png",
            "--set",
            "lights[0].shadow.resolution=4096",
        ],
        &["out.png"],
    )
    .succeeded();
}

/// A PNG header claiming `side` x `side` pixels and no pixels: the budget
/// refuses it from the header, before anything is decoded.
fn claimed_png(side: u32) -> Vec<u8> {
    let mut ihdr = b"IHDR".to_vec();
    ihdr.extend(side.to_be_bytes());
    ihdr.extend(side.to_be_bytes());
    ihdr.extend([8, 6, 0, 0, 0]);
    let crc = crc32(&ihdr);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    png.extend(13u32.to_be_bytes());
    png.extend(&ihdr);
    png.extend(crc.to_be_bytes());
    png.extend(0u32.to_be_bytes());
    png.extend(b"IDAT");
    png.extend(crc32(b"IDAT").to_be_bytes());
    png.extend(0u32.to_be_bytes());
    png.extend(b"IEND");
    png.extend(crc32(b"IEND").to_be_bytes());
    png
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 == 1 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

#[test]
fn six_8192_sky_faces_are_refused_not_drawn_without_a_sky() {
    let dir = temp_dir("budget_sky");
    let png = claimed_png(8192);
    let mut faces = Vec::new();
    for f in ["px", "nx", "py", "ny", "pz", "nz"] {
        write(&dir, &format!("{f}.png"), &png);
        faces.push(format!("\"{f}.png\""));
    }
    write(
        &dir,
        "scene.toml",
        format!("{BASE}\n[skybox]\nfaces = [{}]\n", faces.join(", ")),
    );
    let msg = refused(&dir, "scene.toml", &[]);
    contains_all(
        &msg,
        &[
            "skybox.faces = 8192x8192 images",
            "cube map",
            "2.00 GiB",
            "MAX_TEXTURE_BYTES",
        ],
    );
}

#[test]
fn light_map_bakes_are_bounded_in_work_and_memory() {
    let dir = temp_dir("budget_bake");
    // A 2048 map with shadows under 1023 lights.
    let mut lights = String::new();
    for i in 0..1022 {
        lights += &format!(
            "[[lights]]\ntype = \"point\"\nposition = [{}, 2.0, 0.0]\nintensity = 0.01\n",
            i as f32 * 0.01
        );
    }
    let scene = BASE.replace(
        "scale = [10.0, 1.0, 10.0]",
        "scale = [10.0, 1.0, 10.0]\nlight_map = { size = 2048, shadows = true }",
    );
    write(&dir, "many_lights.toml", format!("{scene}\n{lights}"));
    let msg = refused(&dir, "many_lights.toml", &[]);
    let work = 2048u64 * 2048 * 1023 * 4;
    contains_all(
        &msg,
        &[
            "objects[0].light_map = { size = 2048, shadows = true }",
            &format!("takes {work} texel-light evaluations"),
            &format!("limit of {MAX_BAKE_WORK} (MAX_BAKE_WORK)"),
        ],
    );
    // 120 light-mapped objects of 2048 texels a side: 3.75 GiB of maps.
    let mut objects = String::from(BASE);
    for i in 0..120 {
        objects += &format!(
            "[[objects]]\nname = \"o{i}\"\nmesh = \"cube\"\nlight_map = {{ size = 2048 }}\n"
        );
    }
    write(&dir, "many_maps.toml", objects);
    let msg = refused(&dir, "many_maps.toml", &[]);
    contains_all(
        &msg,
        &["over gloss's budget", "objects[", "light_map.size = 2048"],
    );
    // A bake of a few million evaluations runs, saying what it does.
    let small = BASE.replace(
        "scale = [10.0, 1.0, 10.0]",
        "scale = [10.0, 1.0, 10.0]\nlight_map = { size = 1500 }",
    );
    write(&dir, "small.toml", small);
    let run = gloss_in(
        &dir,
        &["render", "small.toml", "-o", "out.png"],
        &["out.png"],
    );
    contains_all(
        run.succeeded(),
        &["baking the light map of object floor (1500x1500 texels, 1 lights)"],
    );
}

/// GL's limits, which llvmpipe sets high (16384): the same check with a
/// smaller GL's limits names the key, the GL constant and its value.
#[test]
fn gl_limits_name_the_constant() {
    let scene = BASE.replace(
        "attenuation = [1.0, 0.09, 0.032]",
        "attenuation = [1.0, 0.09, 0.032]\nshadow = { resolution = 2048 }",
    );
    let s = gloss::scene::Scene::parse(&scene, std::path::Path::new("small-gl.toml")).unwrap();
    let plan = gloss::techniques::plan(&s);
    let gl = |texture, cube_map, renderbuffer| GlLimits {
        texture,
        cube_map,
        renderbuffer,
        viewport: (16384, 16384),
    };
    let e = check(&s, &plan.targets, 32, 24, Some(&gl(16384, 1024, 16384)))
        .unwrap_err()
        .to_string();
    contains_all(
        &e,
        &[
            "small-gl.toml: lights[0].shadow.resolution = 2048",
            "2048x2048, larger than this GL's GL_MAX_CUBE_MAP_TEXTURE_SIZE (1024)",
        ],
    );
    let e = check(&s, &plan.targets, 4096, 24, Some(&gl(16384, 16384, 2048)))
        .unwrap_err()
        .to_string();
    contains_all(
        &e,
        &["render.size = 4096x24", "GL_MAX_RENDERBUFFER_SIZE (2048)"],
    );
    let e = check(&s, &plan.targets, 32, 24, Some(&gl(1024, 16384, 16384)));
    assert!(e.is_ok(), "a 2048 cube is no 2D texture: {e:?}");
    // Without a GL the plan names what it did not check.
    let unchecked = check(&s, &plan.targets, 32, 24, None).unwrap();
    assert_eq!(
        unchecked,
        ["GL_MAX_CUBE_MAP_TEXTURE_SIZE for lights[0].shadow.resolution = 2048"]
    );
}
