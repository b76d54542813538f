//! src/techniques/blending/depth_peeling.rs and weighted_blended.rs:
//! depth peeling against the over operator composited on the CPU from the
//! known geometry (fragments sorted per pixel), weighted blended against
//! depth peeling with its error stated, the crossed panes that sorting per
//! object gets wrong, one layer (all three agree) and many layers.

use crate::common;
use glam::Vec3;
use gloss::lighting::shade;
use gloss::renderer::Output;
use gloss::scene::{Scene, Transparency};
use std::path::Path;

const W: usize = 64;
const H: usize = 48;
/// Float output, accumulated in 32-bit floats: exact but for float rounding.
const EXACT: f32 = 1e-4;

/// A pane: a plane stood up facing +z, turned `yaw` degrees about the
/// vertical, centred at `z` on the view axis.
struct Pane {
    z: f32,
    yaw: f32,
    diffuse: [f32; 3],
    opacity: f32,
}

/// A perspective camera at (0, 0, 10) looking down -z (fov_y 30), one
/// directional light, no specular: a pane's colour does not depend on where
/// it is hit, only on its normal.
fn scene(panes: &[Pane], transparency: Transparency, layers: u32) -> Scene {
    let mut text = format!(
        r#"
[camera]
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
fov_y = 30.0
near = 1.0
far = 40.0

[render]
size = [{W}, {H}]
ambient = [0.1, 0.1, 0.1]
background = [0.2, 0.3, 0.1]
transparency = "{transparency}"
peel_layers = {layers}

[[lights]]
type = "directional"
direction = [0.3, -0.4, -1.0]
color = [0.9, 0.85, 0.8]
"#
    );
    for (i, p) in panes.iter().enumerate() {
        let [r, g, b] = p.diffuse;
        text += &format!(
            "[materials.m{i}]\ndiffuse = [{r}, {g}, {b}]\nspecular = [0.0, 0.0, 0.0]\nopacity = {}\n\
             [[objects]]\nname = \"p{i}\"\nmesh = \"plane\"\nmaterial = \"m{i}\"\nposition = [0.0, 0.0, {}]\n\
             rotation = [90.0, {}, 0.0]\nscale = [6.0, 1.0, 6.0]\n",
            p.opacity, p.z, p.yaw
        );
    }
    Scene::parse(&text, Path::new("panes.toml")).unwrap()
}

/// The linear colour at GL pixel (x, y) (rows bottom up).
fn pixel(scene: &Scene, x: usize, y: usize) -> Vec3 {
    let lin = common::render(scene, Output::Linear32F);
    assert_eq!((lin.width as usize, lin.height as usize), (W, H));
    let i = (y * W + x) * 4;
    Vec3::new(lin.linear[i], lin.linear[i + 1], lin.linear[i + 2])
}

/// The CPU reference: the ray through pixel (x, y)'s centre meets each
/// pane's plane; the fragments sorted nearest first, the first `layers`
/// of them composited over the background with the over operator.
fn reference(scene: &Scene, panes: &[Pane], x: usize, y: usize, layers: usize) -> Vec3 {
    let eye = scene.camera.eye;
    let t = (15f32.to_radians()).tan();
    let ndc = |p: usize, n: usize| (p as f32 + 0.5) / n as f32 * 2.0 - 1.0;
    let dir = Vec3::new(ndc(x, W) * t * W as f32 / H as f32, ndc(y, H) * t, -1.0);
    let mut hits: Vec<(f32, Vec3, f32)> = panes
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let o = scene
                .objects
                .iter()
                .find(|o| o.name == format!("p{i}"))
                .unwrap();
            let m = &scene.materials[o.material];
            let centre = o.model.transform_point3(Vec3::ZERO);
            let n = o.model.transform_vector3(Vec3::Y).normalize();
            // The plane n . (q - centre) = 0 along eye + s dir.
            let s = n.dot(centre - eye) / n.dot(dir);
            // The side facing the eye (the shader flips a back face's normal).
            let n = if n.dot(eye - centre) < 0.0 { -n } else { n };
            let c = shade(
                &scene.lights,
                scene.render.ambient,
                m,
                m.diffuse,
                centre,
                n,
                eye,
            );
            (s, c, p.opacity)
        })
        .collect();
    hits.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Over, back to front, of the nearest `layers` fragments.
    let mut c = scene.render.background;
    for &(_, colour, alpha) in hits.iter().take(layers).rev() {
        c = colour * alpha + c * (1.0 - alpha);
    }
    c
}

fn err(a: Vec3, b: Vec3) -> f32 {
    (a - b).abs().max_element()
}

/// Facing panes of different colours and opacities, listed in no order.
fn stack(n: usize) -> Vec<Pane> {
    (0..n)
        .map(|i| {
            let k = (i * 3) % n; // scrambled depth order (3 is prime to 4 and 7)
            Pane {
                z: 2.0 - 0.3 * k as f32,
                yaw: 0.0,
                diffuse: [
                    (i % 3 == 0) as u8 as f32 * 0.8 + 0.1,
                    (i % 3 == 1) as u8 as f32 * 0.8 + 0.1,
                    0.1 + 0.07 * (i % 5) as f32,
                ],
                opacity: 0.2 + 0.15 * (i % 4) as f32,
            }
        })
        .collect()
}

#[test]
fn depth_peeling_is_the_over_operator_per_fragment() {
    for (n, layers) in [(1, 1), (4, 4), (4, 8), (7, 64)] {
        let panes = stack(n);
        let s = scene(&panes, Transparency::DepthPeeling, layers);
        let got = pixel(&s, W / 2, H / 2);
        let want = reference(&s, &panes, W / 2, H / 2, layers as usize);
        assert!(
            err(got, want) < EXACT,
            "{n} panes, {layers} layers: peeled {got}, the over operator on the CPU {want}"
        );
    }
}

#[test]
fn depth_peeling_drops_the_fragments_past_its_layers() {
    // Seven panes, three layers: the nearest three over the background.
    let panes = stack(7);
    let s = scene(&panes, Transparency::DepthPeeling, 3);
    let got = pixel(&s, W / 2, H / 2);
    let want = reference(&s, &panes, W / 2, H / 2, 3);
    let all = reference(&s, &panes, W / 2, H / 2, 7);
    assert!(err(got, want) < EXACT, "3 layers: {got}, want {want}");
    assert!(
        err(all, want) > 0.01,
        "the dropped layers must show: {all} vs {want}"
    );
}

#[test]
fn one_layer_all_three_agree() {
    let panes = [Pane {
        z: 0.0,
        yaw: 0.0,
        diffuse: [0.9, 0.2, 0.1],
        opacity: 0.55,
    }];
    let want = reference(
        &scene(&panes, Transparency::Sorted, 1),
        &panes,
        W / 2,
        H / 2,
        1,
    );
    for t in Transparency::ALL {
        let got = pixel(&scene(&panes, *t, 1), W / 2, H / 2);
        assert!(err(got, want) < EXACT, "{t}: {got}, over on the CPU {want}");
    }
}

/// Two panes crossed in an X through the origin (turned +-30 degrees):
/// the left of the image sees one in front, the right the other.
fn crossed() -> Vec<Pane> {
    vec![
        Pane {
            z: 0.0,
            yaw: 30.0,
            diffuse: [0.9, 0.1, 0.05],
            opacity: 0.6,
        },
        Pane {
            z: 0.0,
            yaw: -30.0,
            diffuse: [0.05, 0.2, 0.9],
            opacity: 0.6,
        },
    ]
}

#[test]
fn crossed_panes_sorted_per_object_is_wrong_and_depth_peeling_right() {
    let panes = crossed();
    let (y, columns) = (H / 2, [W / 4, 3 * W / 4]);
    let peeled = scene(&panes, Transparency::DepthPeeling, 2);
    let sorted = scene(&panes, Transparency::Sorted, 2);
    let mut sorted_worst: f32 = 0.0;
    for x in columns {
        let want = reference(&peeled, &panes, x, y, 2);
        let got = pixel(&peeled, x, y);
        assert!(
            err(got, want) < EXACT,
            "column {x}: peeled {got}, want {want}"
        );
        sorted_worst = sorted_worst.max(err(pixel(&sorted, x, y), want));
    }
    // One point per object: one side of the X is blended in the wrong order.
    assert!(
        sorted_worst > 0.05,
        "sorted per object should be wrong on one side of the X, worst error {sorted_worst}"
    );
}

/// Two facing panes, red (alpha 0.8) in front of blue (0.8), `gap` apart.
fn two(gap: f32) -> Vec<Pane> {
    vec![
        Pane {
            z: 0.0,
            yaw: 0.0,
            diffuse: [0.9, 0.1, 0.05],
            opacity: 0.8,
        },
        Pane {
            z: -gap,
            yaw: 0.0,
            diffuse: [0.05, 0.2, 0.9],
            opacity: 0.8,
        },
    ]
}

/// The largest channel error of weighted blended against depth peeling at
/// the centre pixel.
fn weighted_error(panes: &[Pane]) -> f32 {
    let n = panes.len() as u32;
    let exact = pixel(&scene(panes, Transparency::DepthPeeling, n), W / 2, H / 2);
    let weighted = pixel(
        &scene(panes, Transparency::WeightedBlended, n),
        W / 2,
        H / 2,
    );
    err(weighted, exact)
}

#[test]
fn weighted_blended_error_is_bounded_and_grows_where_its_depth_weights_fail() {
    // Far apart (eye distances 10 and 25): the weights (the paper's
    // equation 7) favour the near pane about 3.5 to 1.
    let apart = weighted_error(&two(15.0));
    // Almost together (10 and 10.05): equal weights, an average of the two.
    let together = weighted_error(&two(0.05));
    // The crossed panes: equal depths along the line where they cross.
    let panes = crossed();
    let peeled = pixel(&scene(&panes, Transparency::DepthPeeling, 2), W / 4, H / 2);
    let weighted = pixel(
        &scene(&panes, Transparency::WeightedBlended, 2),
        W / 4,
        H / 2,
    );
    let crossed = err(peeled, weighted);
    eprintln!(
        "weighted blended vs depth peeling: apart {apart}, together {together}, crossed {crossed}"
    );
    assert!(apart < 0.03, "two panes 15 apart: error {apart}");
    assert!(together < 0.3, "two panes 0.05 apart: error {together}");
    assert!(crossed < 0.1, "crossed panes: error {crossed}");
    assert!(
        together > 5.0 * apart,
        "the error should grow as the depths meet: apart {apart}, together {together}"
    );
}

#[test]
fn every_transparency_restores_the_gl_state_in_every_path() {
    use gloss::scene::RenderPath;
    let ctx = common::context(common::backend());
    for t in Transparency::ALL {
        for path in [
            RenderPath::Forward,
            RenderPath::Deferred,
            RenderPath::Prepass,
        ] {
            let mut scene = common::scene("oit.toml");
            scene.render.transparency = *t;
            scene.render.path = path;
            let changed = common::state_left_changed(&ctx, &scene, 96, 54);
            assert!(
                changed.is_empty(),
                "{t}, {path:?}:\n  {}",
                changed.join("\n  ")
            );
        }
    }
}

#[test]
fn the_plan_has_only_the_chosen_technique_and_its_targets() {
    use gloss::techniques::plan;
    let mut scene = common::scene("oit.toml");
    for (t, passes, targets) in [
        (Transparency::Sorted, &["transparency"][..], &[][..]),
        (
            Transparency::WeightedBlended,
            &["oit_accumulate", "oit_composite"][..],
            &["oit_accumulation"][..],
        ),
        (
            Transparency::DepthPeeling,
            &["peel_layers", "peel_composite"][..],
            &["peel_even", "peel_odd", "peeled_layers"][..],
        ),
    ] {
        scene.render.transparency = t;
        let p = plan(&scene);
        let names: Vec<&str> = p.passes.iter().map(|p| p.name).collect();
        let all = [
            "transparency",
            "oit_accumulate",
            "oit_composite",
            "peel_layers",
            "peel_composite",
        ];
        for n in all {
            assert_eq!(
                names.contains(&n),
                passes.contains(&n),
                "{t}: pass {n} in {names:?}"
            );
        }
        for n in ["oit_accumulation", "peel_even", "peel_odd", "peeled_layers"] {
            assert_eq!(
                p.target(n).is_some(),
                targets.contains(&n),
                "{t}: target {n}"
            );
        }
    }
    // No glass: no pass and no target, whatever is chosen.
    let mut plain = common::scene("default.toml");
    plain.render.transparency = Transparency::DepthPeeling;
    let p = plan(&plain);
    assert!(p.target("peeled_layers").is_none() && !p.has_pass("peel_layers"));
}

#[test]
fn msaa_with_an_order_independent_technique_is_refused_by_name() {
    let camera = "[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n";
    let text = format!("{camera}[render]\nmsaa = 4\ntransparency = \"depth_peeling\"\n");
    let e = Scene::parse(&text, Path::new("msaa.toml")).unwrap_err();
    let msg = format!("{e:#}");
    assert!(
        msg.contains("render.transparency") && msg.contains("render.msaa = 1"),
        "{msg}"
    );
    let text = format!("{camera}[render]\npeel_layers = 65\n");
    let e = Scene::parse(&text, Path::new("layers.toml")).unwrap_err();
    assert!(format!("{e:#}").contains("render.peel_layers"), "{e:#}");
}
