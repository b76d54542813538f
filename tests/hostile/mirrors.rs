//! Mirrors in mirrors are bounded by what each mirror can see
//! (src/scene/mirror_views.rs) and by a total view budget.

use crate::{contains_all, gloss_in, temp_dir, write};

/// `n` mirrors standing in a ring of radius 5 around the camera, each
/// facing the centre, `depth` levels deep: every mirror sees the others.
fn ring(n: usize, depth: u32) -> String {
    let mut s = format!(
        r#"name = "ring"

[camera]
eye = [0.0, 1.5, 0.5]
target = [0.0, 1.4, -5.0]
fov_y = 60.0
near = 0.1
far = 60.0

[render]
size = [64, 48]
mirror_depth = {depth}

[[lights]]
type = "point"
position = [0.0, 3.0, 0.0]
color = [1.0, 1.0, 1.0]

[materials.red]
diffuse = [0.8, 0.1, 0.1]

[[objects]]
name = "floor"
mesh = "plane"
scale = [12.0, 1.0, 12.0]

[[objects]]
name = "ball"
mesh = "sphere"
material = "red"
position = [1.0, 1.0, -1.0]
scale = [0.5, 0.5, 0.5]
"#
    );
    for i in 0..n {
        let a = i as f32 / n as f32 * std::f32::consts::TAU;
        let (x, z) = (5.0 * a.sin(), 5.0 * a.cos());
        let yaw = a.to_degrees() + 180.0;
        s += &format!(
            "\n[[objects]]\nname = \"m{i}\"\nmesh = \"plane\"\nposition = [{x}, 1.5, {z}]\n\
             rotation = [90.0, {yaw}, 0.0]\nscale = [1.2, 1.0, 1.2]\nmirror = {{ reflectance = 0.9 }}\n"
        );
    }
    s
}

/// The reflected views a plan lists ("views:" then "  0. camera", ...).
fn views(plan: &str) -> usize {
    plan.lines()
        .skip_while(|l| *l != "views:")
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .count()
        .saturating_sub(1)
}

#[test]
fn many_mirrors_at_depth_8_end_in_bounded_time_and_memory() {
    let dir = temp_dir("mirror_ring");
    for n in [5usize, 6, 16] {
        let name = format!("ring{n}.toml");
        write(&dir, &name, ring(n, 8));
        for command in ["plan", "render"] {
            let mut args = vec![command, name.as_str()];
            if command == "render" {
                args.extend(["-o", "out.png"]);
            }
            let run = gloss_in(&dir, &args, &["out.png"]);
            if run.status.success() {
                assert!(views(&run.stdout) <= 256 || command == "render");
            } else {
                contains_all(
                    run.failed(),
                    &[
                        &name,
                        "render.mirror_depth = 8",
                        &format!("the {n} mirrors see each other in more than 256 reflected views"),
                        "they fit at render.mirror_depth = ",
                    ],
                );
            }
        }
    }
    // At the depth the message offers, the ring of five renders.
    let run = gloss_in(&dir, &["plan", "ring5.toml"], &["out.png"]);
    let msg = run.stderr.clone();
    if let Some(at) = msg.find("they fit at render.mirror_depth = ") {
        let depth: u32 = msg[at + 34..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect::<String>()
            .parse()
            .unwrap();
        let set = format!("render.mirror_depth={depth}");
        let run = gloss_in(
            &dir,
            &["render", "ring5.toml", "--set", &set, "-o", "out.png"],
            &["out.png"],
        );
        run.succeeded();
    }
}

/// Two mirrors facing each other across the camera, which looks at one:
/// the camera sees one mirror, that reflection sees the other, and so on,
/// one view a level: 8 views at depth 8 (without the test, each level
/// held both mirrors' views: 16).
#[test]
fn a_corridor_of_two_mirrors_needs_one_view_a_level() {
    let dir = temp_dir("mirror_corridor");
    let scene = r#"name = "corridor"

[camera]
eye = [0.0, 1.5, 0.0]
target = [0.0, 1.5, -5.0]
fov_y = 50.0
near = 0.1
far = 80.0

[render]
size = [64, 48]
mirror_depth = 8

[[lights]]
type = "directional"
direction = [0.0, -1.0, -0.2]

[[objects]]
name = "floor"
mesh = "plane"
scale = [4.0, 1.0, 8.0]

[[objects]]
name = "front"
mesh = "plane"
position = [0.0, 1.5, -5.0]
rotation = [90.0, 0.0, 0.0]
mirror = {}

[[objects]]
name = "back"
mesh = "plane"
position = [0.0, 1.5, 5.0]
rotation = [90.0, 180.0, 0.0]
mirror = {}
"#;
    write(&dir, "corridor.toml", scene);
    let run = gloss_in(&dir, &["plan", "corridor.toml"], &[]);
    run.succeeded();
    assert_eq!(views(&run.stdout), 8, "{}", run.stdout);
    // Each level alternates: front, then back seen in front, ...
    assert!(run.stdout.contains("in mirror 'back', in mirror 'front'"));
    assert!(!run.stdout.contains("\n  1. in mirror 'back'\n"));
}
