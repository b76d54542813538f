//! src/techniques/deferred/ltc_area_lights_deferred.rs: on
//! scenes/area-lights.toml every G-buffer path (deferred per light and in
//! one pass, light volumes plain and stencil-tested, tiled shading, the
//! light pre-pass; the RGBA16F and the octahedral normal; the microfacet
//! triple in each encoding) draws forward's image within AREA_BOUND, with
//! the area lights on and off, with and without point lights beside them.
//! The lights on change the image far beyond that bound, so a skipped pass
//! fails. The plan lists the pass only when the scene has area lights and
//! `render.area_lights` is on; every pass restores the GL state. Every
//! render runs with GL debug output on (any GL error fails) and the
//! feedback-loop check.

use crate::common;
use gloss::image_compare::{Metrics, compare_rgba8};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

/// The G-buffer's precision against forward, in 8-bit sRGB: no channel off
/// by more than 2/255 and at most 0.05 % of the pixels by more than 1/255.
/// The residue is the G-buffer's: the normal in RGBA16F (relative error
/// 2^-11) or 12 + 12 bits, the albedo in 8-bit sRGB, the microfacet triple
/// in half floats, the light summed in RGBA16F. Measured on llvmpipe at
/// 320x180: at most 2/255 and 1 pixel in 57 600 over 1/255.
const MAX_ABS: f64 = 2.0 / 255.0;
const MAX_FRAC_OVER: f64 = 0.0005;
/// With the triple's gAlpha in 8 bits (`report_rgba8`: alpha and 1/eta to
/// the nearest 1/255) a near-mirror highlight moves a little further:
/// measured at most 3/255, 5 pixels over 1/255.
const MAX_ABS_8BIT: f64 = 4.0 / 255.0;

/// The variants of the G-buffer paths, as `--set` overrides.
const PATHS: &[&[&str]] = &[
    &["render.path=deferred"],
    &["render.path=deferred", "render.deferred_lights=single_pass"],
    &["render.path=volumes"],
    &["render.path=volumes", "render.stencil_volumes=true"],
    &["render.path=tiled"],
    &["render.path=prepass"],
    &["render.path=deferred", "render.gbuffer=octahedral"],
    &["render.path=tiled", "render.gbuffer=octahedral"],
    &["render.path=prepass", "render.gbuffer=octahedral"],
    &[
        "render.path=deferred",
        "render.gbuffer_encoding=report_rgba8",
    ],
    &[
        "render.path=prepass",
        "render.gbuffer_encoding=report_rgba16f",
    ],
];

/// A point light beside the area lights: the lighting pass runs (and
/// clears) before the area lights' pass adds to it.
const POINT_LIGHT: &str = "\n[[lights]]\ntype = \"point\"\nposition = [1.0, 1.2, 1.5]\n\
     color = [0.6, 0.8, 1.0]\nintensity = 1.0\nattenuation = [1.0, 0.35, 0.44]\n";

fn scene(point_light: bool, overrides: &[&str]) -> Scene {
    let path = common::root().join("scenes/area-lights.toml");
    let mut text = std::fs::read_to_string(&path).unwrap();
    let mut o: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    if point_light {
        text.push_str(POINT_LIGHT);
        // No cutoff, so that light volumes and tiles drop none of its light
        // (their own bound against forward is tests/deferred/light_volumes.rs).
        o.insert(0, "render.cutoff=1e-6".into());
    }
    o.push("render.size=[320, 180]".into());
    Scene::parse_with(&text, &path, &o).unwrap()
}

fn compare(label: &str, a: &image::RgbaImage, b: &image::RgbaImage) -> Metrics {
    let m = compare_rgba8(a, b, 1.0 / 255.0).unwrap();
    eprintln!(
        "{label}: max {:.0}/255, {:.4} % over 1/255 ({} pixels), RMSE {:.3}/255",
        m.max_abs * 255.0,
        m.frac_over * 100.0,
        (m.frac_over * f64::from(a.width() * a.height())).round(),
        m.rmse * 255.0
    );
    m
}

#[test]
fn every_gbuffer_path_draws_the_area_lights_as_forward_does() {
    let ctx = common::context(common::backend());
    let render = |s: &Scene| common::render_with(&ctx, s, Output::Srgb8).image;
    let mut worst = (0.0f64, 0.0f64);
    for point_light in [false, true] {
        for on in [true, false] {
            let switch = format!("render.area_lights={on}");
            let forward = render(&scene(point_light, &["render.path=forward", &switch]));
            if on {
                // The lights must matter: forward with them off is far off.
                let off = scene(
                    point_light,
                    &["render.path=forward", "render.area_lights=false"],
                );
                let m = compare("forward on vs off", &forward, &render(&off));
                assert!(m.max_abs > 0.25 && m.frac_over > 0.5, "{m:?}");
            }
            for overrides in PATHS {
                let mut o = overrides.to_vec();
                o.push(&switch);
                let s = scene(point_light, &o);
                let label = format!("{} (point light {point_light}) vs forward", o.join(" "));
                let m = compare(&label, &render(&s), &forward);
                let eight_bit = o.iter().any(|k| k.ends_with("report_rgba8"));
                let max_abs = if eight_bit { MAX_ABS_8BIT } else { MAX_ABS };
                assert!(
                    m.max_abs <= max_abs + 1e-9 && m.frac_over <= MAX_FRAC_OVER,
                    "{label}: {m:?}"
                );
                worst = (worst.0.max(m.max_abs), worst.1.max(m.frac_over));
            }
        }
    }
    eprintln!(
        "worst: max {:.0}/255, {:.4} % over 1/255",
        worst.0 * 255.0,
        worst.1 * 100.0
    );
}

#[test]
fn the_plan_lists_the_pass_only_with_area_lights_switched_on() {
    let names = |s: &Scene| -> Vec<&'static str> {
        gloss::techniques::plan(s)
            .passes
            .iter()
            .map(|p| p.name)
            .collect()
    };
    for path in ["deferred", "volumes", "tiled", "prepass", "forward"] {
        let p = format!("render.path={path}");
        let on = names(&scene(false, &[&p]));
        let off = names(&scene(false, &[&p, "render.area_lights=false"]));
        // The shading pass on the G-buffer paths; forward shades in its own pass.
        assert_eq!(
            on.contains(&"area lights (LTC)"),
            path != "forward",
            "{path}: {on:?}"
        );
        // The rectangles on every path, after the final image.
        let last = on.iter().rposition(|n| *n == "area lights").unwrap();
        let image = ["composite", "combine", "forward"];
        let made = on.iter().position(|n| image.contains(n)).unwrap();
        assert!(made < last, "{path}: {on:?}");
        if path != "forward" {
            let shade = on.iter().position(|n| *n == "area lights (LTC)").unwrap();
            assert!(
                shade < made,
                "{path}: shaded before the final image: {on:?}"
            );
        }
        assert!(
            !off.iter().any(|n| n.starts_with("area lights")),
            "{path}: {off:?}"
        );
        // A scene without area lights: none on any path.
        let mut none = scene(false, &[&p]);
        none.area_lights.clear();
        assert!(!names(&none).iter().any(|n| n.starts_with("area lights")));
        // And no warning that they are left out.
        assert!(
            scene(false, &[&p])
                .warnings()
                .iter()
                .all(|w| !w.starts_with("area_lights")),
            "{path}"
        );
    }
    // The light pre-pass: between its light pre-pass and its combine; with
    // no point light it makes the light targets itself.
    let on = names(&scene(true, &["render.path=prepass"]));
    let at = |n: &str| on.iter().position(|p| *p == n).unwrap();
    assert!(at("light pre-pass") < at("area lights (LTC)"), "{on:?}");
    assert!(at("area lights (LTC)") < at("combine"), "{on:?}");
    for path in ["deferred", "prepass"] {
        let s = scene(false, &[&format!("render.path={path}")]);
        let plan = gloss::techniques::plan(&s);
        assert!(plan.target("light_accumulation").is_some(), "{plan}");
    }
}

#[test]
fn every_pass_restores_the_gl_state_with_area_lights() {
    let ctx = common::context(common::backend());
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Tiled,
        RenderPath::Prepass,
    ] {
        for point_light in [false, true] {
            let mut s = scene(point_light, &[]);
            s.render.path = path;
            let changed = common::state_left_changed(&ctx, &s, 96, 54);
            assert!(changed.is_empty(), "{path:?}:\n  {}", changed.join("\n  "));
        }
    }
}
