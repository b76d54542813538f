//! Keyframe tracks: the keys are hit, the rules hold between them, and bad
//! tracks are refused with a message.

use super::*;
use crate::math::slerp::rotation_between;

fn v(x: f32) -> Vec3 {
    Vec3::new(x, 2.0 * x, -x)
}

fn track(i: Interpolation) -> Track<Vec3> {
    Track::new(
        "t",
        vec![0.0, 1.0, 3.0, 4.0],
        vec![v(0.0), v(1.0), v(-1.0), v(2.0)],
        i,
    )
    .unwrap()
}

#[test]
fn every_rule_passes_through_its_keys_and_holds_beyond_the_ends() {
    for i in [
        Interpolation::Step,
        Interpolation::Linear,
        Interpolation::Cubic,
    ] {
        let tr = track(i);
        for (t, want) in [(0.0, 0.0), (1.0, 1.0), (3.0, -1.0), (4.0, 2.0)] {
            assert!((tr.sample(t) - v(want)).length() < 1e-6, "{i:?} at {t}");
        }
        assert_eq!(tr.sample(-5.0), v(0.0));
        assert_eq!(tr.sample(10.0), v(2.0));
        assert_eq!(tr.sample(f32::NAN), v(0.0));
        assert_eq!(tr.span(), (0.0, 4.0));
    }
}

#[test]
fn step_holds_and_linear_goes_straight() {
    let s = track(Interpolation::Step);
    assert_eq!(s.sample(0.999), v(0.0));
    assert_eq!(s.sample(2.0), v(1.0));
    let l = track(Interpolation::Linear);
    assert!((l.sample(0.25) - v(0.25)).length() < 1e-6);
    assert!(
        (l.sample(2.0) - v(0.0)).length() < 1e-6,
        "halfway from 1 to -1"
    );
}

#[test]
fn cubic_has_no_corner_at_a_key_and_keeps_a_constant_speed() {
    let c = track(Interpolation::Cubic);
    // The slope just before and just after the key at t = 1 agree.
    let h = 1e-3;
    let before = (c.sample(1.0) - c.sample(1.0 - h)) / h;
    let after = (c.sample(1.0 + h) - c.sample(1.0)) / h;
    assert!((before - after).length() < 0.05, "{before} vs {after}");
    // Linear keys (unevenly spaced in time, evenly in speed) stay linear.
    let times = vec![0.0, 0.5, 2.0, 2.25];
    let values: Vec<Vec3> = times.iter().map(|&t| v(3.0 * t)).collect();
    let even = Track::new("even", times, values, Interpolation::Cubic).unwrap();
    for k in 0..=45 {
        let t = k as f32 * 0.05;
        assert!((even.sample(t) - v(3.0 * t)).length() < 1e-4, "t {t}");
    }
}

#[test]
fn a_single_key_is_a_constant() {
    for i in [
        Interpolation::Step,
        Interpolation::Linear,
        Interpolation::Cubic,
    ] {
        let tr = Track::new("one", vec![2.0], vec![v(7.0)], i).unwrap();
        for t in [-1.0, 2.0, 5.0] {
            assert_eq!(tr.sample(t), v(7.0));
        }
    }
}

#[test]
fn rotations_take_the_shortest_arc_and_stay_unit() {
    let y = |deg: f32| Quat::from_rotation_y(deg.to_radians());
    // The third key is stored with the other sign: the same rotation.
    let keys = vec![y(0.0), y(90.0), -y(180.0), y(270.0)];
    for i in [Interpolation::Linear, Interpolation::Cubic] {
        let tr = Track::new("r", vec![0.0, 1.0, 2.0, 3.0], keys.clone(), i).unwrap();
        for k in 0..=30 {
            let t = k as f32 * 0.1;
            let q = tr.sample(t);
            assert!((q.length() - 1.0).abs() < 1e-5, "{i:?} t {t}");
            // A quarter turn a second about y, whichever sign the keys have.
            let want = y(90.0 * t);
            let off = rotation_between(q, want).to_degrees();
            // Catmull-Rom on the components, normalised, is not a constant
            // rate: with keys a quarter turn apart it stays within 2°.
            let allowed = if i == Interpolation::Linear {
                1e-3
            } else {
                2.0
            };
            assert!(off < allowed, "{i:?} t {t}: {off} degrees off");
        }
    }
}

#[test]
fn bad_tracks_are_refused_with_a_message() {
    let msg = |r: Result<Track<Vec3>>| format!("{:#}", r.unwrap_err());
    let lin = Interpolation::Linear;
    assert!(msg(Track::new("a", vec![], vec![], lin)).contains("at least one key"));
    assert!(
        msg(Track::new("a", vec![0.0, 1.0], vec![v(0.0)], lin)).contains("2 times but 1 values")
    );
    assert!(
        msg(Track::new("a", vec![0.0, f32::NAN], vec![v(0.0); 2], lin)).contains("time 1 is NaN")
    );
    let back = msg(Track::new(
        "objects[2].position",
        vec![0.0, 1.0, 1.0],
        vec![v(0.0); 3],
        lin,
    ));
    assert!(
        back.contains("objects[2].position") && back.contains("times must increase"),
        "{back}"
    );
    let nan = msg(Track::new("a", vec![0.0], vec![Vec3::NAN], lin));
    assert!(nan.contains("value 0 is not finite"), "{nan}");
    let zero = Track::new(
        "r",
        vec![0.0],
        vec![Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)],
        lin,
    );
    assert!(format!("{:#}", zero.unwrap_err()).contains("zero"));
}
