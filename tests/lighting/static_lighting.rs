//! Notes 01 §8.2, static lighting (src/lighting/static_lighting.rs): every
//! baked texel holds the Phong diffuse light at its surface point (found
//! here from the plane's analytic uv layout, independently of the bake's
//! rasterisation in uv space), shadow rays darken exactly the texels whose
//! point the occluder hides, and a light-mapped plane draws the image the
//! per-frame light loop draws.

use crate::common;
use glam::Vec3;
use gloss::image_compare::Tolerance;
use gloss::lighting::phong_light;
use gloss::lighting::shadow_reference::{LightRay, SceneTriangles};
use gloss::lighting::static_lighting::bake;
use gloss::renderer::Output;
use gloss::scene::Scene;
use gloss::scene::meshes::mesh_data;

fn scene(extra: &str, light_map: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 6.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\nsize = [320, 180]\nambient = [0.05, 0.05, 0.05]\n\
         [[lights]]\ntype = \"point\"\nposition = [1.0, 2.0, -0.5]\nintensity = 2.0\n\
         [[lights]]\ntype = \"spot\"\nposition = [-2.0, 3.0, 1.0]\ndirection = [0.5, -1.0, 0.0]\n\
         color = [0.4, 0.6, 1.0]\ninner_angle = 20.0\nouter_angle = 35.0\n\
         [materials.floor]\ndiffuse = [0.8, 0.8, 0.8]\nspecular = [0.0, 0.0, 0.0]\n\
         [[objects]]\nname = \"floor\"\nmesh = \"plane\"\nmaterial = \"floor\"\n\
         position = [0.3, 0.0, -0.2]\nscale = [4.0, 1.0, 3.0]\n{light_map}\n{extra}"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

const BOX: &str =
    "[[objects]]\nmesh = \"cube\"\nposition = [0.6, 1.0, -0.3]\nscale = [0.3, 0.3, 0.3]\n";

/// The plane's surface point at texel (x, y) of an n x n map: u = (x + 1/2)
/// / n along +x, v = (y + 1/2) / n along -z (src/geometry/shapes.rs `plane`).
fn texel_point(s: &Scene, x: u32, y: u32, n: u32) -> Vec3 {
    let (u, v) = ((x as f32 + 0.5) / n as f32, (y as f32 + 0.5) / n as f32);
    s.objects[0]
        .model
        .transform_point3(Vec3::new(2.0 * u - 1.0, 0.0, 1.0 - 2.0 * v))
}

#[test]
fn every_texel_holds_the_phong_diffuse_light_at_its_point() {
    let s = scene("", "");
    let mesh = mesh_data(&s.objects[0].mesh).unwrap();
    let n = 48;
    let map = bake(&s, 0, &mesh, n, None);
    assert_eq!(map.overlaps, 0);
    for y in 0..n {
        for x in 0..n {
            let p = texel_point(&s, x, y, n);
            let want: Vec3 = (s.lights.iter())
                .map(|l| phong_light(l, p, Vec3::Y, Vec3::Y, 1.0).0)
                .sum();
            let got = Vec3::from(map.texels[(y * n + x) as usize]);
            assert!(
                (got - want).abs().max_element() <= 1e-5 * want.max_element().max(1.0),
                "texel ({x}, {y}) at {p}: {got} against {want}"
            );
        }
    }
}

#[test]
fn shadow_rays_darken_the_texels_the_box_hides() {
    let s = scene(BOX, "");
    let mesh = mesh_data(&s.objects[0].mesh).unwrap();
    let occluders = SceneTriangles::new(&s).unwrap();
    let n = 64;
    let lit = bake(&s, 0, &mesh, n, None);
    let shadowed = bake(&s, 0, &mesh, n, Some(&occluders));
    let mut hidden = 0;
    for y in 0..n {
        for x in 0..n {
            let p = texel_point(&s, x, y, n);
            let want: Vec3 = (s.lights.iter())
                .filter(|l| !occluders.occluded(p, LightRay::of(l)))
                .map(|l| phong_light(l, p, Vec3::Y, Vec3::Y, 1.0).0)
                .sum();
            let i = (y * n + x) as usize;
            let got = Vec3::from(shadowed.texels[i]);
            assert!((got - want).abs().max_element() <= 1e-5, "texel ({x}, {y})");
            if Vec3::from(lit.texels[i]).max_element() - got.max_element() > 0.05 {
                hidden += 1;
            }
        }
    }
    assert!(hidden > 40, "the box's shadow covers only {hidden} texels");
}

#[test]
fn a_light_mapped_floor_draws_what_the_light_loop_draws() {
    let map = "light_map = { size = 512 }";
    let baked = common::render(&scene("", map), Output::Srgb8).image;
    let per_frame = common::render(&scene("", ""), Output::Srgb8).image;
    // Bilinear filtering of a 512-texel map of a smooth light: within 2/255
    // but at the sharp spot-light edge.
    common::assert_close(
        "static-lighting-floor",
        &baked,
        &per_frame,
        &Tolerance {
            threshold: 2.0 / 255.0,
            max_frac_over: 0.005,
            max_abs: Some(12.0 / 255.0),
        },
    );
    // And the knob turns it off: the light loop again, exactly.
    let mut off = scene("", map);
    off.render.light_maps = false;
    let off = common::render(&off, Output::Srgb8).image;
    assert_eq!(off, per_frame);
}

#[test]
fn light_map_keys_are_checked() {
    let bad = |light_map: &str| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
             [[objects]]\nmesh = \"plane\"\n{light_map}\n"
        );
        Scene::parse(&text, &common::root().join("scenes/t.toml"))
            .expect_err(light_map)
            .to_string()
    };
    let e = bad("light_map = { size = 0 }");
    assert!(
        e.contains("objects[0].light_map.size") && e.contains("1..=2048"),
        "{e}"
    );
    let e = bad("light_map = { size = 64, blur = 2 }");
    assert!(e.contains("blur"), "{e}");
    let e = bad("light_map = { size = 9000 }");
    assert!(e.contains("found 9000"), "{e}");
}
