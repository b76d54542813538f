//! Khronos glTF samples vendored in scenes/assets/khronos (its LICENSE.md
//! attributes them), loaded as a student would load them: BoxTextured as
//! published (.gltf, its PNG a data: URI) and as a .glb whose PNG lies in
//! a buffer view. The texel the camera sees is predicted from the file,
//! read here with the `gltf` crate and decoded by hand, not through gloss.

use crate::common;
use crate::files::folder;
use crate::images::pixel;
use glam::{Mat4, Vec2, Vec3};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::{Path, PathBuf};

fn khronos(file: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("scenes/assets/khronos")
        .join(file)
}

/// A scene looking down -z at the sample from z = 5 (orthographic, half
/// height 2, 200 x 200), lit by a white directional light from the camera,
/// no ambient.
fn scene_with(name: &str, mesh: &Path) -> Scene {
    let d = folder(name);
    let text = crate::files::scene_text("").replace(
        "mesh = \"model.gltf\"",
        &format!("mesh = {:?}", mesh.display().to_string()),
    );
    std::fs::write(d.join("scene.toml"), text).unwrap();
    Scene::load(&d.join("scene.toml")).unwrap()
}

/// BoxTextured read independently: world-space triangles facing +z (the
/// camera) with their glTF uvs, and the decoded PNG.
struct Facing {
    triangles: Vec<([Vec3; 3], [Vec2; 3])>,
    image: image::RgbaImage,
}

fn facing_triangles() -> Facing {
    use base64::Engine as _;
    let text = std::fs::read(khronos("BoxTextured.gltf")).unwrap();
    let doc = gltf::Gltf::from_slice(&text).unwrap();
    let b64 = |uri: &str| {
        let (_, data) = uri.split_once(";base64,").unwrap();
        base64::engine::general_purpose::STANDARD
            .decode(data)
            .unwrap()
    };
    let buffer = match doc.buffers().next().unwrap().source() {
        gltf::buffer::Source::Uri(u) => b64(u),
        _ => panic!("BoxTextured.gltf's buffer is a data: URI"),
    };
    let png = match doc.images().next().unwrap().source() {
        gltf::image::Source::Uri { uri, .. } => b64(uri),
        _ => panic!("BoxTextured.gltf's image is a data: URI"),
    };
    let image = image::load_from_memory(&png).unwrap().to_rgba8();
    let floats = |a: &gltf::Accessor, n: usize| -> Vec<Vec<f32>> {
        let v = a.view().unwrap();
        let stride = v.stride().unwrap_or(4 * n);
        (0..a.count())
            .map(|i| {
                let at = v.offset() + a.offset() + i * stride;
                (0..n)
                    .map(|k| {
                        f32::from_le_bytes(buffer[at + 4 * k..at + 4 * k + 4].try_into().unwrap())
                    })
                    .collect()
            })
            .collect()
    };
    let prim = doc.meshes().next().unwrap().primitives().next().unwrap();
    let pos = floats(&prim.get(&gltf::Semantic::Positions).unwrap(), 3);
    let uv = floats(&prim.get(&gltf::Semantic::TexCoords(0)).unwrap(), 2);
    let ia = prim.indices().unwrap();
    let iv = ia.view().unwrap();
    let index = |i: usize| {
        let at = iv.offset() + ia.offset() + 2 * i;
        u16::from_le_bytes([buffer[at], buffer[at + 1]]) as usize
    };
    // The mesh node sits under node 0, whose matrix turns the box.
    let root = doc.nodes().next().unwrap();
    let m = Mat4::from_cols_array_2d(&root.transform().matrix());
    let mut triangles = Vec::new();
    for t in 0..ia.count() / 3 {
        let k = [index(3 * t), index(3 * t + 1), index(3 * t + 2)];
        let p = k.map(|i| m.transform_point3(Vec3::new(pos[i][0], pos[i][1], pos[i][2])));
        if p.iter().all(|p| (p.z - 0.5).abs() < 1e-5) {
            triangles.push((p, k.map(|i| Vec2::new(uv[i][0], uv[i][1]))));
        }
    }
    assert_eq!(
        triangles.len(),
        2,
        "one face of two triangles faces the camera"
    );
    Facing { triangles, image }
}

/// The glTF uv at world point (x, y) of the facing side, by barycentrics.
fn uv_at(f: &Facing, x: f32, y: f32) -> Vec2 {
    for (p, uv) in &f.triangles {
        let (a, b, c) = (p[0].truncate(), p[1].truncate(), p[2].truncate());
        let q = Vec2::new(x, y);
        let d = (b - a).perp_dot(c - a);
        let l1 = (q - a).perp_dot(c - a) / d;
        let l2 = (b - a).perp_dot(q - a) / d;
        let l0 = 1.0 - l1 - l2;
        if l0 >= -1e-6 && l1 >= -1e-6 && l2 >= -1e-6 {
            return uv[0] * l0 + uv[1] * l1 + uv[2] * l2;
        }
    }
    panic!("({x}, {y}) is not on the facing side");
}

/// The texel at glTF uv (repeat, row 0 at v = 0) and whether the texels
/// within `r` of it all match it within 2 (so filtering cannot change it).
fn texel(img: &image::RgbaImage, uv: Vec2, r: i64) -> ([u8; 4], bool) {
    let (w, h) = (img.width() as i64, img.height() as i64);
    let tx = ((uv.x.rem_euclid(1.0)) * w as f32) as i64;
    let ty = ((uv.y.rem_euclid(1.0)) * h as f32) as i64;
    let at = |x: i64, y: i64| {
        img.get_pixel(x.rem_euclid(w) as u32, y.rem_euclid(h) as u32)
            .0
    };
    let c = at(tx, ty);
    let flat = (-r..=r)
        .all(|dy| (-r..=r).all(|dx| (0..3).all(|k| at(tx + dx, ty + dy)[k].abs_diff(c[k]) <= 2)));
    (c, flat)
}

fn srgb_to_linear(c: u8) -> f32 {
    let c = c as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[test]
fn box_textured_shows_its_texel_where_the_file_puts_it_from_gltf_and_glb() {
    let f = facing_triangles();
    // Points on the facing side whose texel has flat surroundings: 12
    // texels each way covers the trilinear footprint (256 texels over
    // about 50 pixels: level 2-3).
    let mut points = Vec::new();
    for i in 0..9 {
        for j in 0..9 {
            let (x, y) = (-0.4 + 0.1 * i as f32, -0.4 + 0.1 * j as f32);
            let (c, flat) = texel(&f.image, uv_at(&f, x, y), 12);
            if flat {
                points.push((x, y, c));
            }
        }
    }
    let colours: std::collections::HashSet<[u8; 4]> = points.iter().map(|p| p.2).collect();
    assert!(
        points.len() >= 4 && colours.len() >= 2,
        "flat texels of two colours at least: {points:?}"
    );
    let mut images = Vec::new();
    for file in ["BoxTextured.gltf", "BoxTextured.glb"] {
        let s = scene_with(&format!("khronos-{file}"), &khronos(file));
        assert!(s.warnings().is_empty(), "{file}: {:?}", s.warnings());
        let img = common::render(&s, Output::Srgb8).image;
        for &(x, y, c) in &points {
            let (px, py) = pixel(&s, Vec3::new(x, y, 0.5));
            let got = img.get_pixel(px as u32, py as u32).0;
            // Lambert at N . L = 1 gives the texel's linear colour; the
            // dielectric highlight (F0 0.04, roughness 1) adds < 0.01.
            for k in 0..3 {
                let (want, have) = (srgb_to_linear(c[k]), srgb_to_linear(got[k]));
                assert!(
                    (have - want).abs() < 0.02,
                    "{file}: ({x}, {y}) texel {c:?} rendered {got:?}"
                );
            }
        }
        images.push(img);
    }
    // The same file in two containers: the same image.
    assert_eq!(images[0], images[1], ".gltf and .glb differ");
}

#[test]
fn box_textured_agrees_on_every_path() {
    let base = scene_with("khronos-paths", &khronos("BoxTextured.glb"));
    let bound = gloss::image_compare::Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.005,
        max_abs: Some(6.0 / 255.0),
    };
    let ctx = common::context(common::backend());
    let mut fwd = base.clone();
    fwd.render.path = RenderPath::Forward;
    let reference = common::render_with(&ctx, &fwd, Output::Srgb8).image;
    for &path in RenderPath::ALL {
        let mut s = base.clone();
        s.render.path = path;
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        common::assert_close(&format!("box-textured-{path:?}"), &img, &reference, &bound);
    }
}
