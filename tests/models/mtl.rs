//! An OBJ's MTL materials on screen: colours and texels at the pixels a
//! hand computation predicts, the specular map, warnings and overrides.

use crate::common;
use crate::{linear_at, srgb_to_linear, temp_dir, write};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::Path;

/// Two unit quads side by side facing +z: x in -1..0 uses material
/// `left`, x in 0..1 material `right`; uv (0, 0) at each quad's
/// bottom-left corner.
const TWO_QUADS: &str = "mtllib quads.mtl
v -1 -1 0
v 0 -1 0
v 0 1 0
v -1 1 0
v 0 -1 0
v 1 -1 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl left
f 1/1/1 2/2/1 3/3/1 4/4/1
usemtl right
f 5/1/1 6/2/1 7/3/1 8/4/1
";

/// Texel colours of the 4 x 4 test texture: columns 0-1 A, 2-3 B.
const A: [u8; 3] = [200, 40, 30];
const B: [u8; 3] = [20, 180, 60];

fn two_column_png(path: &Path, a: [u8; 3], b: [u8; 3]) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    let img = image::RgbImage::from_fn(4, 4, |x, _| image::Rgb(if x < 2 { a } else { b }));
    img.save(path).unwrap();
}

/// The quads seen head-on through an orthographic camera, 64 x 64 pixels:
/// pixel column c looks at x = (c + 0.5) / 32 - 1.
fn scene(dir: &Path, extra: &str, lights: &str, ambient: f32) -> Scene {
    let text = format!(
        r#"
[camera]
projection = "orthographic"
eye = [0.0, 0.0, 5.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
half_height = 1.0
near = 1.0
far = 10.0

[render]
size = [64, 64]
ambient = [{ambient}, {ambient}, {ambient}]
background = [0.0, 0.0, 1.0]

{lights}

[materials.grey]
diffuse = [0.5, 0.5, 0.5]
specular = [0.0, 0.0, 0.0]

[[objects]]
name = "model"
mesh = "quads.obj"
{extra}
"#
    );
    Scene::parse(&text, &dir.join("scene.toml")).expect("scene loads")
}

fn close(a: [f32; 3], b: [f32; 3], tol: f32) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn an_mtl_colour_and_a_map_kd_texel_land_on_the_predicted_pixels() {
    let dir = temp_dir("mtl-colours");
    write(&dir, "quads.obj", TWO_QUADS);
    // Written as a Windows exporter would: backslash, spaces, another case.
    write(
        &dir,
        "quads.mtl",
        "newmtl left\nKd 0.8 0.2 0.1\nKs 0 0 0\nillum 2\n\nnewmtl right\nKs 0 0 0\nmap_Kd Tex\\Two Columns.PNG\n",
    );
    two_column_png(&dir.join("tex/two columns.png"), A, B);
    let ctx = common::context(common::backend());
    let s = scene(&dir, "", "", 1.0);
    let file_warnings: Vec<String> = (s.warnings().into_iter())
        .filter(|w| !w.starts_with("materials.grey"))
        .collect();
    assert!(file_warnings.is_empty(), "{file_warnings:?}");
    // One object per usemtl part: the second is a child of the first.
    assert_eq!(s.objects.len(), 2);
    assert_eq!(s.objects[1].parent, Some(0));
    assert_eq!(s.objects[1].name, "model.right");
    let decode = |c: [u8; 3]| c.map(srgb_to_linear);
    for path in RenderPath::ALL {
        let mut s = s.clone();
        s.render.path = *path;
        let r = common::render_with(&ctx, &s, Output::Linear32F);
        // Ambient 1, no light: each pixel is its c_d (x the texel).
        let red = linear_at(&r, 16, 32);
        assert!(
            close(red, [0.8, 0.2, 0.1], 0.01),
            "{path}: Kd pixel {red:?}"
        );
        // Column 40: x = 0.27, u = 0.27 (texels 0 and 1, both A).
        let a = linear_at(&r, 40, 32);
        assert!(
            close(a, decode(A), 0.01),
            "{path}: texel A {a:?} vs {:?}",
            decode(A)
        );
        // Column 56: x = 0.77, u = 0.77 (texels 2 and 3, both B).
        let b = linear_at(&r, 56, 32);
        assert!(
            close(b, decode(B), 0.01),
            "{path}: texel B {b:?} vs {:?}",
            decode(B)
        );
    }
    // The scene's material overrides the file's: one mesh, one colour.
    let grey = scene(&dir, "material = \"grey\"", "", 1.0);
    assert_eq!(grey.objects.len(), 1);
    let r = common::render_with(&ctx, &grey, Output::Linear32F);
    for x in [16, 40, 56] {
        assert!(close(linear_at(&r, x, 32), [0.5; 3], 0.01));
    }
}

#[test]
fn a_specular_map_darkens_the_highlight_where_it_is_black() {
    let dir = temp_dir("mtl-specular-map");
    write(&dir, "quads.obj", TWO_QUADS);
    // Black diffuse: only the highlight shows. Ns 1: a lobe as wide as the quad.
    let mtl = |map: &str| {
        format!(
            "newmtl left\nKd 0 0 0\nKs 0 0 0\n\nnewmtl right\nKd 0 0 0\nKs 1 1 1\nNs 1\nillum 2\n{map}\n"
        )
    };
    two_column_png(&dir.join("spec.png"), [0; 3], [255; 3]);
    let light = "[[lights]]\ntype = \"directional\"\ndirection = [0.0, 0.0, -1.0]\nintensity = 1.0";
    let ctx = common::context(common::backend());
    write(&dir, "quads.mtl", &mtl(""));
    let plain = scene(&dir, "", light, 0.0);
    write(&dir, "quads.mtl", &mtl("map_Ks spec.png"));
    let mapped = scene(&dir, "", light, 0.0);
    assert!(mapped.materials.iter().any(|m| m.specular_map.is_some()));
    for path in RenderPath::ALL {
        let (mut p, mut m) = (plain.clone(), mapped.clone());
        p.render.path = *path;
        m.render.path = *path;
        let p = common::render_with(&ctx, &p, Output::Linear32F);
        let m = common::render_with(&ctx, &m, Output::Linear32F);
        // Where the map is black (u < 0.5, column 40) the highlight is gone;
        // where it is white (column 56) it is the map-less highlight.
        let (lit, dark, white) = (
            linear_at(&p, 40, 32),
            linear_at(&m, 40, 32),
            linear_at(&m, 56, 32),
        );
        assert!(lit[0] > 0.3, "{path}: no highlight to darken: {lit:?}");
        assert!(
            dark.iter().all(|x| *x < 0.01),
            "{path}: black map, highlight {dark:?}"
        );
        let expected = linear_at(&p, 56, 32);
        assert!(
            close(white, expected, 0.01),
            "{path}: white map {white:?} vs {expected:?}"
        );
    }
}

#[test]
fn a_missing_texture_is_a_warning_naming_the_material_and_the_path() {
    let dir = temp_dir("mtl-missing");
    write(&dir, "quads.obj", TWO_QUADS);
    write(
        &dir,
        "quads.mtl",
        "newmtl left\nKd 0.8 0.2 0.1\nKs 0 0 0\nnewmtl right\nKd 0.1 0.7 0.2\nKs 0 0 0\nmap_Kd textures/gone.jpg\n",
    );
    let s = scene(&dir, "", "", 1.0);
    let w = s.warnings().join("\n");
    assert!(
        w.contains("quads.mtl") && w.contains("\"right\"") && w.contains("textures/gone.jpg"),
        "{w}"
    );
    // The rest renders: the part keeps its Kd.
    let r = common::render(&s, Output::Linear32F);
    assert!(close(linear_at(&r, 16, 32), [0.8, 0.2, 0.1], 0.01));
    assert!(close(linear_at(&r, 48, 32), [0.1, 0.7, 0.2], 0.01));
    // An MTL that is not there: one warning, default material.
    write(
        &dir,
        "quads.obj",
        &TWO_QUADS.replace("quads.mtl", "nowhere.mtl"),
    );
    let s = scene(&dir, "", "", 1.0);
    let w = s.warnings().join("\n");
    assert!(w.contains("nowhere.mtl") && w.contains("not found"), "{w}");
    assert_eq!(s.objects.len(), 1);
}

#[test]
fn a_malformed_mtl_is_an_error_naming_the_file_and_the_line() {
    let dir = temp_dir("mtl-malformed");
    write(&dir, "quads.obj", TWO_QUADS);
    write(&dir, "quads.mtl", "newmtl left\nKd 0.8 zero 0.1\n");
    let e = scene_err(&dir);
    let e = format!("{e:#}");
    assert!(
        e.contains("quads.mtl") && e.contains("line 2") && e.contains("Kd 0.8 zero 0.1"),
        "{e}"
    );
}

fn scene_err(dir: &Path) -> anyhow::Error {
    let text = "[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\n[[objects]]\nmesh = \"quads.obj\"\n";
    Scene::parse(text, &dir.join("scene.toml")).unwrap_err()
}
