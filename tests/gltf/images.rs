//! Rendered glTF scenes against pixels predicted on the CPU: the nested
//! cube lands where the node matrices put it, MASK's alphaCutoff splits a
//! gradient quad at the predicted column (in the image and in its
//! shadow), the base colour texel shows where its uv says, and forward and
//! every deferred path agree.

use crate::common;
use crate::files::{folder, scene_text};
use crate::reader::{NESTED_ENTRY, nested_cube};
use glam::{Mat4, Vec3, Vec4};
use gloss::geometry::{GltfBuilder, MeshData, Vertex};
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

/// The scene's view-projection and the pixel (column, row from the top)
/// of world point `p`.
pub(crate) fn pixel(s: &Scene, p: Vec3) -> (f32, f32) {
    let vp = s.camera.projection(s.aspect()) * s.camera.view();
    let c = vp * p.extend(1.0);
    let ndc = c.truncate() / c.w;
    let (w, h) = (s.render.size.0 as f32, s.render.size.1 as f32);
    ((ndc.x + 1.0) * 0.5 * w, (1.0 - ndc.y) * 0.5 * h)
}

fn lit(img: &image::RgbaImage, x: u32, y: u32) -> bool {
    let p = img.get_pixel(x, y);
    p[0] as u32 + p[1] as u32 + p[2] as u32 > 30
}

#[test]
fn the_nested_cube_covers_the_pixels_its_matrices_predict() {
    let (b, model, _) = nested_cube();
    let s = crate::files::load("nested-image", &b, NESTED_ENTRY).unwrap();
    let img = common::render(&s, Output::Srgb8).image;
    // The cube's corners through the spec's product of matrices.
    let corners: Vec<(f32, f32)> = (0..8)
        .map(|i| {
            let c = Vec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            );
            pixel(&s, (model * Vec4::from((c, 1.0))).truncate())
        })
        .collect();
    let (x0, x1) = corners
        .iter()
        .fold((f32::MAX, f32::MIN), |a, c| (a.0.min(c.0), a.1.max(c.0)));
    let (y0, y1) = corners
        .iter()
        .fold((f32::MAX, f32::MIN), |a, c| (a.0.min(c.1), a.1.max(c.1)));
    // Every lit pixel lies in the projected box, and the box's middle is lit.
    for (x, y, p) in img.enumerate_pixels() {
        if p[0] as u32 + p[1] as u32 + p[2] as u32 > 30 {
            let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
            assert!(
                fx > x0 - 1.0 && fx < x1 + 1.0 && fy > y0 - 1.0 && fy < y1 + 1.0,
                "pixel ({x}, {y}) lit outside the predicted box x {x0}..{x1}, y {y0}..{y1}"
            );
        }
    }
    let centre = pixel(&s, (model * Vec4::W).truncate());
    assert!(
        lit(&img, centre.0 as u32, centre.1 as u32),
        "the cube's centre {centre:?} is dark"
    );
    assert!(
        x1 - x0 > 20.0 && y1 - y0 > 20.0,
        "a box worth testing: {x0} {x1} {y0} {y1}"
    );
}

/// A quad facing the camera, x and y in -1..1, uv 0..1 (gloss's: v up).
pub(crate) fn quad() -> MeshData {
    let v = |x: f32, y: f32| Vertex {
        position: [x, y, 0.0],
        normal: [0.0, 0.0, 1.0],
        uv: [(x + 1.0) * 0.5, (y + 1.0) * 0.5],
        tangent: [1.0, 0.0, 0.0, 1.0],
    };
    MeshData {
        vertices: vec![v(-1.0, -1.0), v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)],
        indices: vec![0, 1, 2, 0, 2, 3],
        colors: Vec::new(),
    }
}

/// The 64 x 1 texture whose alpha rises along u: texel i has alpha
/// round(255 (i + 0.5) / 64).
fn gradient(dir: &std::path::Path) {
    let img = image::RgbaImage::from_fn(64, 1, |i, _| {
        image::Rgba([
            255,
            255,
            255,
            (255.0 * (i as f32 + 0.5) / 64.0).round() as u8,
        ])
    });
    img.save(dir.join("gradient.png")).unwrap();
}

/// The masked quad: alphaCutoff `cutoff`, nearest sampling; plus a floor
/// behind it for the shadow, when `floor`.
fn masked(cutoff: f32) -> GltfBuilder {
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&quad(), Some(0));
    b.materials.push(format!(
        r#"{{"name":"leaf","alphaMode":"MASK","alphaCutoff":{cutoff},"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}},"metallicFactor":0,"roughnessFactor":1}}}}"#
    ));
    b.textures.push(r#"{"source":0,"sampler":0}"#.into());
    b.images.push(r#"{"uri":"gradient.png"}"#.into());
    b.samplers
        .push(r#"{"magFilter":9728,"minFilter":9728,"wrapS":33071,"wrapT":33071}"#.into());
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    b
}

fn masked_scene(name: &str) -> Scene {
    let d = folder(name);
    gradient(&d);
    std::fs::write(d.join("model.gltf"), masked(0.3).gltf()).unwrap();
    std::fs::write(d.join("scene.toml"), scene_text("")).unwrap();
    Scene::load(&d.join("scene.toml")).unwrap()
}

/// The first texel that passes alpha >= cutoff, as the GPU stores alpha.
fn first_passing(cutoff: f32) -> u32 {
    (0..64)
        .find(|&i| (255.0 * (i as f32 + 0.5) / 64.0).round() / 255.0 >= cutoff)
        .unwrap()
}

#[test]
fn alpha_cutoff_splits_the_gradient_quad_at_the_predicted_column() {
    let s = masked_scene("mask");
    let i = first_passing(0.3);
    assert_eq!(i, 19);
    // Texel i starts at u = i / 64: x = -1 + 2u in the world.
    let (edge, row) = pixel(&s, Vec3::new(-1.0 + 2.0 * i as f32 / 64.0, 0.0, 0.0));
    let left = pixel(&s, Vec3::new(-1.0, 0.0, 0.0)).0;
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let mut s = s.clone();
        s.render.path = path;
        let img = common::render(&s, Output::Srgb8).image;
        let y = row as u32;
        let lit_cols: Vec<u32> = (0..img.width()).filter(|&x| lit(&img, x, y)).collect();
        let first = *lit_cols.first().expect("some of the quad is drawn");
        // Pixel centres: the first lit column is the first whose centre
        // lies past the edge.
        assert_eq!(
            first,
            (edge - 0.5).ceil() as u32,
            "{path:?}: edge at {edge}"
        );
        assert!(left < edge - 10.0, "a masked part worth seeing");
    }
}

#[test]
fn the_base_colour_texel_appears_where_its_uv_says() {
    let d = folder("texel");
    // 2 x 2: top-left red, top-right green, bottom-left blue, bottom-right white.
    let img = image::RgbaImage::from_fn(2, 2, |x, y| {
        image::Rgba(match (x, y) {
            (0, 0) => [255, 0, 0, 255],
            (1, 0) => [0, 255, 0, 255],
            (0, 1) => [0, 0, 255, 255],
            _ => [255, 255, 255, 255],
        })
    });
    img.save(d.join("quadrants.png")).unwrap();
    let mut b = GltfBuilder::default();
    let mesh = b.mesh(&quad(), Some(0));
    b.materials.push(r#"{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0,"roughnessFactor":1}}"#.into());
    b.textures.push(r#"{"source":0,"sampler":0}"#.into());
    b.images.push(r#"{"uri":"quadrants.png"}"#.into());
    b.samplers
        .push(r#"{"magFilter":9728,"minFilter":9728}"#.into());
    b.nodes.push(format!(r#"{{"mesh":{mesh}}}"#));
    std::fs::write(d.join("model.gltf"), b.gltf()).unwrap();
    std::fs::write(d.join("scene.toml"), scene_text("")).unwrap();
    let s = Scene::load(&d.join("scene.toml")).unwrap();
    let out = common::render(&s, Output::Srgb8).image;
    // glTF's uv (0, 0) is the image's top-left: the quad's top-left quarter.
    for (x, y, want) in [(-0.5, 0.5, 0), (0.5, 0.5, 1), (-0.5, -0.5, 2)] {
        let (px, py) = pixel(&s, Vec3::new(x, y, 0.0));
        let p = out.get_pixel(px as u32, py as u32);
        let strongest = (0..3).max_by_key(|&k| p[k]).unwrap();
        assert_eq!(strongest, want, "({x}, {y}) -> {p:?}");
        // The other channels hold only the white highlight (F0 = 0.04).
        assert!(
            p[want] > 200 && (0..3).all(|k| k == want || p[k] < 50),
            "{p:?}"
        );
    }
    let (px, py) = pixel(&s, Vec3::new(0.5, -0.5, 0.0));
    let p = out.get_pixel(px as u32, py as u32);
    assert!(p[0] > 100 && p[1] > 100 && p[2] > 100, "white: {p:?}");
}

#[test]
fn forward_and_every_deferred_path_agree_on_a_gltf_scene() {
    let (b, _, _) = nested_cube();
    let base = crate::files::load("paths", &b, NESTED_ENTRY).unwrap();
    let bound = Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.005,
        max_abs: Some(6.0 / 255.0),
    };
    let mut fwd = base.clone();
    fwd.render.path = RenderPath::Forward;
    let reference = common::render(&fwd, Output::Srgb8).image;
    for &path in RenderPath::ALL {
        let mut s = base.clone();
        s.render.path = path;
        let img = common::render(&s, Output::Srgb8).image;
        let m = common::assert_close(&format!("gltf-{path:?}"), &img, &reference, &bound);
        eprintln!("{path:?} vs forward: {m}");
    }
    let _ = Mat4::IDENTITY;
}

#[test]
fn every_path_agrees_with_forward_on_the_shipped_gltf_scene() {
    let base = common::scene("gltf-scene.toml");
    let bound = Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.005,
        max_abs: Some(6.0 / 255.0),
    };
    let mut fwd = base.clone();
    fwd.render.path = RenderPath::Forward;
    let ctx = common::context(common::backend());
    let reference = common::render_with(&ctx, &fwd, Output::Srgb8).image;
    for &path in RenderPath::ALL {
        let mut s = base.clone();
        s.render.path = path;
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        let m = common::assert_close(&format!("gltf-scene-{path:?}"), &img, &reference, &bound);
        eprintln!("gltf-scene {path:?} vs forward: {m}");
    }
}
