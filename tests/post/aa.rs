//! Anti-aliasing (src/techniques/post/fxaa.rs,
//! src/techniques/fragment_tests/msaa.rs) against a 16-sample supersampled
//! reference (src/bench/aa.rs): both bring the error on edge pixels down by
//! a stated factor; FXAA leaves flat regions exactly as they were; MSAA with
//! no edge in view changes nothing; the plan shows the multisampled target
//! and the resolve only when they run; every pass restores the GL state;
//! bad keys are errors that name the key.

use crate::common;
use gloss::bench::aa::{self, AaError, LinearImage};
use gloss::frame::multisample::MSAA;
use gloss::gl::Headless;
use gloss::renderer::{Output, render_scene};
use gloss::scene::post::PostPass;
use gloss::scene::{RenderPath, Scene};
use gloss::techniques::plan;
use std::path::Path;

/// A white plate turned 5 degrees over black, seen from straight above: its
/// edges step once every 11 pixels, the case anti-aliasing is for.
/// Lit white exactly (diffuse 1, a light straight down, no ambient), tone
/// mapped by clamping, so every pixel is 0 or 1 before anti-aliasing.
const SLANTED: &str = r#"
[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 3.0
near = 1.0
far = 20.0

[render]
size = [160, 120]
ambient = [0.0, 0.0, 0.0]

[[lights]]
type = "directional"
direction = [0.0, -1.0, 0.0]

[materials.white]
diffuse = [1.0, 1.0, 1.0]
specular = [0.0, 0.0, 0.0]

[[objects]]
mesh = "plane"
material = "white"
rotation = [0.0, 5.0, 0.0]
scale = [1.5, 1.0, 1.0]

[[post]]
pass = "tonemap"
operator = "clamp"
[[post]]
pass = "gamma"
"#;

/// A plane that fills the view, lit by a point light (smooth shading, no
/// geometric edge anywhere).
const FLAT: &str = r#"
[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 3.0
near = 1.0
far = 20.0

[render]
size = [160, 120]

[[lights]]
type = "point"
position = [1.0, 2.0, -0.5]

[[objects]]
mesh = "plane"
scale = [20.0, 1.0, 20.0]
"#;

fn parse(text: &str, sets: &[&str]) -> anyhow::Result<Scene> {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    Scene::parse_with(text, Path::new("aa-test.toml"), &sets)
}

fn scene(text: &str, sets: &[&str]) -> Scene {
    parse(text, sets).unwrap_or_else(|e| panic!("{e:#}"))
}

fn edge_errors(ctx: &Headless, base: &Scene) -> Vec<(&'static str, AaError)> {
    let reference = aa::reference(ctx, base).unwrap();
    let edges = aa::edge_mask(&reference);
    let (w, h) = base.render.size;
    [("none", 1, false), ("FXAA", 1, true), ("MSAA 4", 4, false)]
        .into_iter()
        .map(|(label, msaa, fxaa)| {
            let s = aa::variant(base, msaa, fxaa).unwrap();
            let image = aa::render_linear(ctx, &s, w, h).unwrap();
            (label, aa::error(&image, &reference, &edges).unwrap())
        })
        .collect()
}

#[test]
fn fxaa_and_msaa_bring_the_edge_error_down_against_supersampling() {
    let ctx = common::context(common::backend());
    let errors = edge_errors(&ctx, &scene(SLANTED, &[]));
    let [none, fxaa, msaa] = [errors[0].1, errors[1].1, errors[2].1];
    let table = format!("{errors:#?}");
    // The plate's outline: a few hundred pixels of 19 200.
    assert!(none.edge_pixels > 300, "{table}");
    assert!(
        none.edge_rmse * 255.0 > 40.0,
        "aliased edges are far off: {table}"
    );
    // Measured on llvmpipe: 62.7/255 with none, 36.4 with FXAA (1.7x
    // less), 15.3 with 4x MSAA (4.1x less). Bounds: FXAA 1.5x, MSAA 3x.
    assert!(fxaa.edge_rmse < none.edge_rmse / 1.5, "{table}");
    assert!(msaa.edge_rmse < none.edge_rmse / 3.0, "{table}");
    assert!(fxaa.rmse < none.rmse && msaa.rmse < none.rmse, "{table}");
}

#[test]
fn fxaa_leaves_flat_regions_exactly_as_they_were() {
    let ctx = common::context(common::backend());
    let base = scene(SLANTED, &[]);
    let plain = render_scene(&ctx, &base, Output::Srgb8)
        .unwrap()
        .read_image();
    let with = aa::variant(&base, 1, true).unwrap();
    let fxaa = render_scene(&ctx, &with, Output::Srgb8)
        .unwrap()
        .read_image();
    let (w, h) = plain.dimensions();
    let (mut flat, mut changed_flat, mut changed) = (0, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let p = plain.get_pixel(x, y);
            // Flat: the pixel's 3x3 neighbourhood (clamped at the border)
            // is one colour, so FXAA's local contrast is zero.
            let uniform = (-1i32..=1).all(|dy| {
                (-1i32..=1).all(|dx| {
                    let qx = (x as i32 + dx).clamp(0, w as i32 - 1) as u32;
                    let qy = (y as i32 + dy).clamp(0, h as i32 - 1) as u32;
                    plain.get_pixel(qx, qy) == p
                })
            });
            let differs = fxaa.get_pixel(x, y) != p;
            changed += differs as u32;
            if uniform {
                flat += 1;
                changed_flat += differs as u32;
            }
        }
    }
    assert_eq!(
        changed_flat, 0,
        "FXAA changed {changed_flat} of {flat} flat pixels"
    );
    assert!(flat > w * h * 9 / 10, "{flat} flat pixels of {}", w * h);
    assert!(
        changed > 100,
        "FXAA changed only {changed} pixels: it did nothing"
    );
}

#[test]
fn msaa_with_no_edge_in_view_changes_nothing() {
    let ctx = common::context(common::backend());
    // Without a chain (RGBA8 resolved into the output) and with one (RGBA16F
    // resolved into hdr).
    for chain in [false, true] {
        let mut one = scene(FLAT, &[]);
        if chain {
            one.post = scene(SLANTED, &[]).post;
        }
        let mut four = one.clone();
        four.render.msaa = 4;
        let r1 = render_scene(&ctx, &one, Output::Srgb8).unwrap();
        let r4 = render_scene(&ctx, &four, Output::Srgb8).unwrap();
        let samples = r4.targets().get(MSAA).colors[0].samples;
        assert!(samples >= 4, "the twin has {samples} samples");
        assert!(r1.targets().find(MSAA).is_none());
        let (a, b) = (r1.read_image(), r4.read_image());
        let differ = (a.pixels().zip(b.pixels())).filter(|(p, q)| p != q).count();
        assert_eq!(differ, 0, "chain {chain}: {differ} pixels differ");
        // The resolve also gave the world's depth (read back by the shadow tests).
        assert_eq!(r1.read_depth(), r4.read_depth(), "chain {chain}: depth");
    }
}

#[test]
fn the_plan_has_the_msaa_target_and_resolve_only_when_msaa_runs() {
    let with = plan(&scene(SLANTED, &["render.msaa=4"]));
    let t = with.target(MSAA).expect("the multisampled twin");
    assert_eq!(t.samples, 4);
    assert!(t.attachments().contains(&"4 samples".to_string()));
    let names: Vec<&str> = with.passes.iter().map(|p| p.name).collect();
    let resolve = names.iter().position(|n| *n == "msaa resolve").unwrap();
    let tonemap = names.iter().position(|n| *n == "tone mapping").unwrap();
    assert_eq!(resolve + 1, tonemap, "resolved before the chain: {names:?}");
    assert_eq!(with.passes[resolve].target, "hdr");
    assert_eq!(
        with.passes[0].target, MSAA,
        "the forward pass draws into the twin"
    );
    let text = with.to_string();
    assert!(
        text.contains("msaa resolve") && text.contains("4 samples"),
        "{text}"
    );

    let without = plan(&scene(SLANTED, &[]));
    assert!(without.target(MSAA).is_none() && !without.has_pass("msaa resolve"));
    assert_eq!(without.passes[0].target, "hdr");
    // A deferred path draws no multisampled world (docs/fragment_tests/msaa.md).
    let mut deferred = scene(SLANTED, &["render.msaa=8"]);
    deferred.render.path = RenderPath::Deferred;
    let p = plan(&deferred);
    assert!(
        p.target(MSAA).is_none() && !p.has_pass("msaa resolve"),
        "{p}"
    );
    // No chain: the resolve writes the output.
    let direct = plan(&scene(FLAT, &["render.msaa=2"]));
    assert_eq!(direct.passes.last().unwrap().target, "output");
    assert_eq!(direct.target(MSAA).unwrap().samples, 2);
}

#[test]
fn every_aa_pass_restores_the_gl_state_and_raises_no_error() {
    let ctx = common::context(common::backend());
    let shipped = common::scene("antialiasing.toml");
    assert_eq!(shipped.render.msaa, 4);
    assert!(shipped.post.iter().any(|p| matches!(p, PostPass::Fxaa(_))));
    for msaa in [1, 2, 4, 8] {
        let mut s = shipped.clone();
        s.render.msaa = msaa;
        let changed = common::state_left_changed(&ctx, &s, 96, 54);
        assert!(
            changed.is_empty(),
            "msaa {msaa}:\n  {}",
            changed.join("\n  ")
        );
    }
    // RGBA32F output (error measurements) with MSAA and no chain: the twin
    // follows the output's format, or the blit would fail.
    let mut direct = scene(FLAT, &["render.msaa=4"]);
    direct.post.clear();
    common::render_with(&ctx, &direct, Output::Linear32F);
    ctx.debug.check(&ctx.gl, "anti-aliasing").unwrap();
}

#[test]
fn the_reference_is_a_box_filter_in_linear_light() {
    let big = LinearImage {
        width: 4,
        height: 4,
        rgb: (0..16)
            .flat_map(|i| [if i % 2 == 0 { 1.0 } else { 0.0 }, 0.5, 0.0])
            .collect(),
    };
    let small = big.box_down(4);
    assert_eq!((small.width, small.height), (1, 1));
    assert_eq!(small.rgb, vec![0.5, 0.5, 0.0]);
    // Half covered is 0.5 in linear light: 188 of 255 once encoded, not 128.
    let edges = [true];
    let grey = LinearImage {
        width: 1,
        height: 1,
        rgb: vec![0.5, 0.5, 0.0],
    };
    let e = aa::error(&grey, &small, &edges).unwrap();
    assert_eq!(e.rmse, 0.0);
    assert_eq!(e.edge_pixels, 1);
}

#[test]
fn bad_aa_keys_are_errors_that_name_the_key() {
    let fxaa = |keys: &str| {
        SLANTED.replace(
            "[[post]]\npass = \"gamma\"",
            &format!("[[post]]\npass = \"fxaa\"\n{keys}\n[[post]]\npass = \"gamma\""),
        )
    };
    let cases: Vec<(String, &str)> = vec![
        (
            SLANTED.replace("size = [160, 120]", "size = [160, 120]\nmsaa = 3"),
            "render.msaa",
        ),
        (
            SLANTED.replace("size = [160, 120]", "size = [160, 120]\nmsaa = 16"),
            "render.msaa",
        ),
        (
            SLANTED.replace("size = [160, 120]", "size = [160, 120]\nmsaa = \"4\""),
            "msaa",
        ),
        (fxaa("quality = 16"), "post[1] (fxaa).quality"),
        (fxaa("quality = \"high\""), "post[1] (fxaa).quality"),
        (fxaa("subpix = 1.5"), "post[1] (fxaa).subpix"),
        (
            fxaa("edge_threshold = 0.0"),
            "post[1] (fxaa).edge_threshold",
        ),
        (
            fxaa("edge_threshold_min = -0.1"),
            "post[1] (fxaa).edge_threshold_min",
        ),
        (fxaa("radius = 2"), "unknown key 'radius'"),
    ];
    for (text, key) in &cases {
        let e = format!("{:#}", parse(text, &[]).unwrap_err());
        assert!(e.contains(key), "expected an error naming {key}, got: {e}");
    }
    // FXAA before the tonemap reads HDR light: refused, with the fix.
    let early = SLANTED.replace(
        "[[post]]\npass = \"tonemap\"",
        "[[post]]\npass = \"fxaa\"\n[[post]]\npass = \"tonemap\"",
    );
    let e = format!("{:#}", parse(&early, &[]).unwrap_err());
    assert!(e.contains("post[0] (fxaa)") && e.contains("tonemap"), "{e}");
    // And --set names the key too.
    let e = format!("{:#}", parse(SLANTED, &["render.msaa=5"]).unwrap_err());
    assert!(e.contains("render.msaa"), "{e}");
}

#[test]
fn an_fxaa_entry_is_saved_as_it_was_read() {
    let text = SLANTED.replace(
        "[[post]]\npass = \"gamma\"",
        "[[post]]\npass = \"fxaa\"\nquality = 39\nsubpix = 0.5\nedge_threshold = 0.125\nedge_threshold_min = 0.0312\n[[post]]\npass = \"gamma\"",
    );
    let s = scene(&text, &[]);
    let PostPass::Fxaa(x) = &s.post[1] else {
        panic!("{:?}", s.post)
    };
    assert_eq!((x.quality, x.subpix, x.steps().len()), (39, 0.5, 12));
    let again = PostPass::parse(&s.post[1].table(), 1).unwrap();
    assert_eq!(again, s.post[1]);
    // Left out, every key takes FXAA 3.11's default.
    let d = PostPass::parse(&toml::from_str("pass = \"fxaa\"").unwrap(), 0).unwrap();
    assert_eq!(d, PostPass::Fxaa(gloss::scene::fxaa::Fxaa::default()));
}
