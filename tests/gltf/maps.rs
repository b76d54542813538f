//! glTF's maps beyond the base colour (docs/gltf.md, "Maps"), each against
//! values computed here from the specification's formulas, on every render
//! path: emission is added to the lit colour, occlusion scales the ambient
//! term by 1 + strength (R - 1), and a metallicRoughnessTexture's B and G
//! scale metallic and roughness per texel (the same pixels as a material
//! whose factors hold those values). The images are data: URIs, so the
//! reader of images inside a file is exercised too. `gloss plan` lists
//! every map's memory.

use crate::common;
use crate::files::folder;
use crate::images::{pixel, quad};
use glam::Vec3;
use gloss::geometry::GltfBuilder;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

/// A PNG of `w` x `h` as a data: URI.
fn png_uri(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> String {
    use base64::Engine as _;
    let img = image::RgbaImage::from_fn(w, h, |x, y| image::Rgba(f(x, y)));
    let mut png = std::io::Cursor::new(Vec::new());
    img.write_to(&mut png, image::ImageFormat::Png).unwrap();
    let b64 = base64::engine::general_purpose::STANDARD.encode(png.into_inner());
    format!("data:image/png;base64,{b64}")
}

/// The quad (x, y in -1..1 at z = 0) with `material` (JSON) and `images`
/// (data: URIs), texture k reading image k with nearest sampling.
fn quad_file(material: &str, images: &[String]) -> GltfBuilder {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&quad(), Some(0));
    b.materials.push(material.into());
    for (k, uri) in images.iter().enumerate() {
        b.textures.push(format!(r#"{{"source":{k},"sampler":0}}"#));
        b.images.push(format!(r#"{{"uri":"{uri}"}}"#));
    }
    b.samplers
        .push(r#"{"magFilter":9728,"minFilter":9728,"wrapS":33071,"wrapT":33071}"#.into());
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    b
}

/// The scene of files.rs around `b`, with ambient `ambient` and the light
/// on or off.
fn load(name: &str, b: &GltfBuilder, ambient: f32, light: bool) -> Scene {
    let d = folder(name);
    std::fs::write(d.join("model.gltf"), b.gltf()).unwrap();
    let a = format!("{ambient:?}");
    let mut text = crate::files::scene_text("").replace(
        "ambient = [0.0, 0.0, 0.0]",
        &format!("ambient = [{a}, {a}, {a}]"),
    );
    if !light {
        text = text.replace("color = [1.0, 1.0, 1.0]", "color = [0.0, 0.0, 0.0]");
    }
    std::fs::write(d.join("scene.toml"), text).unwrap();
    let s = Scene::load(&d.join("scene.toml")).unwrap();
    // A metal with a colour is named for its tint (docs/gltf.md); nothing else.
    let w = s.warnings();
    assert!(
        w.iter().all(|w| w.contains("the metal's tint")),
        "{name}: {w:?}"
    );
    s
}

fn linear(c: u8) -> f32 {
    let c = c as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The linear colour at world point (x, y, 0) of `s` on `path`.
fn at(s: &Scene, img: &image::RgbaImage, x: f32, y: f32) -> Vec3 {
    let (px, py) = pixel(s, Vec3::new(x, y, 0.0));
    let p = img.get_pixel(px as u32, py as u32).0;
    Vec3::new(linear(p[0]), linear(p[1]), linear(p[2]))
}

/// Render `s` on every path and check the linear colour at each point.
fn check_every_path(s: &Scene, points: &[(f32, f32, Vec3)], bound: f32) {
    let ctx = common::context(common::backend());
    for &path in RenderPath::ALL {
        let mut s = s.clone();
        s.render.path = path;
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        for &(x, y, want) in points {
            let got = at(&s, &img, x, y);
            assert!(
                (got - want).abs().max_element() <= bound,
                "{path:?} at ({x}, {y}): {got} where {want} was predicted"
            );
        }
    }
}

/// The quadrants' colours (glTF uv (0, 0) is the image's top-left, the
/// quad's top-left corner) at their quad points.
const QUADRANTS: [(f32, f32, [u8; 4]); 4] = [
    (-0.5, 0.5, [255, 0, 0, 255]),
    (0.5, 0.5, [0, 255, 0, 255]),
    (-0.5, -0.5, [0, 0, 255, 255]),
    (0.5, -0.5, [255, 255, 255, 255]),
];

fn quadrants() -> String {
    png_uri(2, 2, |x, y| QUADRANTS[(2 * y + x) as usize].2)
}

#[test]
fn emission_is_factor_times_texture_on_every_path() {
    let e = Vec3::new(0.2, 0.5, 0.8);
    let b = quad_file(
        &format!(
            r#"{{"emissiveFactor":[{},{},{}],"emissiveTexture":{{"index":0}},"pbrMetallicRoughness":{{"baseColorFactor":[0,0,0,1],"metallicFactor":0}}}}"#,
            e.x, e.y, e.z
        ),
        &[quadrants()],
    );
    // No light and no ambient: what is seen is the emission, the sRGB
    // texel decoded times the factor.
    let s = load("emissive", &b, 0.0, false);
    let points: Vec<(f32, f32, Vec3)> = QUADRANTS
        .iter()
        .map(|&(x, y, c)| {
            (
                x,
                y,
                e * Vec3::new(linear(c[0]), linear(c[1]), linear(c[2])),
            )
        })
        .collect();
    // 8-bit steps: the output's, and the G-buffer's gSpecular on the deferred paths.
    check_every_path(&s, &points, 0.006);
}

#[test]
fn occlusion_scales_the_ambient_term_by_its_strength_on_every_path() {
    // R = 64 on the left half, 255 on the right; strength 0.5.
    let map = png_uri(2, 1, |x, _| {
        if x == 0 {
            [64, 0, 0, 255]
        } else {
            [255, 0, 0, 255]
        }
    });
    let b = quad_file(
        r#"{"occlusionTexture":{"index":0,"strength":0.5},"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":0}}"#,
        &[map],
    );
    let s = load("occlusion", &b, 0.5, false);
    let factor = 1.0 + 0.5 * (64.0 / 255.0 - 1.0);
    let points = [
        (-0.5, 0.0, Vec3::splat(0.5 * factor)),
        (0.5, 0.0, Vec3::splat(0.5)),
    ];
    check_every_path(&s, &points, 0.01);
}

#[test]
fn metallic_roughness_texels_act_as_the_factors_they_hold() {
    // B (metallic) 0 on the left, 255 on the right; G (roughness) 128.
    let map = png_uri(2, 1, |x, _| [0, 128, if x == 0 { 0 } else { 255 }, 255]);
    let textured = |ambient: f32, light: bool, name: &str| {
        let b = quad_file(
            r#"{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.6,0.4,1],"metallicFactor":1,"roughnessFactor":1,"metallicRoughnessTexture":{"index":0}}}"#,
            std::slice::from_ref(&map),
        );
        load(name, &b, ambient, light)
    };
    // Ambient alone: c_d = base (1 - metallic): the base colour on the
    // left, black on the right (a metal has no diffuse colour).
    let s = textured(0.5, false, "mr-ambient");
    let points = [
        (-0.5, 0.0, 0.5 * Vec3::new(0.8, 0.6, 0.4)),
        (0.5, 0.0, Vec3::ZERO),
    ];
    check_every_path(&s, &points, 0.01);
    // Lit: each half matches a material whose factors hold its texel
    // (metallic 0 or 1, roughness 128 / 255), drawn through the already
    // tested uniform mapping.
    let lit = textured(0.1, true, "mr-lit");
    let ctx = common::context(common::backend());
    for (x, metallic) in [(-0.5, 0.0), (0.5, 1.0)] {
        let b = quad_file(
            &format!(
                r#"{{"pbrMetallicRoughness":{{"baseColorFactor":[0.8,0.6,0.4,1],"metallicFactor":{metallic},"roughnessFactor":{}}}}}"#,
                128.0 / 255.0
            ),
            &[],
        );
        let plain = load(&format!("mr-plain-{metallic}"), &b, 0.1, true);
        for &path in RenderPath::ALL {
            let (mut a, mut p) = (lit.clone(), plain.clone());
            a.render.path = path;
            p.render.path = path;
            let ia = common::render_with(&ctx, &a, Output::Srgb8).image;
            let ip = common::render_with(&ctx, &p, Output::Srgb8).image;
            for y in [-0.5, 0.0, 0.5] {
                let (ca, cp) = (at(&a, &ia, x, y), at(&p, &ip, x, y));
                assert!(
                    (ca - cp).abs().max_element() < 0.01,
                    "{path:?} metallic {metallic} at ({x}, {y}): map {ca} vs factors {cp}"
                );
            }
        }
    }
}

#[test]
fn gloss_plan_lists_every_maps_memory() {
    let uri = |w: u32, h: u32| png_uri(w, h, |_, _| [128, 128, 255, 255]);
    let b = quad_file(
        r#"{"normalTexture":{"index":1},"occlusionTexture":{"index":3},"emissiveTexture":{"index":4},"emissiveFactor":[1,1,1],"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicRoughnessTexture":{"index":2}}}"#,
        &[uri(4, 4), uri(8, 4), uri(8, 8), uri(16, 8), uri(16, 16)],
    );
    let s = load("plan-maps", &b, 0.1, true);
    let _ = s;
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .arg("plan")
        .arg(crate::files::dir("plan-maps").join("scene.toml"))
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text} {}",
        String::from_utf8_lossy(&out.stderr)
    );
    for (k, kind, (w, h)) in [
        (0, "diffuse", (4, 4)),
        (1, "normal map", (8, 4)),
        (2, "metallic-roughness map", (8, 8)),
        (3, "occlusion map", (16, 8)),
        (4, "emissive map", (16, 16)),
    ] {
        // Level 0 is w x h x 4 bytes (RGBA8).
        let line = format!(
            "model.gltf#images[{k}] ({kind})  {w}x{h}: {} bytes",
            w * h * 4
        );
        assert!(text.contains(&line), "no \"{line}\" in:\n{text}");
    }
}
