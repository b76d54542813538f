//! src/scene/animation.rs and src/math/keyframes.rs driving objects: at any
//! instant each animated object has the transform its tracks give, its
//! children follow through the model matrices, and the instant comes from
//! the file, `--set animation.time` or `--time`, never the clock.

use crate::common;
use glam::{Mat4, Quat, Vec3};
use gloss::math::slerp::rotation_between;
use gloss::renderer::Output;

fn close(a: Mat4, b: Mat4) -> bool {
    a.abs_diff_eq(b, 1e-5)
}

#[test]
fn each_instant_poses_the_objects_as_the_keys_say() {
    let mut s = common::scene("animated-hierarchy.toml");
    let index = |s: &gloss::scene::Scene, name: &str| {
        s.objects.iter().position(|o| o.name == name).unwrap()
    };
    let (boxi, ball, knot) = (index(&s, "box"), index(&s, "ball"), index(&s, "knot"));
    // The file's instant.
    assert_eq!(s.animation.time, 0.75);
    assert_eq!(s.animation.span(), Some((0.0, 2.0)));
    // Halfway between the box's first two keys: halfway along, and turned
    // 45° about y (slerp from 0° to 90°).
    s.set_time(0.5).unwrap();
    let b = &s.objects[boxi];
    assert!((b.position - Vec3::new(-1.0, 0.5, 0.5)).length() < 1e-6);
    let turned = b.orientation.unwrap();
    assert!(rotation_between(turned, Quat::from_rotation_y(45f32.to_radians())) < 1e-5);
    let want = Mat4::from_translation(b.position) * Mat4::from_quat(turned);
    assert!(close(b.model, want), "{}", b.model);
    // The child follows: its model is the box's times its own local one.
    let child = &s.objects[ball];
    assert!(close(child.model, s.objects[boxi].model * child.local()));
    // On a key the cubic spin is exactly that key, half a turn about y at
    // 1 s; the tumble is halfway, a quarter turn about x; the knot is
    // their 70/30 blend.
    s.set_time(1.0).unwrap();
    let k = &s.objects[knot];
    let spin = Quat::from_rotation_y(std::f32::consts::PI);
    let tumble = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let blend = (spin * 0.7 + tumble * 0.3).normalize();
    assert!(rotation_between(k.orientation.unwrap(), blend) < 1e-5);
    assert!((k.scale - Vec3::splat(0.8)).length() < 1e-6);
    // Before the first key and after the last, the end keys hold.
    s.set_time(-3.0).unwrap();
    assert!((s.objects[boxi].position - Vec3::new(-2.0, 0.5, 0.0)).length() < 1e-6);
    s.set_time(9.0).unwrap();
    assert!((s.objects[boxi].position - Vec3::new(-2.0, 0.5, 0.0)).length() < 1e-6);
    // A time that is not a number is refused and changes nothing.
    let before = s.objects[boxi].model;
    assert!(s.set_time(f32::NAN).is_err());
    assert_eq!(s.animation.time, 9.0);
    assert_eq!(s.objects[boxi].model, before);
}

#[test]
fn the_time_from_the_command_line_is_the_time_set_on_the_scene() {
    let path = common::root().join("scenes/animated-hierarchy.toml");
    let from_set = gloss::scene::Scene::load_with(&path, &["animation.time=1.5".into()]).unwrap();
    let mut from_api = common::scene("animated-hierarchy.toml");
    from_api.set_time(1.5).unwrap();
    let a = common::render(&from_set, Output::Srgb8).image;
    let b = common::render(&from_api, Output::Srgb8).image;
    assert!(a == b, "--set animation.time=1.5 and set_time(1.5) differ");
    let file = common::render(&common::scene("animated-hierarchy.toml"), Output::Srgb8).image;
    assert!(a != file, "1.5 s looks like the file's 0.75 s");
    // `gloss render --time 1.5` writes the same image.
    let out = std::env::temp_dir().join("gloss-animation-time.png");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args([
            "render",
            "scenes/animated-hierarchy.toml",
            "--time",
            "1.5",
            "-o",
        ])
        .arg(&out)
        .current_dir(common::root())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let written = image::open(&out).unwrap().to_rgba8();
    assert!(
        written == a,
        "gloss render --time 1.5 differs from the scene at 1.5 s"
    );
}

#[test]
fn clips_blend_by_weight_and_the_file_pose_takes_what_is_left() {
    let path = common::root().join("scenes/animated-hierarchy.toml");
    let at = |weights: &[&str]| {
        let mut o: Vec<String> = weights
            .iter()
            .map(|w| format!("animation.weights.{w}"))
            .collect();
        o.push("animation.time=1.0".into());
        let s = gloss::scene::Scene::load_with(&path, &o).unwrap();
        let k = s.objects.iter().find(|o| o.name == "knot").unwrap().clone();
        (k.orientation.unwrap(), k.scale)
    };
    let spin = Quat::from_rotation_y(std::f32::consts::PI);
    let tumble = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    // One clip at full weight: that clip alone.
    let (r, _) = at(&["spin=1", "tumble=0"]);
    assert!(rotation_between(r, spin) < 1e-5);
    let (r, _) = at(&["spin=0", "tumble=1"]);
    assert!(rotation_between(r, tumble) < 1e-5);
    // Both at 0: the pose the file gives the knot (no rotation, scale 0.8).
    let (r, scale) = at(&["spin=0", "tumble=0"]);
    assert!(rotation_between(r, Quat::IDENTITY) < 1e-5);
    assert!((scale - Vec3::splat(0.8)).length() < 1e-6);
    // Weights above 1 in all are normalised: 2 and 2 is an even blend.
    let (r, _) = at(&["spin=2", "tumble=2"]);
    assert!(rotation_between(r, (spin + tumble).normalize()) < 1e-5);
    // Spin alone at 0.5: halfway between rest and the spin's key (and the
    // spin's scale, 1.0 at 1 s... 0.8 there: halfway from 0.8 to 0.8).
    let (r, _) = at(&["spin=0.5", "tumble=0"]);
    let half = (Quat::IDENTITY * 0.5 + spin * 0.5).normalize();
    assert!(rotation_between(r, half) < 1e-5);
}
