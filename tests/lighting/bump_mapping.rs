//! Notes 01 §8.4, bump mapping (glsl/common/bump_mapping.glsl,
//! src/geometry/tangents.rs): a flat normal map changes nothing; a normal
//! map baked on the CPU from a known height field lights a plane as the
//! height field's analytic normals do, with the texture mirrored too (the
//! handedness); meshes with no usable uvs give finite tangents and no NaN
//! pixel; forward and deferred agree.

use crate::common;
use glam::DVec3;
use gloss::image_compare::Tolerance;
use gloss::math::bump::{bake_normal_map, tangent_normal};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::f64::consts::TAU;
use std::path::PathBuf;

fn write_png(name: &str, w: u32, h: u32, texels: &[[u8; 3]]) -> PathBuf {
    let p = common::out_dir().join(name);
    image::RgbImage::from_fn(w, h, |x, y| image::Rgb(texels[(y * w + x) as usize]))
        .save(&p)
        .expect("write the normal map");
    p
}

/// The height field the test bakes, in uv units: ridges along u and v.
fn height(u: f64, v: f64) -> f64 {
    0.012 * (TAU * 2.0 * u).sin() + 0.008 * (TAU * 3.0 * v).sin()
}
fn slopes(u: f64, v: f64) -> (f64, f64) {
    (
        0.012 * TAU * 2.0 * (TAU * 2.0 * u).cos(),
        0.008 * TAU * 3.0 * (TAU * 3.0 * v).cos(),
    )
}

/// A 2 x 2 plane facing up seen from above by an orthographic camera that
/// fits it to the 256 x 256 image (u = (x + 0.5) / 256 along +x, v up the
/// image), lit by one white directional light only: each pixel is
/// max(0, N . L).
fn lit_plane(normal_map: &str, uv_scale_u: f64, path: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = [0.0, 5.0, 0.0]\n\
         target = [0.0, 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\nhalf_height = 1.0\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [256, 256]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\n\
         [[lights]]\ntype = \"directional\"\ndirection = [-0.5, -0.6, 0.4]\ncolor = [1.0, 1.0, 1.0]\n\
         [materials.m]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [0.0, 0.0, 0.0]\n{normal_map}\n\
         uv_scale = [{uv_scale_u:.1}, 1.0]\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

#[test]
fn a_baked_height_field_lights_the_plane_as_its_analytic_normals_do() {
    let (w, h) = (256, 256);
    let png = write_png(
        "bump-height-field.png",
        w,
        h,
        &bake_normal_map(w, h, height),
    );
    let map = format!("normal_map = \"{}\"", png.display());
    let ctx = common::context(common::backend());
    let l = -DVec3::new(-0.5, -0.6, 0.4).normalize();
    for (scale, path) in [
        (1.0, "forward"),
        (-1.0, "forward"),
        (1.0, "deferred"),
        (-1.0, "deferred"),
    ] {
        let r = common::render_with(&ctx, &lit_plane(&map, scale, path), Output::Linear32F);
        let mut worst = (0.0f64, 0, 0);
        for y in (2..254).step_by(5) {
            for x in (2..254).step_by(5) {
                // Pixel (x, y from the bottom) sees mesh uv ((x + 0.5) / 256, (y + 0.5) / 256);
                // the texture is read at u' = scale u.
                let (u, v) = ((x as f64 + 0.5) / 256.0, (y as f64 + 0.5) / 256.0);
                // The surface the texture describes: heights h(scale u, v),
                // so its slope along the mesh's u is scale h_u.
                let (hu, hv) = slopes(scale * u, v);
                let n = tangent_normal(scale * hu, hv);
                // Tangent space on this plane: T = +x, B = +v = -z, N = +y.
                let world = DVec3::new(n.x, n.z, -n.y);
                let want = world.dot(l).max(0.0);
                let got = f64::from(r.linear[((y * 256 + x) * 4) as usize]);
                let err = (got - want).abs();
                if err > worst.0 {
                    worst = (err, x, y);
                }
            }
        }
        // 8-bit normals are within 1/255 a component (about 0.006 in N . L),
        // and bilinear filtering between texels adds less than that.
        assert!(
            worst.0 < 0.012,
            "{path}, uv scale {scale}: N . L off by {:.4} at ({}, {})",
            worst.0,
            worst.1,
            worst.2
        );
    }
    // And the height field is not flat: without the map the same pixels differ.
    let flat = common::render_with(&ctx, &lit_plane("", 1.0, "forward"), Output::Linear32F);
    let bumped = common::render_with(&ctx, &lit_plane(&map, 1.0, "forward"), Output::Linear32F);
    let differ = (0..256 * 256)
        .filter(|i| (flat.linear[i * 4] - bumped.linear[i * 4]).abs() > 0.05)
        .count();
    assert!(differ > 10_000, "only {differ} pixels changed");
}

#[test]
fn a_flat_normal_map_changes_nothing() {
    let flat = write_png("bump-flat.png", 4, 4, &[[128, 128, 255]; 16]);
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let mut with = common::scene("bump-mapping.toml");
        with.render.size = (480, 270);
        with.render.path = path;
        let mut without = with.clone();
        for m in &mut with.materials {
            if m.normal_map.is_some() {
                m.normal_map = Some(flat.clone());
            }
        }
        for m in &mut without.materials {
            m.normal_map = None;
        }
        let a = common::render(&with, Output::Srgb8).image;
        let b = common::render(&without, Output::Srgb8).image;
        // 128 / 255 is 0.502, not 0.5: the flat texel leans 0.2 degrees,
        // which moves a highlight's edge by a step or two here and there.
        common::assert_close(
            &format!("bump-flat-{path}"),
            &a,
            &b,
            &Tolerance {
                threshold: 2.0 / 255.0,
                max_frac_over: 0.001,
                max_abs: Some(4.0 / 255.0),
            },
        );
    }
}

#[test]
fn every_deferred_path_bumps_as_forward_does() {
    let mut s = common::scene("bump-mapping.toml");
    s.render.size = (480, 270);
    let forward = common::render(&s, Output::Srgb8).image;
    // The G-buffer holds the bumped normal (RGBA16F), which every deferred
    // path lights: a few pixels round differently.
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Tiled,
        RenderPath::Prepass,
    ] {
        s.render.path = path;
        let deferred = common::render(&s, Output::Srgb8).image;
        common::assert_close(
            &format!("bump-forward-{path}"),
            &deferred,
            &forward,
            &Tolerance {
                threshold: 2.0 / 255.0,
                max_frac_over: 0.002,
                max_abs: Some(6.0 / 255.0),
            },
        );
    }
}

#[test]
fn meshes_without_usable_uvs_bump_to_finite_pixels() {
    // No vt at all, and every vt equal: no direction of increasing u.
    let objs = [
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 3 2\nf 1 4 3\n",
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nvt 0.3 0.3\nf 1/1 3/1 2/1\nf 1/1 4/1 3/1\n",
    ];
    for (k, obj) in objs.iter().enumerate() {
        let p = common::out_dir().join(format!("bump-degenerate-{k}.obj"));
        std::fs::write(&p, obj).unwrap();
        for path in ["forward", "deferred"] {
            let text = format!(
                "name = \"t\"\n[camera]\neye = [0.0, 3.0, 2.0]\ntarget = [0.0, 0.0, 0.0]\n\
                 [render]\nsize = [64, 64]\npath = \"{path}\"\n\
                 [[lights]]\ntype = \"point\"\nposition = [0.0, 2.0, 0.0]\n\
                 [materials.m]\nnormal_map = \"assets/bricks-normal.png\"\n\
                 [[objects]]\nmesh = \"{}\"\nmaterial = \"m\"\n",
                p.display()
            );
            let s = Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap();
            let r = common::render(&s, Output::Linear32F);
            assert!(
                r.linear.iter().all(|c| c.is_finite()),
                "{path}, mesh {k}: NaN pixels"
            );
            let lit = (r.linear.chunks(4)).filter(|p| p[0] > 0.05).count();
            assert!(lit > 500, "{path}, mesh {k}: only {lit} lit pixels");
        }
    }
}
