//! Object outlines (LearnOpenGL, Stencil testing; src/techniques/stencil/object_outlines.rs):
//! the outline's width in pixels at rows predicted by hand from the
//! projected silhouette of a sphere (the tangent lines from the eye), on
//! every lighting path:
//!
//! * one ball: a band `render.outline_width` pixels wide on each side of
//!   the silhouette, for two widths;
//! * two outlined balls that overlap on screen: the band runs round the
//!   pair only, never across the nearer one's face over the farther;
//! * a ball partly behind a crate: the band at the hidden silhouette is
//!   drawn over the crate, and the crate inside the silhouette keeps its
//!   colour (the stencil marks depth-failing fragments too: with the
//!   lesson's GL_KEEP there, it would be painted in the outline's colour);
//! * with a mirror in the scene the outline takes only the stencil's top
//!   bit: turning outlines on changes nothing but outline pixels;
//! * no pass without [outlines] or with render.outlines = false; bad
//!   [outlines] are clear errors.

use crate::common;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::Path;

const W: u32 = 401;
const H: u32 = 301;
const FOV_Y: f32 = 40.0;
const EYE_Z: f32 = 6.0;
const ORANGE: [u8; 3] = [255, 188, 0];

/// A scene at W x H seen from (0, 0, EYE_Z) towards -z; `objects` are
/// [[objects]] tables, `outlined` the names in [outlines].
fn scene(path: RenderPath, width: u32, objects: &str, outlined: &[&str], extra: &str) -> Scene {
    let names: Vec<String> = outlined.iter().map(|n| format!("\"{n}\"")).collect();
    let text = format!(
        r#"
name = "outline test"
[camera]
eye = [0.0, 0.0, {EYE_Z}]
target = [0.0, 0.0, 0.0]
fov_y = {FOV_Y}
[render]
path = "{}"
size = [{W}, {H}]
ambient = [0.3, 0.3, 0.3]
background = [0.0, 0.0, 0.0]
outline_width = {width}
{extra}
[outlines]
objects = [{}]
color = [1.0, 0.5, 0.0]
[[lights]]
type = "directional"
direction = [0.0, 0.0, -1.0]
color = [0.5, 0.5, 0.5]
[materials.blue]
diffuse = [0.1, 0.2, 0.9]
specular = [0.0, 0.0, 0.0]
[materials.grey]
diffuse = [0.5, 0.5, 0.5]
specular = [0.0, 0.0, 0.0]
{objects}
"#,
        path.name(),
        names.join(", ")
    );
    Scene::parse(&text, Path::new("outlines-test.toml")).unwrap()
}

fn ball(name: &str, x: f32, z: f32, r: f32) -> String {
    format!(
        "[[objects]]\nname = \"{name}\"\nmesh = \"sphere\"\nmaterial = \"blue\"\nposition = [{x}, 0.0, {z}]\nscale = [{r}, {r}, {r}]\n"
    )
}

/// The columns (window x, pixels) where the tangent lines from the eye
/// touch a sphere of radius `r` at (x, 0, z), on the row through the
/// image's centre (the horizontal plane through the eye and the centre):
/// the silhouette's left and right ends, by hand.
fn silhouette(x: f32, z: f32, r: f32) -> (f32, f32) {
    let d = EYE_Z - z;
    let centre = (x / d).atan();
    let half = (r / (x * x + d * d).sqrt()).asin();
    let aspect = W as f32 / H as f32;
    let t = (FOV_Y.to_radians() / 2.0).tan() * aspect;
    let px = |a: f32| (a.tan() / t * 0.5 + 0.5) * W as f32;
    (px(centre - half), px(centre + half))
}

fn is_outline(p: &image::Rgba<u8>) -> bool {
    (0..3).all(|c| (p[c] as i32 - ORANGE[c] as i32).abs() <= 1)
}

/// The runs of outline pixels on the centre row, as [start, end) columns.
fn runs(img: &image::RgbaImage) -> Vec<(u32, u32)> {
    let y = H / 2; // pixel centre at H / 2 exactly (H odd): the centre row
    let mut out = Vec::new();
    let mut start = None;
    for x in 0..=W {
        let on = x < W && is_outline(img.get_pixel(x, y));
        match (on, start) {
            (true, None) => start = Some(x),
            (false, Some(s)) => {
                out.push((s, x));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// A band of `w` pixels ending at the silhouette column `edge` on its
/// left (`left`: the band lies left of `edge`) or starting there.
fn assert_band(run: (u32, u32), edge: f32, w: u32, left: bool, what: &str) {
    let (s, e) = run;
    let len = e - s;
    assert!(
        len.abs_diff(w) <= 1,
        "{what}: band {s}..{e} is {len} px wide, expected {w} +- 1"
    );
    let inner = if left { e as f32 } else { s as f32 };
    assert!(
        (inner - edge).abs() <= 1.0,
        "{what}: band {s}..{e} meets the silhouette at {inner}, predicted {edge:.2}"
    );
}

#[test]
fn one_ball_band_is_the_width_in_pixels_on_every_path() {
    let ctx = common::context(common::backend());
    let (x, z, r) = (0.3, -0.5, 1.1);
    let (l, rt) = silhouette(x, z, r);
    for &path in RenderPath::ALL {
        for w in [2, 7] {
            let s = scene(path, w, &ball("a", x, z, r), &["a"], "");
            let img = common::render_with(&ctx, &s, Output::Srgb8).image;
            let runs = runs(&img);
            let what = format!("{} width {w}", path.name());
            assert_eq!(runs.len(), 2, "{what}: outline runs {runs:?}");
            assert_band(runs[0], l, w, true, &format!("{what}, left"));
            assert_band(runs[1], rt, w, false, &format!("{what}, right"));
        }
    }
}

#[test]
fn overlapping_balls_are_outlined_round_the_pair() {
    let ctx = common::context(common::backend());
    let (a, b) = ((-0.6, 0.5, 0.8), (0.6, -1.0, 0.8));
    let objects = ball("near", a.0, a.1, a.2) + &ball("far", b.0, b.1, b.2);
    let (al, ar) = silhouette(a.0, a.1, a.2);
    let (bl, br) = silhouette(b.0, b.1, b.2);
    // They overlap on screen: the near one's right end is inside the far one.
    assert!(ar > bl + 10.0 && ar < br - 10.0);
    for path in [RenderPath::Forward, RenderPath::Deferred, RenderPath::Tiled] {
        let s = scene(path, 4, &objects, &["near", "far"], "");
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        let runs = runs(&img);
        let what = path.name();
        assert_eq!(runs.len(), 2, "{what}: outline runs {runs:?}");
        assert_band(runs[0], al, 4, true, &format!("{what}, near ball's left"));
        assert_band(runs[1], br, 4, false, &format!("{what}, far ball's right"));
    }
    // Only the far one outlined: its band crosses the near ball's face? No:
    // the near ball hides the far one's left end, but the outline is drawn
    // with the depth test off, so its band shows there, over the near ball.
    let s = scene(RenderPath::Forward, 4, &objects, &["far"], "");
    let runs = runs(&common::render_with(&ctx, &s, Output::Srgb8).image);
    assert_eq!(runs.len(), 2, "far only: outline runs {runs:?}");
    assert_band(runs[0], bl, 4, true, "far only, left (over the near ball)");
    assert_band(runs[1], br, 4, false, "far only, right");
}

#[test]
fn a_ball_partly_behind_a_crate_keeps_its_band_and_the_crate_its_colour() {
    let ctx = common::context(common::backend());
    let (x, z, r) = (-0.5, 0.0, 0.7);
    let crate_box = "[[objects]]\nname = \"crate\"\nmesh = \"cube\"\nmaterial = \"grey\"\nposition = [-1.0, 0.0, 2.0]\nscale = [0.4, 0.4, 0.4]\n";
    let objects = ball("ball", x, z, r) + crate_box;
    let (l, rt) = silhouette(x, z, r);
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Prepass,
    ] {
        let s = scene(path, 5, &objects, &["ball"], "");
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        let y = H / 2;
        // The crate hides the ball's left end: the pixel just inside the
        // silhouette is the crate's grey, not the ball's blue.
        let inside = img.get_pixel(l.ceil() as u32 + 2, y);
        assert!(
            inside[0] == inside[1] && inside[1] == inside[2] && inside[0] > 20,
            "{}: the crate is not in front of the ball's left end: {inside:?}",
            path.name()
        );
        let runs = runs(&img);
        assert_eq!(runs.len(), 2, "{}: outline runs {runs:?}", path.name());
        assert_band(
            runs[0],
            l,
            5,
            true,
            &format!("{}, hidden left", path.name()),
        );
        assert_band(runs[1], rt, 5, false, &format!("{}, right", path.name()));
    }
}

#[test]
fn outlines_beside_a_mirror_change_only_outline_pixels() {
    let ctx = common::context(common::backend());
    let mut text =
        std::fs::read_to_string(common::root().join("scenes/mirror-normal-first.toml")).unwrap();
    text.push_str("\n[outlines]\nobjects = [\"ball\", \"knot\"]\ncolor = [1.0, 0.5, 0.0]\n");
    let path = common::root().join("scenes/mirror-normal-first.toml");
    let on = Scene::parse(&text, &path).unwrap();
    let mut off = on.clone();
    off.render.outlines = false;
    let a = common::render_with(&ctx, &on, Output::Srgb8).image;
    let b = common::render_with(&ctx, &off, Output::Srgb8).image;
    // The mirror multiplies its reflection by its tint (stencil/mirror.rs,
    // step SURFACE): an outline seen in it is orange darkened, no bluer.
    let tinted = |p: &image::Rgba<u8>| {
        let g = p[1] as f32 / p[0].max(1) as f32;
        p[2] <= 2 && p[0] > 100 && (0.6..0.8).contains(&g)
    };
    let (mut outlined, mut reflected) = (0, 0);
    for (x, y, p) in a.enumerate_pixels() {
        let q = b.get_pixel(x, y);
        if p != q {
            assert!(
                is_outline(p) || tinted(p),
                "pixel ({x}, {y}) changed to {p:?} (was {q:?}), not the outline's colour"
            );
            outlined += 1;
            reflected += usize::from(!is_outline(p));
        }
    }
    assert!(outlined > 500, "only {outlined} outline pixels");
    assert!(
        reflected > 50,
        "only {reflected} outline pixels in the reflection"
    );
}

#[test]
fn plan_runs_outlines_only_when_asked_and_bad_outlines_are_errors() {
    let has = |s: &Scene| gloss::techniques::plan(s).has_pass("outline_draw");
    let s = scene(
        RenderPath::Forward,
        4,
        &ball("a", 0.0, 0.0, 1.0),
        &["a"],
        "",
    );
    assert!(has(&s));
    let mut off = s.clone();
    off.render.outlines = false;
    assert!(!has(&off));
    let mut none = s.clone();
    none.outlines = None;
    assert!(!has(&none));
    let text = |body: &str| {
        format!(
            "[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n[[objects]]\nname = \"a\"\nmesh = \"sphere\"\n{body}"
        )
    };
    for (body, expect) in [
        (
            "[outlines]\nobjects = [\"b\"]\n",
            "outlines.objects[0]: no object named \"b\"",
        ),
        ("[outlines]\nobjects = []\n", "outlines.objects: expected"),
        (
            "[outlines]\nobjects = [\"a\"]\ncolor = [2.0, 0.0, 0.0]\n",
            "outlines.color",
        ),
        (
            "[render]\noutline_width = 0\n",
            "render.outline_width: expected 1..=64",
        ),
    ] {
        let e = Scene::parse(&text(body), Path::new("bad.toml")).unwrap_err();
        assert!(format!("{e:#}").contains(expect), "{e:#}");
    }
}
