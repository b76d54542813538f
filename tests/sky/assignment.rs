//! Notes 03's whole pipeline, scenes/assignment-bunny.toml: the frame plan
//! runs the report's passes in the report's order (geometry, shadow, point
//! light, ambient light, skybox mirror reflection, sun-sky, the four blurs
//! into mip levels 1-4, merge, gamma), each writing the target the report's
//! diagram names; the G-buffer holds the report's four buffers; the frame
//! renders with no GL error and no non-finite pixel; the sun's disc has the
//! radiance src/scene/sky.rs gives it, and it is what the bloom spreads. Its picture is held by
//! tests/golden.rs.

use crate::common;
use glam::Vec4Swizzles;
use gloss::renderer::Output;
use gloss::scene::Scene;

#[test]
fn the_plan_runs_the_reports_passes_in_the_reports_order() {
    let scene = common::scene("assignment-bunny.toml");
    let plan = gloss::techniques::plan(&scene);
    let names: Vec<&str> = plan.passes.iter().map(|p| p.name).collect();
    let first = |name: &str| {
        (names.iter().position(|n| *n == name))
            .unwrap_or_else(|| panic!("no {name} pass in {names:?}"))
    };
    // (pass, the target the report's diagram has it write)
    let report = [
        ("shadow map", "shadow map"),
        ("gbuffer", "gbuffer"),
        ("lighting", "light_accumulation"),
        ("ambient light", "ambient_occlusion"),
        ("skybox reflection", "light_accumulation"),
        ("sun-sky", "hdr"),
        ("bloom blur v", "bloom_levels"),
        ("bloom merge", "post_ping_pong"),
        ("gamma correction", "output"),
    ];
    let mut last = 0;
    for (i, (name, target)) in report.iter().enumerate() {
        let at = first(name);
        assert_eq!(plan.passes[at].target, *target, "{name} writes {target}");
        // The shadow maps are made before the views (they do not depend on
        // the camera); everything else follows the report.
        if i > 1 {
            assert!(
                at > last,
                "{name} runs after {}: {names:?}",
                report[i - 1].0
            );
        }
        last = at;
    }
    assert!(first("shadow map") < first("lighting"));
    // Two point lights, two cube shadow maps, each drawn face by face (six
    // passes a light); four blurs into levels 1-4.
    let mut casting: Vec<usize> = (plan.passes.iter())
        .filter(|p| p.name == "shadow map")
        .map(|p| p.item)
        .collect();
    assert_eq!(casting.len(), 12);
    casting.dedup();
    assert_eq!(casting.len(), 2);
    let levels: Vec<u32> = (plan.passes.iter())
        .filter(|p| p.name == "bloom blur v")
        .map(|p| p.level)
        .collect();
    assert_eq!(levels, [1, 2, 3, 4]);
    // The geometry pass's G-buffers: normal, diffuse, gAlpha, gConvert.
    let gbuffer = (plan.targets.iter().find(|t| t.name == "gbuffer")).expect("a G-buffer");
    let colors: Vec<&str> = gbuffer.colors.iter().map(|c| c.0).collect();
    assert_eq!(
        colors,
        ["normal_shininess", "albedo", "specular", "alpha", "convert"]
    );
}

#[test]
fn the_whole_frame_renders_finite() {
    let mut scene = common::scene("assignment-bunny.toml");
    scene.render.size = (320, 180);
    let r = common::render(&scene, Output::Linear32F);
    let bad = r.linear.iter().filter(|c| !c.is_finite()).count();
    assert_eq!(bad, 0, "{bad} channels are not finite");
    // The bunny is lit (not black) and the sky is there (the top row bright).
    let top = &r.linear[((179 * 320 + 160) * 4) as usize..][..3];
    assert!(
        top.iter().all(|c| *c > 0.05),
        "the sky's top row is {top:?}"
    );
}

/// The pixel (x, y from the bottom) the sun's centre falls on.
fn sun_pixel(scene: &Scene) -> (u32, u32) {
    let sky = scene.sky.as_ref().expect("a sky");
    let (w, h) = scene.render.size;
    let vp = scene.camera.projection(w as f32 / h as f32) * scene.camera.view();
    let clip = vp * sky.sun.extend(0.0);
    let ndc = clip.xy() / clip.w;
    let x = (ndc.x * 0.5 + 0.5) * w as f32;
    let y = (ndc.y * 0.5 + 0.5) * h as f32;
    assert!(
        x > 8.0 && y > 8.0 && x < w as f32 - 8.0 && y < h as f32 - 8.0,
        "the sun is in view"
    );
    (x as u32, y as u32)
}

#[test]
fn the_suns_disc_has_its_radiance_and_blooms() {
    let mut scene = common::scene("assignment-bunny.toml");
    scene.render.size = (640, 360);
    let (x, y) = sun_pixel(&scene);
    let want = scene.sky.as_ref().unwrap().sun_disc_radiance();
    // Without the post chain the output is the linear HDR image: the
    // disc's pixel is its radiance plus a sky a ten-thousandth as bright,
    // within a half float's rounding.
    let ctx = common::context(common::backend());
    let mut hdr = scene.clone();
    hdr.post.clear();
    let r = common::render_with(&ctx, &hdr, Output::Linear32F);
    let got = &r.linear[((y * 640 + x) * 4) as usize..][..3];
    for (g, w) in got.iter().zip(want.to_array()) {
        assert!(
            (g - w).abs() <= 2e-3 * w,
            "the sun's pixel is {got:?}, want {want}"
        );
    }
    // The bloom spreads it: a ring 12 to 24 pixels from the sun's centre
    // gains light with the bloom, far more than without the disc.
    let ring_gain = |s: &Scene| {
        let mut plain = s.clone();
        plain
            .post
            .retain(|p| !matches!(p, gloss::scene::post::PostPass::Bloom(_)));
        let with = common::render_with(&ctx, s, Output::Srgb8).image;
        let without = common::render_with(&ctx, &plain, Output::Srgb8).image;
        let (mut sum, mut n) = (0.0, 0);
        for dy in -24i32..=24 {
            for dx in -24i32..=24 {
                let d2 = dx * dx + dy * dy;
                if !(144..=576).contains(&d2) {
                    continue;
                }
                // The image's rows run top down.
                let (px, py) = ((x as i32 + dx) as u32, (359 - y as i32 - dy) as u32);
                let a = with.get_pixel(px, py).0;
                let b = without.get_pixel(px, py).0;
                sum += (0..3)
                    .map(|c| f64::from(a[c]) - f64::from(b[c]))
                    .sum::<f64>()
                    / 3.0;
                n += 1;
            }
        }
        sum / f64::from(n)
    };
    let with_sun = ring_gain(&scene);
    let mut no_disc = scene.clone();
    no_disc.sky.as_mut().unwrap().sun_disc = 0.0;
    let without_sun = ring_gain(&no_disc);
    assert!(
        with_sun > 20.0 && with_sun > 5.0 * without_sun.max(1.0),
        "the bloom brightens the ring by {with_sun:.1}/255 with the sun's disc, {without_sun:.1}/255 without"
    );
}

#[test]
fn the_data_flow_diagram_has_the_reports_arrows() {
    let scene = common::scene("assignment-bunny.toml");
    let plan = gloss::techniques::plan(&scene);
    let dot = gloss::frame::plan_graph::dot(&plan, &scene.name);
    let number = |name: &str| {
        let i = plan.passes.iter().position(|p| p.name == name).unwrap();
        format!("\"{}. {name}\"", i + 1)
    };
    // The report's diagram: object model -> geometry -> g-buffers -> point
    // light (with the shadow map) -> accumulation -> ... -> merge -> gamma.
    for (from, to) in [
        (number("gbuffer"), "\"target: gbuffer\"".to_string()),
        ("\"target: gbuffer\"".into(), number("lighting")),
        ("\"target: shadow map\"".into(), number("lighting")),
        (number("lighting"), "\"target: light_accumulation\"".into()),
        ("\"target: gbuffer\"".into(), number("ambient light")),
        (
            "\"target: environment\"".into(),
            number("skybox reflection"),
        ),
        ("\"target: light_accumulation\"".into(), number("composite")),
        ("\"target: hdr\"".into(), number("bloom merge")),
        ("\"target: bloom_levels\"".into(), number("bloom merge")),
        (number("gamma correction"), "\"target: output\"".into()),
    ] {
        let edge = format!("{from} -> {to};");
        assert!(dot.contains(&edge), "no {edge} in\n{dot}");
    }
    // The copy in docs/ is this scene's diagram as gloss writes it now.
    let shipped = std::fs::read_to_string(common::root().join("docs/images/assignment-bunny.dot"))
        .expect("docs/images/assignment-bunny.dot");
    assert_eq!(
        shipped, dot,
        "docs/images/assignment-bunny.dot is stale: gloss plan scenes/assignment-bunny.toml --dot docs/images/assignment-bunny.dot"
    );
}

#[test]
fn each_passes_target_can_be_written_as_a_picture() {
    let mut scene = common::scene("assignment-bunny.toml");
    scene.render.size = (160, 90);
    let ctx = common::context(common::backend());
    let r = gloss::renderer::render_scene(&ctx, &scene, Output::Srgb8).expect("renders");
    // The ground at the bottom of the picture faces up: (0, 1, 0) shows as
    // (n + 1) / 2 = (128, 255, 128).
    let normals = r.read_target("gbuffer.normal_shininess").unwrap();
    let p = normals.get_pixel(80, 88).0;
    assert!(
        p[0].abs_diff(128) <= 1 && p[1] == 255 && p[2].abs_diff(128) <= 1,
        "the ground's normal shows as {p:?}"
    );
    // The AO is one channel, shown grey; the open ground is unoccluded.
    let ao = r.read_target("ambient_occlusion_blurred").unwrap();
    let a = ao.get_pixel(5, 88).0;
    assert!(
        a[0] == a[1] && a[1] == a[2] && a[0] == 255,
        "open ground's AO shows as {a:?}"
    );
    // What cannot be written says what can.
    let e = r.read_target("nope").unwrap_err().to_string();
    assert!(
        e.contains("no target \"nope\"") && e.contains("gbuffer"),
        "{e}"
    );
    let e = r.read_target("gbuffer.nope").unwrap_err().to_string();
    assert!(
        e.contains("normal_shininess, albedo, specular, alpha, convert"),
        "{e}"
    );
    let e = r.read_target("bloom_levels").unwrap_err().to_string();
    assert!(e.contains("mip levels"), "{e}");
}
