//! Notes 03's microfacet material (glsl/common/microfacet.glsl through
//! `surface_light` in glsl/common/lighting.glsl; the triple through the
//! G-buffer in glsl/common/gbuffer_material.glsl): a lit plane's every
//! sampled pixel equals the CPU's f64 Cook-Torrance (src/lighting/microfacet.rs)
//! on the forward path and through each G-buffer encoding, where the
//! expected value uses the triple as the encoding's format gives it back;
//! grazing light and view, and alpha at its ends, give no NaN; every
//! deferred path draws scenes/microfacet.toml as forward does.

use crate::common;
use glam::{DVec3, Vec3};
use gloss::image_compare::Tolerance;
use gloss::lighting::{light_factor, microfacet, srgb_decode, srgb_encode};
use gloss::math::gbuffer_encoding::Format;
use gloss::renderer::Output;
use gloss::scene::material::GBufferEncoding;
use gloss::scene::{RenderPath, Scene};
use std::f64::consts::PI;

const SIZE: u32 = 128;
const LIGHT: [f32; 3] = [0.3, 1.5, -0.2];
const EYE: [f32; 3] = [0.0, 4.0, 0.0];

/// A 2 x 2 plane facing up, filling the image of an orthographic camera
/// above it, lit by one point light with Kq = 0 (pixel (x, y from the
/// bottom) is world ((2x + 1) / SIZE - 1, 0, 1 - (2y + 1) / SIZE)).
fn lit_plane(path: &str, encoding: GBufferEncoding, material: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = {EYE:?}\n\
         target = [0.0, 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\nhalf_height = 1.0\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [{SIZE}, {SIZE}]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\n\
         gbuffer_encoding = \"{encoding}\"\n\
         [[lights]]\ntype = \"point\"\nposition = {LIGHT:?}\ncolor = [1.0, 1.0, 1.0]\n\
         intensity = 1.0\nattenuation = [1.0, 0.2, 0.0]\n\
         [materials.m]\n{material}\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// What the encoding gives a lighting pass back for `v`: the GLSL's
/// decode_report (1 / max(stored, 1e-3)) of the value the format stores.
fn through(encoding: GBufferEncoding, v: f64) -> f64 {
    let report = |f: Format| {
        if v > 1.0 {
            1.0 / f.quantise(1.0 / v).max(1e-3)
        } else {
            f.quantise(v)
        }
    };
    match encoding {
        GBufferEncoding::ReportRgba8 => report(Format::Rgba8),
        GBufferEncoding::ReportRgba16f => report(Format::Rgba16F),
        GBufferEncoding::PlainRgba16f => Format::Rgba16F.quantise(v),
    }
}

#[test]
fn a_lit_planes_pixels_are_the_cpu_brdf() {
    let ctx = common::context(common::backend());
    let kd = 0.2;
    // (alpha, eta, k_s): near a mirror, glossy, rough with a strong
    // Fresnel, alpha past 1 (stored as its reciprocal) and past 510
    // (stored as 0 in 8 bits), eta and k_s past 1; none on an 8-bit
    // rounding tie (0.3 x 255 = 76.5), where the GPU may round either way.
    let triples = [
        (0.05, 1.5, 1.0),
        (0.31, 1.33, 0.72),
        (1.0, 2.4, 3.0),
        (4.0, 1.5, 1.0),
        (700.0, 1.2, 0.5),
    ];
    let runs = [
        ("forward", GBufferEncoding::PlainRgba16f),
        ("deferred", GBufferEncoding::ReportRgba8),
        ("deferred", GBufferEncoding::ReportRgba16f),
        ("deferred", GBufferEncoding::PlainRgba16f),
        ("prepass", GBufferEncoding::ReportRgba16f),
    ];
    for (alpha, eta, k_s) in triples {
        let material = format!(
            "diffuse = [{kd}, {kd}, {kd}]\nmodel = \"microfacet\"\nalpha = {alpha}\neta = {eta}\nk_s = {k_s}"
        );
        for (path, encoding) in runs {
            let scene = lit_plane(path, encoding, &material);
            let light = &scene.lights[0];
            // The forward path reads the uniforms as they are.
            let g = |v: f64| {
                if path == "forward" {
                    v
                } else {
                    through(encoding, v)
                }
            };
            let (a, e, k) = (g(alpha), g(eta), g(k_s));
            // The G-buffer's albedo is SRGB8_ALPHA8 (the light pre-pass
            // reads the material again instead).
            let kd = if path != "deferred" {
                kd
            } else {
                let stored = (srgb_encode(kd as f32) * 255.0).round() / 255.0;
                f64::from(srgb_decode(stored))
            };
            let r = common::render_with(&ctx, &scene, Output::Linear32F);
            let mut worst = (0.0f64, 0, 0, 0.0, 0.0);
            for y in (1..SIZE).step_by(6) {
                for x in (1..SIZE).step_by(6) {
                    let s = f64::from(SIZE);
                    let p = DVec3::new(
                        (2.0 * f64::from(x) + 1.0) / s - 1.0,
                        0.0,
                        1.0 - (2.0 * f64::from(y) + 1.0) / s,
                    );
                    let (att, l, _) = light_factor(light, p.as_vec3());
                    let i = f64::from(att * light.radiance().x);
                    let (l, n) = (l.as_dvec3(), DVec3::Y);
                    let v = (Vec3::from(EYE).as_dvec3() - p).normalize();
                    let n_dot_l = n.dot(l).max(0.0);
                    let f_s = microfacet::brdf(l, v, n, a, e, 1.0);
                    let want = kd * i * n_dot_l + k * PI * f_s * i * n_dot_l;
                    let got = f64::from(r.linear[((y * SIZE + x) * 4) as usize]);
                    let err = (got - want).abs() / want.max(0.05);
                    if err > worst.0 {
                        worst = (err, x, y, got, want);
                    }
                }
            }
            // f32 arithmetic against f64, the light and the eye as f32 and
            // the depth rebuilt position (deferred): 0.5% of the value.
            let (err, x, y, got, want) = worst;
            assert!(
                err < 5e-3,
                "{path} {encoding}, (alpha, eta, k_s) = ({alpha}, {eta}, {k_s}): pixel ({x}, {y}) \
                 is {got}, the CPU says {want} (relative error {err:.2e})"
            );
        }
    }
}

#[test]
fn grazing_light_and_view_and_extreme_alpha_give_no_nan() {
    let ctx = common::context(common::backend());
    for alpha in [1e-3, 1.0, 1e3] {
        for path in ["forward", "deferred"] {
            let material = format!(
                "diffuse = [0.2, 0.2, 0.2]\nmodel = \"microfacet\"\nalpha = {alpha}\neta = 1.5"
            );
            let mut scene = lit_plane(path, GBufferEncoding::ReportRgba16f, &material);
            // The light in the plane (N . L = 0 across it) and the eye
            // skimming it (N . V -> 0 toward the far edge).
            scene.lights[0].position = Vec3::new(0.0, 1e-4, -3.0);
            scene.camera.eye = Vec3::new(0.0, 0.02, 3.0);
            scene.camera.target = Vec3::new(0.0, 0.0, -1.0);
            scene.camera.up = Vec3::Y;
            let r = common::render_with(&ctx, &scene, Output::Linear32F);
            let bad = r.linear.iter().filter(|c| !c.is_finite()).count();
            assert_eq!(
                bad, 0,
                "{path}, alpha {alpha}: {bad} channels are not finite"
            );
            // The plane is there and lit a little: the test looked at something.
            let lit = r.linear.chunks(4).filter(|p| p[0] > 0.0).count();
            assert!(lit > 100, "{path}, alpha {alpha}: only {lit} pixels lit");
        }
    }
}

#[test]
fn every_deferred_path_draws_the_microfacet_scene_as_forward_does() {
    let ctx = common::context(common::backend());
    let mut s = common::scene("microfacet.toml");
    s.render.size = (480, 270);
    s.render.path = RenderPath::Forward;
    let forward = common::render_with(&ctx, &s, Output::Srgb8).image;
    for encoding in GBufferEncoding::ALL {
        for path in [
            RenderPath::Deferred,
            RenderPath::Volumes,
            RenderPath::Tiled,
            RenderPath::Prepass,
        ] {
            s.render.path = path;
            s.render.gbuffer_encoding = *encoding;
            let deferred = common::render_with(&ctx, &s, Output::Srgb8).image;
            // Half floats hold the triple within 4.9e-4 (relative); 8 bits
            // move a near-mirror's alpha by up to 1/510 absolute, which
            // moves its highlight.
            let tol = match encoding {
                GBufferEncoding::ReportRgba8 => Tolerance {
                    threshold: 2.0 / 255.0,
                    max_frac_over: 0.01,
                    max_abs: Some(40.0 / 255.0),
                },
                _ => Tolerance {
                    threshold: 1.0 / 255.0,
                    max_frac_over: 0.005,
                    max_abs: Some(6.0 / 255.0),
                },
            };
            common::assert_close(
                &format!("microfacet-forward-{path}-{encoding}"),
                &deferred,
                &forward,
                &tol,
            );
        }
    }
}
