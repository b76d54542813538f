//! The shadow pass's two programs (src/techniques/shadows/casters.rs): with
//! `render.specialize` the opaque casters are drawn with the depth-only
//! program (built with DEPTH_ONLY: no alpha test, no texture coordinates)
//! and only alpha-tested casters with the alpha-test program; with it off,
//! every caster with the general program, as before.
//!
//! * `gloss trace` shows it: no `u_alpha_test` uniform in a frame without
//!   alpha-tested casters, and one program switch in model-loading's (its
//!   leaves are alpha-tested), the general program setting `u_alpha_test`
//!   for every caster with `render.specialize = false`;
//! * the images are, byte for byte, those of the shadow pass before the
//!   split (tests/shadows/before_depth_only/, rendered by `gloss render
//!   --size 192x108` at commit 8d99c02, one program for every caster), both
//!   specialised and general: the depth-only program stores the same depths,
//!   and the leaves keep their cut-out shadows.

use crate::common;
use gloss::renderer::Output;

fn trace(scene: &str, technique: &str, general: bool) -> String {
    let mut args = vec!["trace", scene, "--technique", technique, "--size", "96x54"];
    if general {
        args.extend(["--set", "render.specialize=false"]);
    }
    common::gloss(&args)
}

/// The programs the first pass of a listing puts in use, in order.
fn first_pass_programs(listing: &str) -> Vec<String> {
    let first = listing.split("\n2. ").next().unwrap();
    (first.lines().map(str::trim_start))
        .filter(|l| l.starts_with("glUseProgram(") && !l.starts_with("glUseProgram(0)"))
        .map(|l| l[..=l.find(')').unwrap()].to_string())
        .collect()
}

#[test]
fn opaque_casters_use_the_depth_only_program_and_alpha_tested_ones_the_test() {
    for (scene, technique) in [
        ("default", "shadow_map"),
        ("shadows-directional", "shadow_map"),
        ("shadows-spot", "shadow_map"),
        ("shadows-point", "shadow_map"),
        ("skinned-arm", "shadow_map"),
        ("cascaded-shadows", "cascaded_shadow_maps"),
    ] {
        // No alpha-tested caster: one program, without the alpha test.
        let special = trace(scene, technique, false);
        assert!(special.contains("glDrawElements"), "{scene}: {special}");
        assert!(!special.contains("u_alpha_test"), "{scene}: {special}");
        assert_eq!(first_pass_programs(&special).len(), 1, "{scene}: {special}");
        // The general program tests every caster (u_alpha_test = 0).
        let general = trace(scene, technique, true);
        assert!(general.contains("u_alpha_test, 0)"), "{scene}: {general}");
        assert_eq!(first_pass_programs(&general).len(), 1, "{scene}: {general}");
    }
    // model-loading's leaves are alpha-tested: the opaque casters first,
    // depth only, then a switch to the alpha test for the leaves alone.
    let special = trace("model-loading", "shadow_map", false);
    let programs = first_pass_programs(&special);
    assert_eq!(programs.len(), 2, "{special}");
    assert_ne!(programs[0], programs[1], "{special}");
    let first = special.split("\n2. ").next().unwrap();
    let switch = first.find(programs[1].as_str()).unwrap();
    assert!(!first[..switch].contains("u_alpha_test"), "{first}");
    assert!(first[switch..].contains("u_alpha_test, 7)"), "{first}");
    assert!(!special.contains("u_alpha_test, 0)"), "{special}");
    let general = trace("model-loading", "shadow_map", true);
    assert_eq!(first_pass_programs(&general).len(), 1, "{general}");
    assert!(general.contains("u_alpha_test, 0)"), "{general}");
    assert!(general.contains("u_alpha_test, 7)"), "{general}");
}

#[test]
fn the_images_are_those_of_the_single_program_byte_for_byte() {
    let ctx = common::context(common::backend());
    let dir = common::root().join("tests/shadows/before_depth_only");
    let cases = [
        ("default", false),
        ("shadows-spot", false),
        ("shadows-directional", false),
        ("shadows-point", false),
        ("skinned-arm", false),
        ("cascaded-shadows", false),
        ("model-loading", false),
        ("default", true),
        ("shadows-point", true),
        ("model-loading", true),
    ];
    for (name, general) in cases {
        let mut s = common::scene(&format!("{name}.toml"));
        s.render.size = (192, 108);
        s.render.specialize = !general;
        let file = format!(
            "{name}-192x108{}.png",
            if general { "-general" } else { "" }
        );
        let before = image::open(dir.join(&file)).unwrap().to_rgba8();
        let now = common::render_with(&ctx, &s, Output::Srgb8).image;
        let differ = common::pixels_differing(&now, &before, &file);
        assert_eq!(differ, 0, "{file}: {differ} pixels differ");
    }
}
