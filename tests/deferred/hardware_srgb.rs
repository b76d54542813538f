//! The composite's sRGB encoding by the hardware (`render.hardware_srgb`,
//! src/frame/plan.rs `hardware_srgb`; techniques/deferred/composite.rs):
//!
//! * GL's encoding into the SRGB8_ALPHA8 output against the exact formula
//!   (IEC 61966-2-1, src/lighting srgb_encode) rounded to 8 bits, over a
//!   sweep of linear values drawn as the composite's background: never more
//!   than one step off, and how many are off is printed;
//! * every G-buffer path's image with it within 1/255 of the shader's pow();
//! * where the output cannot be sRGB (a post chain follows, the RGBA32F
//!   output, the switch off), the output stays RGBA8 and the shader encodes.

use crate::common;
use glam::Vec3;
use gloss::frame::lights::FrameLights;
use gloss::frame::plan::FramePlan;
use gloss::gl::program::Sources;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::lighting::srgb_encode;
use gloss::renderer::{Output, Renderer};
use gloss::scene::{RenderPath, Scene};

/// A scene whose only object is behind the camera: every pixel is the
/// composite's background.
fn empty(path: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\nsize = [4, 4]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\n\
         [materials.m]\n[[objects]]\nmesh = \"cube\"\nmaterial = \"m\"\nposition = [0.0, 0.0, 20.0]\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

#[test]
fn gl_encodes_within_one_step_of_the_formula() {
    let ctx = common::context(common::backend());
    let mut scene = empty("deferred");
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &scene,
        &Sources::Embedded,
        4,
        4,
        Output::Srgb8,
    )
    .unwrap();
    let output = FramePlan::new(&scene, &FrameLights::new(&scene), gloss::techniques::ALL);
    let format = output.targets.iter().find(|t| t.name == "output").unwrap();
    assert_eq!(format.colors[0].1, glow::SRGB8_ALPHA8);
    // 1536 linear values: 1024 over [0, 1] and 512 over the linear toe.
    let values: Vec<f32> = (0..1024)
        .map(|i| i as f32 / 1023.0)
        .chain((0..512).map(|i| i as f32 / 511.0 * 0.01))
        .collect();
    let (mut off, mut worst) = (0, 0i32);
    for rgb in values.chunks(3) {
        let c = Vec3::new(rgb[0], rgb[1], rgb[2]);
        scene.render.background = c;
        r.set_scene_values(&scene).unwrap();
        r.render(&scene.camera).unwrap();
        let px = r.read_image().get_pixel(1, 1).0;
        for (k, v) in c.to_array().into_iter().enumerate() {
            let want = (srgb_encode(v) * 255.0).round() as i32;
            let d = (i32::from(px[k]) - want).abs();
            worst = worst.max(d);
            off += i32::from(d > 0);
        }
    }
    eprintln!(
        "GL_FRAMEBUFFER_SRGB vs the formula: {off} of {} channels one step off, worst {worst}",
        values.len()
    );
    assert!(worst <= 1, "worst {worst} steps");
}

#[test]
fn every_gbuffer_path_is_within_one_step_of_the_shaders_encoding() {
    let ctx = common::context(common::backend());
    let one = Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.0,
        max_abs: Some(1.0 / 255.0),
    };
    for name in ["deferred-shading", "mixed-lights"] {
        let scene = common::scene(&format!("{name}.toml"));
        for path in [RenderPath::Deferred, RenderPath::Volumes, RenderPath::Tiled] {
            let mut s = crate::with_path(&scene, path);
            s.render.size = (320, 180);
            let hardware = common::render_with(&ctx, &s, Output::Srgb8).image;
            s.render.hardware_srgb = false;
            let shader = common::render_with(&ctx, &s, Output::Srgb8).image;
            let m = compare_rgba8(&hardware, &shader, 1.0 / 255.0).unwrap();
            eprintln!(
                "{name} {path}: hardware vs shader sRGB max {:.0}/255, RMSE {:.3}/255, {:.2}% of pixels differ",
                m.max_abs * 255.0,
                m.rmse * 255.0,
                differing(&hardware, &shader) * 100.0
            );
            let tag = format!("hardware_srgb_{name}_{path}");
            common::assert_close(&tag, &hardware, &shader, &one);
        }
    }
}

fn differing(a: &image::RgbaImage, b: &image::RgbaImage) -> f64 {
    let n = a.pixels().zip(b.pixels()).filter(|(x, y)| x != y).count();
    n as f64 / f64::from(a.width() * a.height())
}

#[test]
fn the_shader_encodes_where_the_output_cannot_be_srgb() {
    let output_format = |s: &Scene| {
        let plan = FramePlan::new(s, &FrameLights::new(s), gloss::techniques::ALL);
        let t = plan.targets.iter().find(|t| t.name == "output").unwrap();
        let composite = plan.passes.iter().find(|p| p.name == "composite").unwrap();
        (t.colors[0].1, composite.draws.clone())
    };
    let (format, what) = output_format(&empty("deferred"));
    assert_eq!(format, glow::SRGB8_ALPHA8);
    assert!(what.contains("GL_FRAMEBUFFER_SRGB"), "{what}");
    let mut off = empty("tiled");
    off.render.hardware_srgb = false;
    let (format, what) = output_format(&off);
    assert_eq!(format, glow::RGBA8);
    assert!(
        what.contains("sRGB encode") && !what.contains("GL_FRAMEBUFFER"),
        "{what}"
    );
    // A post chain: the composite writes linear light into its HDR target.
    let post = common::scene("post-effects.toml");
    let (_, what) = output_format(&post);
    assert!(what.contains("linear"), "{what}");
    // Forward: no composite; its output stays RGBA8.
    let (format, _) = {
        let s = empty("forward");
        let plan = FramePlan::new(&s, &FrameLights::new(&s), gloss::techniques::ALL);
        let t = plan.targets.iter().find(|t| t.name == "output").unwrap();
        (t.colors[0].1, ())
    };
    assert_eq!(format, glow::RGBA8);
    // The RGBA32F output of error measurements: linear, nothing encoded
    // (encoded, 0.5 would read 0.735).
    let mut s = empty("deferred");
    s.render.background = Vec3::splat(0.5);
    let linear = common::render_with(&common::context(common::backend()), &s, Output::Linear32F);
    assert!(
        linear.linear.chunks(4).all(|p| (p[0] - 0.5).abs() < 1e-6),
        "{:?}",
        &linear.linear[..4]
    );
}
