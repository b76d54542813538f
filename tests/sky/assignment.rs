//! Notes 03's whole pipeline, scenes/assignment-bunny.toml: the frame plan
//! runs the report's passes in the report's order (geometry, shadow, point
//! light, ambient light, skybox mirror reflection, sun-sky, the four blurs
//! into mip levels 1-4, merge, gamma), each writing the target the report's
//! diagram names; the G-buffer holds the report's four buffers; the frame
//! renders with no GL error and no non-finite pixel. Its picture is held by
//! tests/golden.rs.

use crate::common;
use gloss::renderer::Output;

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
    // Two point lights, two cube shadow maps; four blurs into levels 1-4.
    assert_eq!(names.iter().filter(|n| **n == "shadow map").count(), 2);
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
