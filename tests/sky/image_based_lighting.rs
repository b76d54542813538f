//! Image-based lighting (render.ibl; Karis 2013, "Real Shading in Unreal
//! Engine 4"; src/techniques/sky/image_based_lighting.rs): each of the
//! GPU's three maps against a Monte Carlo integral (or quadrature) on the
//! CPU of the environment the GPU rendered, read back; the white furnace
//! on the forward and deferred paths; the split sum's error against the
//! whole specular integral at sphere pixels; the sun at the horizon.

use crate::common;
use crate::environment_reflection::pixel_ray;
use glam::DVec3;
use gloss::gl::cube_map::CubeMap;
use gloss::gl::program::Sources;
use gloss::lighting::image_based_lighting as ibl;
use gloss::lighting::microfacet;
use gloss::math::cube_map::CubeImage;
use gloss::renderer::{Output, Renderer, render_scene};
use gloss::scene::Scene;

/// A sphere under the sky, image-based lighting on.
fn sky_scene(path: &str, sun: [f32; 3], sun_disc: f32, material: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\nfov_y = 50.0\n\
         [render]\nsize = [160, 160]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\nibl = true\n\
         [sky]\nsun = {sun:?}\nturbidity = 3.0\nintensity = 0.5\nsun_disc = {sun_disc}\n[skybox]\nsize = 64\n\
         [materials.m]\n{material}\n[[objects]]\nmesh = \"sphere\"\nmaterial = \"m\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

const RED_DIELECTRIC: &str =
    "diffuse = [0.5, 0.2, 0.1]\nmodel = \"microfacet\"\nalpha = 0.3\neta = 1.5\nk_s = 1.0";

/// Level `level` of a cube map, read back.
fn level_image(c: &CubeMap, level: u32) -> CubeImage {
    let size = (c.size >> level).max(1) as usize;
    let faces = std::array::from_fn(|f| {
        let v = c.read_face_f32(f as u32, level);
        v.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
    });
    CubeImage { size, faces }
}

fn rgb(c: [f64; 4]) -> DVec3 {
    DVec3::new(c[0], c[1], c[2])
}

fn normals() -> Vec<DVec3> {
    [
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.6, 0.35, -1.0],
        [-0.3, 0.1, 0.9],
        [0.2, -0.4, -0.5],
        [1.0, 1.0, 1.0],
    ]
    .iter()
    .map(|&v| DVec3::from(v).normalize())
    .collect()
}

/// The worst |got - want| / max(want) over the normals, printed.
fn relative(got: DVec3, want: DVec3) -> f64 {
    (got - want).abs().max_element() / want.max_element().max(1e-6)
}

#[test]
fn the_irradiance_map_matches_a_monte_carlo_integral_at_several_normals() {
    let ctx = common::context(common::backend());
    let scene = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, RED_DIELECTRIC);
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let env = r.draws().environment.cube.as_ref().unwrap().read_image();
    let maps = r
        .draws()
        .environment
        .ibl
        .as_ref()
        .expect("render.ibl makes the maps");
    let irradiance = level_image(&maps.irradiance, 0);
    let lookup = ibl::cube_environment(&env);
    let mut worst: f64 = 0.0;
    for n in normals() {
        let got = rgb(irradiance.sample(n, true));
        let want = ibl::irradiance_mc(&lookup, n, 400_000, 11);
        let err = relative(got, want);
        println!("n {n:.2}: GPU {got:.4}, Monte Carlo {want:.4}, relative {err:.2e}");
        worst = worst.max(err);
        assert!(
            err < 0.02,
            "irradiance at {n}: GPU {got} against Monte Carlo {want}"
        );
    }
    println!("irradiance: worst relative difference from Monte Carlo {worst:.2e}");
}

#[test]
fn the_prefiltered_levels_match_a_monte_carlo_integral_at_several_roughnesses() {
    let ctx = common::context(common::backend());
    let scene = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, RED_DIELECTRIC);
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let env = r.draws().environment.cube.as_ref().unwrap().read_image();
    let maps = r.draws().environment.ibl.as_ref().unwrap();
    let lookup = ibl::cube_environment(&env);
    for level in 1..maps.levels() {
        let alpha = ibl::level_alpha(level);
        let image = level_image(&maps.prefiltered, level as u32);
        let mut worst: f64 = 0.0;
        for r in normals() {
            let got = rgb(image.sample(r, true));
            let want = ibl::prefiltered_mc(&lookup, r, alpha, 200_000, 5);
            worst = worst.max(relative(got, want));
        }
        println!(
            "level {level} (alpha {alpha:.2}): worst relative difference from Monte Carlo {worst:.2e}"
        );
        assert!(worst < 0.08, "prefiltered level {level}: {worst}");
    }
}

#[test]
fn the_split_sum_table_matches_the_quadrature_of_gloss_brdf() {
    let ctx = common::context(common::backend());
    let scene = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, RED_DIELECTRIC);
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let maps = r.draws().environment.ibl.as_ref().unwrap();
    let (w, h, texels) = maps.brdf.read_level_f32(0);
    // Grazing (N.V < 0.15) the GGX samples are fewest where the lobe
    // is cut by the horizon: a looser bound there.
    let (mut worst, mut worst_grazing): (f64, f64) = (0.0, 0.0);
    for j in (0..h as usize).step_by(3) {
        for i in (0..w as usize).step_by(3) {
            let nv = (i as f64 + 0.5) / f64::from(w);
            let roughness = (j as f64 + 0.5) / f64::from(h);
            let (a, b) = ibl::brdf_table_reference(nv, roughness * roughness);
            let t = (j * w as usize + i) * 4;
            let (ga, gb) = (f64::from(texels[t]), f64::from(texels[t + 1]));
            let err = (ga - a).abs().max((gb - b).abs());
            let bound = if nv < 0.15 { 0.1 } else { 0.01 };
            if nv < 0.15 {
                worst_grazing = worst_grazing.max(err);
            } else {
                worst = worst.max(err);
            }
            assert!(
                err < bound,
                "N.V {nv:.3}, alpha {:.3}: table ({ga}, {gb}) against ({a}, {b})",
                roughness * roughness
            );
        }
    }
    println!(
        "split-sum table: worst |GPU - quadrature| {worst:.2e} (N.V >= 0.15), {worst_grazing:.2e} (grazing)"
    );
}

/// Six white PNG faces in the test's output folder.
fn white_faces() -> Vec<String> {
    let dir = common::out_dir().join("ibl-white");
    std::fs::create_dir_all(&dir).unwrap();
    let img = image::RgbaImage::from_pixel(8, 8, image::Rgba([255, 255, 255, 255]));
    (0..6)
        .map(|i| {
            let p = dir.join(format!("white{i}.png"));
            img.save(&p).unwrap();
            format!("{:?}", p.display().to_string())
        })
        .collect()
}

/// A sphere in a uniform white environment (radiance 1).
fn furnace(path: &str, material: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\nfov_y = 50.0\n\
         [render]\nsize = [120, 120]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\nibl = true\n\
         [skybox]\nfaces = [{}]\n[materials.m]\n{material}\n[[objects]]\nmesh = \"sphere\"\nmaterial = \"m\"\n",
        white_faces().join(", ")
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// The sphere's pixels off its silhouette: (index, N, V).
fn sphere_pixels(scene: &Scene) -> Vec<(usize, DVec3, DVec3)> {
    let (w, h) = (scene.render.size.0 as usize, scene.render.size.1 as usize);
    let mut out = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let (e, d) = pixel_ray(scene, x, y);
            let b = e.dot(d);
            let disc = b * b - (e.length_squared() - 1.0);
            if disc <= 0.0 {
                continue;
            }
            let n = e + (-b - disc.sqrt()) * d;
            if -d.dot(n) > 0.3 {
                out.push(((y * w + x) * 4, n, -d));
            }
        }
    }
    out
}

#[test]
fn white_furnace_a_white_lambertian_sphere_gives_its_albedo_on_every_path() {
    let ctx = common::context(common::backend());
    let material =
        "diffuse = [1.0, 1.0, 1.0]\nmodel = \"microfacet\"\nalpha = 0.5\neta = 1.5\nk_s = 0.0";
    for path in ["forward", "deferred", "prepass"] {
        let scene = furnace(path, material);
        let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
        let got = r.read_linear();
        let pixels = sphere_pixels(&scene);
        assert!(pixels.len() > 3000, "{path}: {} pixels", pixels.len());
        let mut worst: f32 = 0.0;
        for &(i, _, _) in &pixels {
            for c in 0..3 {
                worst = worst.max((got[i + c] - 1.0).abs());
            }
        }
        println!("{path}: white furnace, k_d = 1: worst |pixel - 1| {worst:.2e}");
        assert!(
            worst < 2e-3,
            "{path}: a white Lambertian sphere in a white furnace is off by {worst}"
        );
    }
}

#[test]
fn white_furnace_the_specular_term_is_the_directional_albedo_of_gloss_brdf() {
    // k_d = 0, k_s = 1: the pixel is F0 A + B (the prefiltered map of a
    // uniform environment is 1), against gloss's exact albedo (exact
    // Fresnel) by quadrature. The split sum adds nothing in a furnace: the
    // difference is Schlick's Fresnel against the exact one, and the table's
    // sampling; the energy below 1 is the single-scattering microfacet loss,
    // which gloss's BRDF has too.
    let ctx = common::context(common::backend());
    for (alpha, eta) in [
        (0.05, 1.5),
        (0.3, 1.5),
        (1.0, 1.5),
        (0.3, 10.0),
        (1.0, 10.0),
    ] {
        let material = format!(
            "diffuse = [0.0, 0.0, 0.0]\nmodel = \"microfacet\"\nalpha = {alpha}\neta = {eta}\nk_s = 1.0"
        );
        let scene = furnace("forward", &material);
        let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
        let got = r.read_linear();
        let (mut table, mut schlick, mut most): (f64, f64, f64) = (0.0, 0.0, 0.0);
        for (i, n, v) in sphere_pixels(&scene).into_iter().step_by(37) {
            let nv = n.dot(v);
            let local = DVec3::new((1.0 - nv * nv).max(0.0).sqrt(), 0.0, nv);
            // The albedo with Schlick's Fresnel (what the table holds) and the exact one.
            let with_schlick = microfacet::albedo_with(local, alpha, 1.0, 128, |c| {
                microfacet::fresnel_schlick(c, eta)
            });
            let exact = microfacet::directional_albedo(local, alpha, eta, 1.0, 128);
            let pixel = f64::from(got[i]);
            assert!(
                pixel <= 1.0 + 2e-3,
                "alpha {alpha}, eta {eta}: gains energy: {pixel}"
            );
            table = table.max((pixel - with_schlick).abs());
            schlick = schlick.max((pixel - exact).abs());
            most = most.max(pixel);
        }
        println!(
            "white furnace specular, alpha {alpha}, eta {eta}: worst |pixel - albedo (Schlick)| {table:.3e}, |pixel - albedo (exact Fresnel)| {schlick:.3e}, brightest {most:.3}"
        );
        assert!(
            table < 0.01,
            "alpha {alpha}, eta {eta}: the table is off by {table}"
        );
        assert!(
            schlick < 0.08,
            "alpha {alpha}, eta {eta}: Schlick's Fresnel costs {schlick}"
        );
    }
}

#[test]
fn the_split_sum_error_against_the_whole_specular_integral() {
    // k_d = 0 spheres under the sky: each pixel against the Monte Carlo
    // integral of the environment times gloss's exact f_s.
    let ctx = common::context(common::backend());
    for alpha in [0.1, 0.3, 0.6, 1.0] {
        let material = format!(
            "diffuse = [0.0, 0.0, 0.0]\nmodel = \"microfacet\"\nalpha = {alpha}\neta = 1.5\nk_s = 1.0"
        );
        let scene = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, &material);
        let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
        let env = r.draws().environment.cube.as_ref().unwrap().read_image();
        let lookup = ibl::cube_environment(&env);
        let got = r.read_linear();
        let pixels = sphere_pixels(&scene);
        // Facing the eye (N.V > 0.8) and towards the silhouette.
        let (mut sum, mut worst, mut k) = ([0.0; 2], [0.0f64; 2], [0; 2]);
        for &(i, n, v) in pixels.iter().step_by(151) {
            let want = ibl::full_ibl(&lookup, (n, v), (alpha, 1.5, 1.0), 20_000, i as u64);
            let pixel = DVec3::new(got[i].into(), got[i + 1].into(), got[i + 2].into());
            let err = relative(pixel, want);
            let band = usize::from(n.dot(v) <= 0.8);
            sum[band] += err;
            worst[band] = worst[band].max(err);
            k[band] += 1;
        }
        for (band, name) in ["N.V > 0.8", "N.V 0.3..0.8"].iter().enumerate() {
            println!(
                "split sum, alpha {alpha}, {name}: {} pixels, mean relative error {:.3}, worst {:.3}",
                k[band],
                sum[band] / f64::from(k[band]),
                worst[band]
            );
        }
        assert!(
            worst[0] < 0.15,
            "alpha {alpha}: the split sum is off by {} facing the eye",
            worst[0]
        );
        assert!(
            worst[1] < 0.35,
            "alpha {alpha}: the split sum is off by {} obliquely",
            worst[1]
        );
    }
}

#[test]
fn a_sun_at_the_horizon_gives_finite_non_negative_continuous_irradiance() {
    let ctx = common::context(common::backend());
    // With the sun's disc: every texel of every map finite and >= 0.
    let scene = sky_scene("forward", [1.0, 0.0, 0.0], 2.0, RED_DIELECTRIC);
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let maps = r.draws().environment.ibl.as_ref().unwrap();
    let mut all: Vec<f32> = Vec::new();
    for f in 0..6 {
        all.extend(maps.irradiance.read_face_f32(f, 0));
        for level in 0..maps.levels() as u32 {
            all.extend(maps.prefiltered.read_face_f32(f, level));
        }
    }
    all.extend(maps.brdf.read_level_f32(0).2);
    let bad = all.iter().filter(|v| !v.is_finite() || **v < 0.0).count();
    assert_eq!(bad, 0, "{bad} texels NaN, infinite or negative");
    let image = r.read_linear();
    assert!(
        image.iter().all(|v| v.is_finite() && *v >= 0.0),
        "a pixel is NaN or negative"
    );
    // Continuous: along the great circle through the sun and the zenith,
    // one degree apart, no step larger than a few per cent of the brightest.
    let irradiance = level_image(&maps.irradiance, 0);
    let along: Vec<DVec3> = (-180..=180)
        .map(|deg| {
            let t = f64::from(deg).to_radians();
            rgb(irradiance.sample(DVec3::new(t.cos(), t.sin(), 0.0), true))
        })
        .collect();
    let top = along.iter().map(|c| c.max_element()).fold(0.0, f64::max);
    let step = along
        .windows(2)
        .map(|w| (w[1] - w[0]).abs().max_element())
        .fold(0.0, f64::max);
    println!("horizon sun: brightest irradiance {top:.4}, largest 1-degree step {step:.2e}");
    assert!(
        step < 0.03 * top,
        "irradiance jumps by {step} (brightest {top})"
    );
    // And without the disc it matches Monte Carlo at the normals.
    let scene = sky_scene("forward", [1.0, 0.0, 0.0], 0.0, RED_DIELECTRIC);
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let env = r.draws().environment.cube.as_ref().unwrap().read_image();
    let lookup = ibl::cube_environment(&env);
    let irradiance = level_image(&r.draws().environment.ibl.as_ref().unwrap().irradiance, 0);
    for n in normals()
        .into_iter()
        .chain([DVec3::X, DVec3::new(1.0, -0.05, 0.0).normalize()])
    {
        let got = rgb(irradiance.sample(n, true));
        let want = ibl::irradiance_mc(&lookup, n, 400_000, 3);
        assert!(
            relative(got, want) < 0.02,
            "horizon sun, n {n}: GPU {got} against Monte Carlo {want}"
        );
    }
}

#[test]
fn the_maps_are_planned_only_when_the_scene_asks() {
    let on = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, RED_DIELECTRIC);
    let mut off = on.clone();
    off.render.ibl = false;
    let count = |s: &Scene| {
        let lights = gloss::frame::lights::FrameLights::new(s);
        let plan = gloss::frame::plan::FramePlan::new(s, &lights, gloss::techniques::ALL);
        plan.passes
            .iter()
            .filter(|p| p.code.ends_with("image_based_lighting.rs"))
            .count()
    };
    assert_eq!(count(&on), 3);
    assert_eq!(count(&off), 0);
}

#[test]
fn switching_render_ibl_live_gives_the_image_of_the_scene_loaded_with_it() {
    // The demo's switch: the renderer makes the sky's cube map and the
    // maps when render.ibl comes on, and drops them when it goes off.
    let ctx = common::context(common::backend());
    let on = sky_scene("forward", [0.6, 0.35, -1.0], 0.0, RED_DIELECTRIC);
    let mut off = on.clone();
    off.render.ibl = false;
    let (w, h) = on.render.size;
    let mut live = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &off,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Srgb8,
    )
    .unwrap();
    live.render(&off.camera).unwrap();
    let before = live.read_image();
    live.set_render_settings(on.render.clone()).unwrap();
    live.render(&on.camera).unwrap();
    let after = live.read_image();
    let fresh = render_scene(&ctx, &on, Output::Srgb8).unwrap().read_image();
    assert!(
        after.as_raw() == fresh.as_raw(),
        "switched on live != loaded with render.ibl"
    );
    assert!(
        before.as_raw() != after.as_raw(),
        "render.ibl changed nothing"
    );
    live.set_render_settings(off.render.clone()).unwrap();
    live.render(&off.camera).unwrap();
    assert!(
        live.read_image().as_raw() == before.as_raw(),
        "switched off != never on"
    );
    assert!(
        live.draws().environment.ibl.is_none(),
        "the maps outlive the switch"
    );
}
