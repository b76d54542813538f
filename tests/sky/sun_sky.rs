//! The sun-sky pass (notes 03, Sun Sky; Implementation): the GPU's sky
//! equals the CPU's f64 Preetham model (src/math/preetham.rs) in every
//! pixel's direction, for suns high, low, on and below the horizon and
//! turbidities across the model's range, with views above and below the
//! horizon; drawn at z = w with GL_LEQUAL, it changes no pixel an object
//! covers, on the forward and deferred paths; the plan has the pass only
//! with a `[sky]`; bad skies are refused by key.

use crate::common;
use glam::{DVec3, Vec4};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

fn scene(sky: &str, objects: &str, path: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 1.0, 0.0]\ntarget = [3.0, 1.2, -4.0]\nfov_y = 70.0\n\
         [render]\nsize = [160, 120]\npath = \"{path}\"\nambient = [1.0, 1.0, 1.0]\n{sky}\n{objects}"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

#[test]
fn every_pixel_is_the_cpu_preetham_sky_in_its_direction() {
    let ctx = common::context(common::backend());
    let mut worst = 0.0f64;
    for (sun, turbidity) in [
        ("[0.6, 0.8, -0.5]", 2.0),
        ("[0.6, 0.15, -1.0]", 3.0),
        ("[1.0, 0.0, -0.2]", 10.0),
        ("[0.7, -0.05, -1.0]", 5.0),
    ] {
        let s = scene(
            &format!("[sky]\nsun = {sun}\nturbidity = {turbidity:.1}\nintensity = 0.5\n"),
            "",
            "forward",
        );
        let sky = s.sky.as_ref().unwrap().model();
        let r = common::render_with(&ctx, &s, Output::Linear32F);
        let (w, h) = (r.width as usize, r.height as usize);
        let inverse = (s.camera.projection(w as f32 / h as f32) * s.camera.view()).inverse();
        for y in (0..h).step_by(3) {
            for x in (0..w).step_by(3) {
                let ndc = |a: usize, n: usize| 2.0 * (a as f32 + 0.5) / n as f32 - 1.0;
                let at = |z: f32| {
                    let q = inverse * Vec4::new(ndc(x, w), ndc(y, h), z, 1.0);
                    (q.truncate() / q.w).as_dvec3()
                };
                let dir: DVec3 = (at(1.0) - at(-1.0)).normalize();
                let want = sky.radiance_rgb(dir).map(|c| 0.5 * c);
                let i = (y * w + x) * 4;
                for (c, &want) in want.iter().enumerate() {
                    let got = f64::from(r.linear[i + c]);
                    let err = (got - want).abs() / want.abs().max(0.02);
                    worst = worst.max(err);
                    assert!(
                        err < 2e-3,
                        "sun {sun}, T {turbidity}: pixel ({x}, {y}) channel {c}: {got} against {want}"
                    );
                }
            }
        }
    }
    println!("worst relative difference {worst:.2e}");
}

#[test]
fn the_sky_is_drawn_only_where_nothing_was() {
    let sky = "[sky]\nsun = [0.5, 0.5, -1.0]\n";
    let cube = "[[objects]]\nmesh = \"cube\"\nposition = [3.0, 1.2, -4.0]\n";
    for path in ["forward", "deferred"] {
        let with = common::render(&scene(sky, cube, path), Output::Srgb8).image;
        let without = common::render(&scene("", cube, path), Output::Srgb8).image;
        let bare = common::render(&scene("", "", path), Output::Srgb8).image;
        let (mut object, mut background) = (0, 0);
        for (x, y, p) in without.enumerate_pixels() {
            if p == bare.get_pixel(x, y) {
                // Background: the sky replaced it.
                background += 1;
                assert_ne!(with.get_pixel(x, y), p, "{path}: ({x}, {y}) has no sky");
            } else {
                object += 1;
                assert_eq!(
                    with.get_pixel(x, y),
                    p,
                    "{path}: the sky drew over the cube at ({x}, {y})"
                );
            }
        }
        assert!(
            object > 500 && background > 5000,
            "{path}: {object} {background}"
        );
    }
}

#[test]
fn the_plan_draws_the_sky_only_for_a_scene_with_one() {
    let names = |s: &Scene| -> Vec<&'static str> {
        gloss::techniques::plan(s)
            .passes
            .iter()
            .map(|p| p.name)
            .collect()
    };
    let mut s = scene("[sky]\nsun = [0.0, 1.0, 0.0]\n", "", "forward");
    assert!(names(&s).contains(&"sun-sky"));
    s.render.path = RenderPath::Tiled;
    assert!(names(&s).contains(&"sun-sky"));
    assert!(!names(&scene("", "", "forward")).contains(&"sun-sky"));
}

#[test]
fn bad_skies_are_refused_by_key() {
    let bad = |sky: &str| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 1.0, 0.0]\ntarget = [0.0, 1.0, -1.0]\n{sky}"
        );
        Scene::parse(&text, &common::root().join("scenes/t.toml"))
            .expect_err(sky)
            .to_string()
    };
    let e = bad("[sky]\nsun = [0.0, 1.0, 0.0]\nturbidity = 1.5\n");
    assert!(e.contains("sky.turbidity") && e.contains("2..=10"), "{e}");
    let e = bad("[sky]\nsun = [0.0, 0.0, 0.0]\n");
    assert!(e.contains("sky.sun"), "{e}");
    let e = bad("[sky]\nsun = [0.0, 1.0, 0.0]\nintensity = -1.0\n");
    assert!(e.contains("sky.intensity"), "{e}");
    let e = bad("[sky]\nturbidity = 3.0\n");
    assert!(e.contains("sun"), "{e}");
    for disc in ["-0.1", "2.5", "nan"] {
        let e = bad(&format!(
            "[sky]\nsun = [0.0, 1.0, 0.0]\nsun_disc = {disc}\n"
        ));
        assert!(e.contains("sky.sun_disc") && e.contains("0..=2"), "{e}");
    }
}
