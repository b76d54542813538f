//! src/techniques/vertex_geometry/tessellation.rs: notes 01 §3.1's rule that
//! edges shared by two patches "must share the same outer tessellation level
//! and vertex calculation". Rendered against a magenta background, the
//! terrain with a level per edge shows no background through it; with one
//! level per patch it cracks, and the cracks show. Tessellation needs GL
//! 4.0, so these renders run as `gloss render` without the 3.3 override the
//! rest of the suite runs under; under it, the terrain is reported missing
//! and the rest of the scene is drawn.

use crate::common;
use gloss::renderer::Output;
use gloss::scene::RenderPath;
use std::process::Command;

/// `gloss render scenes/tessellated-terrain.toml` with `set`, as the GL gives it
/// (`capped`: under MESA_GL_VERSION_OVERRIDE=3.3); the image and stderr.
fn render(name: &str, set: &[&str], capped: bool) -> (image::RgbaImage, String) {
    let out = std::env::temp_dir().join(format!("gloss-tess-{name}.png"));
    let mut c = Command::new(env!("CARGO_BIN_EXE_gloss"));
    c.args([
        "render",
        "scenes/tessellated-terrain.toml",
        "--debug",
        "--backend",
        "egl",
    ])
    .args(["--set", "render.background=[1.0,0.0,1.0]"])
    .args(["--set", "tessellation.height=4.0"]);
    for s in set {
        c.args(["--set", s]);
    }
    if capped {
        c.env("MESA_GL_VERSION_OVERRIDE", "3.3")
            .env("MESA_GLSL_VERSION_OVERRIDE", "330");
    } else {
        c.env_remove("MESA_GL_VERSION_OVERRIDE")
            .env_remove("MESA_GLSL_VERSION_OVERRIDE");
    }
    let o = c
        .arg("-o")
        .arg(&out)
        .current_dir(common::root())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{stderr}");
    (image::open(&out).unwrap().to_rgba8(), stderr)
}

/// Magenta pixels in the middle of the frame, where the terrain covers
/// everything (640 x 360: rows 130 to 230, columns 40 to 600).
fn holes(img: &image::RgbaImage) -> usize {
    (130..=230)
        .flat_map(|y| (40..=600).map(move |x| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[..3] == [255, 0, 255])
        .count()
}

#[test]
fn a_level_per_edge_does_not_crack_and_a_level_per_patch_does() {
    let (shared, stderr) = render("shared", &[], false);
    if stderr.contains("needs OpenGL 4.0") {
        eprintln!("this GL has no 4.0 context: {stderr}");
        return;
    }
    assert_eq!(
        holes(&shared),
        0,
        "the shared-edge terrain shows the background through it"
    );
    let (cracked, _) = render("per-patch", &["tessellation.edges=per_patch"], false);
    let n = holes(&cracked);
    assert!(
        n > 20,
        "a level per patch should crack the terrain: {n} background pixels"
    );
    eprintln!("shared edges: 0 holes; a level per patch: {n}");
}

#[test]
fn on_a_3_3_context_the_terrain_is_reported_and_the_rest_renders() {
    let (img, stderr) = render("capped", &[], true);
    assert!(
        stderr.contains("the tessellated terrain needs OpenGL 4.0")
            && stderr.contains("this context is 3.3"),
        "{stderr}"
    );
    // No terrain: the middle of the frame is background, but for the sphere.
    let background = holes(&img);
    assert!(background > 50_000, "{background}");
    let sphere = (0..img.width())
        .flat_map(|x| (0..img.height()).map(move |y| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[..3] != [255, 0, 255])
        .count();
    assert!(
        sphere > 300,
        "the rest of the scene is drawn: {sphere} pixels"
    );
    // In this process, under the suite's 3.3 cap, the same holds.
    let scene = common::scene("tessellated-terrain.toml");
    let r = common::render(&scene, Output::Srgb8);
    assert!(
        r.image
            .pixels()
            .any(|p| p.0[..3] != r.image.get_pixel(0, 0).0[..3])
    );
}

#[test]
fn the_plan_lists_the_pass_on_the_forward_path_and_says_it_needs_4_0() {
    let scene = common::scene("tessellated-terrain.toml");
    let plan = gloss::techniques::plan(&scene).to_string();
    assert!(
        plan.contains("256 patches (16 x 16) of 4 corners"),
        "{plan}"
    );
    assert!(plan.contains("(needs OpenGL 4.0)"), "{plan}");
    let mut deferred = scene.clone();
    deferred.render.path = RenderPath::Deferred;
    assert!(!gloss::techniques::plan(&deferred).has_pass("tessellation"));
}
