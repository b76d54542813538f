//! The "Try it" part of every docs block (src/trace/try_it.rs): the demo
//! keys it names are the demo's, and what it derives for a technique is
//! what the frame does.

use gloss::scene::knobs::keys::{KNOB_KEYS, KeyEffect};
use gloss::scene::knobs::{self, Value};
use gloss::scene::{RenderPath, Shading};
use gloss::trace::docs::Request;
use gloss::trace::try_it::{switches, views};

/// The demo's key table and key handling, as its source has them
/// (src/demo/keys.rs is private to the demo; its `action` maps a key to a
/// `KeyAction` in one arm a key: `"3" => KeyAction::Path(2),`).
fn demo_keys() -> String {
    std::fs::read_to_string(crate::common::root().join("src/demo/keys.rs")).unwrap()
}

/// The arm of the demo's `action` for the key `c` (lower case), if any.
fn arm(source: &str, c: &str) -> Option<String> {
    let needle = format!("\"{c}\" => KeyAction::");
    let at = source.find(&needle)? + needle.len() - "KeyAction::".len();
    let end = source[at..].find(',')? + at;
    Some(source[at..end].trim().to_string())
}

#[test]
fn every_key_the_docs_name_does_what_the_demo_does_with_it() {
    let source = demo_keys();
    for k in KNOB_KEYS {
        let expected = match (k.knob.key, k.effect) {
            ("render.path", KeyEffect::Choose(i)) => format!("KeyAction::Path({i})"),
            ("render.shading", KeyEffect::Next) => "KeyAction::NextShading".to_string(),
            ("render.stencil_volumes", KeyEffect::Toggle) => "KeyAction::ToggleStencil".to_string(),
            ("render.area_lights", KeyEffect::Toggle) => "KeyAction::ToggleAreaLights".to_string(),
            other => panic!("{}: the demo has no action {other:?}", k.key),
        };
        assert_eq!(
            arm(&source, &k.key.to_lowercase()),
            Some(expected),
            "src/demo/keys.rs: key {}",
            k.key
        );
        // The demo's key table (shown in the panel and by F1) lists it.
        let listed = source.lines().any(|l| {
            let l = l.trim();
            l.starts_with('(')
                && l.split('"')
                    .nth(1)
                    .is_some_and(|keys| keys.split_whitespace().any(|x| x == k.key))
                || l.starts_with('"')
                    && l.trim_end_matches(',')
                        .trim_matches('"')
                        .split_whitespace()
                        .any(|x| x == k.key)
        });
        assert!(listed, "src/demo/keys.rs's KEYS does not list {}", k.key);
        // The knob's value is the one the demo's action sets (src/demo/actions.rs:
        // RenderPath::ALL[i], the next of Shading::ALL, stencil volumes flipped).
        let mut r = Request::parse("default").unwrap().load().unwrap().render;
        match k.effect {
            KeyEffect::Choose(i) => {
                (k.knob.set)(&mut r, Value::Choice(i));
                assert_eq!(r.path, RenderPath::ALL[i]);
            }
            KeyEffect::Next => {
                let before = r.shading;
                let i = Shading::ALL.iter().position(|&s| s == before).unwrap();
                let next = Shading::ALL[(i + 1) % Shading::ALL.len()];
                let Value::Choice(j) = (k.knob.get)(&r) else {
                    panic!("{} is not a choice", k.knob.key)
                };
                let knobs::Kind::Choice(words) = k.knob.kind else {
                    panic!("{} is not a choice", k.knob.key)
                };
                (k.knob.set)(&mut r, Value::Choice((j + 1) % words.len()));
                assert_eq!(r.shading, next);
            }
            KeyEffect::Toggle => {
                // The field the demo's action flips (src/demo/actions.rs).
                let field = |r: &gloss::scene::RenderSettings| match k.knob.key {
                    "render.stencil_volumes" => r.stencil_volumes,
                    "render.area_lights" => r.area_lights,
                    other => panic!("{other}: which field does the demo flip?"),
                };
                let before = field(&r);
                (k.knob.set)(&mut r, Value::Bool(!before));
                assert_ne!(field(&r), before);
            }
        }
    }
    // Every key of the demo that changes a setting is named here.
    for c in "abcdefghijklmnopqrstuvwxyz0123456789".chars() {
        let c = c.to_string();
        let Some(a) = arm(&source, &c) else { continue };
        if ["Path(", "NextShading", "ToggleStencil", "ToggleAreaLights"]
            .iter()
            .any(|x| a.contains(x))
        {
            assert!(
                KNOB_KEYS.iter().any(|k| k.key.eq_ignore_ascii_case(&c)),
                "the demo's key {c} ({a}) changes a setting that src/scene/knobs/keys.rs does not list"
            );
        }
    }
}

#[test]
fn light_volumes_are_switched_on_by_the_path_and_off_by_the_stencil_knob() {
    let scene = Request::parse("mixed-lights").unwrap().load().unwrap();
    let t = gloss::techniques::ALL
        .iter()
        .find(|t| t.name == "light_volumes")
        .unwrap();
    let on = switches(t, &scene);
    let keys: Vec<&str> = on.iter().map(|(k, _, _)| k.key).collect();
    assert_eq!(keys, ["render.path", "render.stencil_volumes"], "{keys:?}");
    let (_, now, off) = &on[0];
    let volumes = RenderPath::ALL
        .iter()
        .position(|&p| p == RenderPath::Volumes)
        .unwrap();
    assert_eq!(*now, Value::Choice(volumes));
    assert_eq!(off.len(), RenderPath::ALL.len() - 1);
    assert_eq!(on[1].1, Value::Bool(false));
    // It writes the light accumulation target.
    let v = views(t, &scene);
    assert!(
        v.iter().any(|x| x.starts_with("`light_accumulation.")),
        "{v:?}"
    );
    // The shadow map runs whatever the settings: no knob switches it.
    let shadows = Request::parse("shadows-spot").unwrap().load().unwrap();
    let sm = gloss::techniques::ALL
        .iter()
        .find(|t| t.name == "shadow_map")
        .unwrap();
    assert!(switches(sm, &shadows).is_empty());
    assert!(views(sm, &shadows).contains(&"`shadow map: light N`".to_string()));
    // A technique that orders the frame (mirrors) has its passes through
    // the order: no setting of a mirror scene takes it out.
    let mirrors = Request::parse("mirror-normal-first")
        .unwrap()
        .load()
        .unwrap();
    let mirror = gloss::techniques::ALL
        .iter()
        .find(|t| t.name == "mirror")
        .unwrap();
    let on = switches(mirror, &mirrors);
    assert!(
        on.is_empty(),
        "{:?}",
        on.iter().map(|s| s.0.key).collect::<Vec<_>>()
    );
    // Its stencil marks are a view of their own.
    let v = views(mirror, &mirrors);
    assert!(v.contains(&"`output.stencil`".to_string()), "{v:?}");
}

/// The arm reader sees the key's action, so a changed key table fails.
#[test]
fn the_demo_key_reader_reads_one_arm() {
    let source =
        "            \"3\" => KeyAction::Path(1),\n            \"g\" => KeyAction::NextShading,\n";
    assert_eq!(arm(source, "3").as_deref(), Some("KeyAction::Path(1)"));
    assert_eq!(arm(source, "g").as_deref(), Some("KeyAction::NextShading"));
    assert_eq!(arm(source, "v"), None);
    // KNOB_KEYS says key 3 is the third path: this source would fail the check.
    let three = KNOB_KEYS.iter().find(|k| k.key == "3").unwrap();
    assert_eq!(three.effect, KeyEffect::Choose(2));
}

/// Whether `t` adds a pass to (or orders) a frame of `scene`, as the demo's
/// panel sees it (src/demo/panel/mod.rs `technique_section`).
fn in_frame(t: &gloss::frame::Technique, scene: &gloss::scene::Scene) -> bool {
    let lights = gloss::frame::lights::FrameLights::new(scene);
    !(t.passes)(scene, &lights).is_empty() || t.order.is_some_and(|o| o(scene, &lights).is_some())
}

/// The render knobs the demo's panel shows for `scene` in its Techniques
/// section: the path, the knobs of every technique in the frame, and the
/// switches (`knobs::SWITCHES`) of techniques switched off.
fn panel_knobs(scene: &gloss::scene::Scene) -> Vec<&'static str> {
    let mut shown = vec![knobs::PATH.key];
    for t in gloss::techniques::ALL.iter().filter(|t| in_frame(t, scene)) {
        shown.extend(t.knobs.iter().map(|k| k.key));
    }
    for (k, applies) in knobs::SWITCHES {
        if applies(scene) {
            shown.push(k.key);
        }
    }
    shown
}

/// A student who switches a technique off in the panel can switch it on
/// again there: for every technique, on its own scene, every setting that
/// takes it out of the frame leaves that setting's knob in the panel.
#[test]
fn every_switch_that_takes_a_technique_out_stays_in_the_panel() {
    let mut missing = Vec::new();
    for t in gloss::techniques::ALL {
        let scene = Request::parse(t.scene)
            .and_then(|r| r.load())
            .unwrap_or_else(|e| panic!("{}: {}: {e:#}", t.name, t.scene));
        for (knob, _, off) in switches(t, &scene) {
            for v in off {
                let mut other = scene.clone();
                (knob.set)(&mut other.render, v);
                if !panel_knobs(&other).contains(&knob.key) {
                    missing.push(format!("{} ({}): {} = {v:?}", t.name, t.scene, knob.key));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "switched off by these, the technique leaves the panel with its switch \
         (add it to knobs::SWITCHES):\n  {}",
        missing.join("\n  ")
    );
}
