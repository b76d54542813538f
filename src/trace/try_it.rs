//! The "Try it" part of a docs block: the commands, and how to reach the
//! technique in the demo, derived from the code so that it cannot drift:
//!
//! * which settings switch it on: every yes/no or choice knob
//!   (src/scene/knobs.rs) whose other values take the technique's passes
//!   out of the frame (its `passes` asked with each value), with the
//!   demo's key for it (src/scene/knobs/keys.rs, checked against the
//!   demo's key handling by tests/trace/try_it.rs);
//! * the settings it reads (its registration's knobs, the panel's
//!   Techniques section shows them beside it);
//! * the inspector views of the targets its passes write and read (the
//!   inspector lists the frame plan's targets, src/demo/inspect_views.rs).

use crate::frame::Technique;
use crate::frame::lights::FrameLights;
use crate::frame::targets::{Depth, HDR, OUTPUT};
use crate::scene::Scene;
use crate::scene::knobs::keys::{KNOB_KEYS, KeyEffect};
use crate::scene::knobs::{self, Kind, Knob, Value};
use crate::techniques;
use std::fmt::Write as _;

/// A value of a knob in words: "on", "volumes".
fn word(knob: &Knob, v: Value) -> String {
    match (v, knob.kind) {
        (Value::Bool(b), _) => if b { "on" } else { "off" }.to_string(),
        (Value::Choice(i), Kind::Choice(words)) => words.get(i).unwrap_or(&"?").to_string(),
        _ => "?".to_string(),
    }
}

/// `a, b or c`.
fn either(words: &[String]) -> String {
    match words {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
    }
}

/// The other values of a yes/no or choice knob (none for numbers).
fn others(knob: &Knob, now: Value) -> Vec<Value> {
    match (knob.kind, now) {
        (Kind::Bool, Value::Bool(b)) => vec![Value::Bool(!b)],
        (Kind::Choice(words), Value::Choice(i)) => (0..words.len())
            .filter(|&j| j != i)
            .map(Value::Choice)
            .collect(),
        _ => vec![],
    }
}

/// Whether `t` is in a frame of `scene`: it adds a pass, or it orders the
/// frame (mirrors, split views: their passes come with the order).
fn runs(t: &Technique, scene: &Scene) -> bool {
    let lights = FrameLights::new(scene);
    !(t.passes)(scene, &lights).is_empty() || t.order.is_some_and(|o| o(scene, &lights).is_some())
}

/// The knobs whose value in `scene` keeps `t` in the frame: (knob, its
/// value now, the values that take it out).
pub fn switches(t: &Technique, scene: &Scene) -> Vec<(&'static Knob, Value, Vec<Value>)> {
    let mut seen: Vec<&str> = Vec::new();
    let mut out = Vec::new();
    for &knob in knobs::ALL.iter().chain(t.knobs) {
        if seen.contains(&knob.key) {
            continue;
        }
        seen.push(knob.key);
        let now = (knob.get)(&scene.render);
        let off: Vec<Value> = others(knob, now)
            .into_iter()
            .filter(|&v| {
                let mut other = scene.clone();
                (knob.set)(&mut other.render, v);
                !runs(t, &other)
            })
            .collect();
        if !off.is_empty() {
            out.push((knob, now, off));
        }
    }
    out
}

/// The demo key that gives `knob` the value `now`, in words.
fn key_for(knob: &Knob, now: Value) -> Option<String> {
    KNOB_KEYS
        .iter()
        .filter(|k| k.knob.key == knob.key)
        .find_map(|k| match (k.effect, now) {
            (KeyEffect::Choose(i), Value::Choice(j)) if i == j => Some(format!("key {}", k.key)),
            (KeyEffect::Next, _) => Some(format!("key {} cycles it", k.key)),
            (KeyEffect::Toggle, _) => Some(format!("key {} toggles it", k.key)),
            _ => None,
        })
}

/// The inspector's views of what `t`'s passes write and read in a frame
/// of `scene`: `target.attachment` as the inspector labels them.
pub fn views(t: &Technique, scene: &Scene) -> Vec<String> {
    let plan = techniques::plan(scene);
    let Some(index) = techniques::ALL.iter().position(|x| x.name == t.name) else {
        return vec![];
    };
    let mut names: Vec<&str> = Vec::new();
    for p in plan.passes.iter().filter(|p| p.technique == index) {
        for n in std::iter::once(p.target).chain(p.reads.iter().copied()) {
            if !names.contains(&n) {
                names.push(n);
            }
        }
    }
    let mut out = Vec::new();
    for n in names {
        match plan.targets.iter().find(|d| d.name == n) {
            // A multisampled target is shown through its resolve.
            Some(d) if d.samples > 1 => {}
            Some(d) => {
                out.extend(d.colors.iter().map(|(a, _)| format!("`{n}.{a}`")));
                if let Depth::Own(format) = d.depth {
                    out.push(format!("`{n}.depth`"));
                    // The world's target's stencil (where mirrors mark
                    // their regions), read back by the inspector.
                    if format == glow::DEPTH24_STENCIL8 && [OUTPUT, HDR].contains(&n) {
                        out.push(format!("`{n}.stencil`"));
                    }
                }
            }
            // The inspector's first views: each casting light's map.
            None if n == "shadow map" => out.push("`shadow map: light N`".to_string()),
            None => {}
        }
    }
    out
}

/// The "Try it" text for the techniques `names` of the block of `scene`
/// (`set`: the block's `--set` arguments; `listing`: its trace command).
pub fn text(
    scene_name: &str,
    set: &[String],
    scene: &Scene,
    names: &[&str],
    listing: &str,
) -> String {
    let sets: String = set.iter().map(|kv| format!(" --set {kv}")).collect();
    let mut s = format!(
        "\nTry it:\n\n```sh\ngloss{sets} {scene_name}                 # the demo: the panel switches, inspects and times each pass\n\
         gloss plan {scene_name}{sets}            # the passes and targets this frame runs\n{listing}   # this listing\n```\n"
    );
    for t in techniques::ALL.iter().filter(|t| names.contains(&t.name)) {
        let _ = write!(s, "\nIn the demo, `{}`", t.name);
        let on = switches(t, scene);
        if on.is_empty() {
            s += " runs whenever the scene has what it draws (no render setting turns it off)";
        } else {
            s += " runs while";
            for (i, (knob, now, off)) in on.iter().enumerate() {
                let off: Vec<String> = off.iter().map(|&v| word(knob, v)).collect();
                let key = key_for(knob, *now).map_or(String::new(), |k| format!(", {k}"));
                let _ = write!(
                    s,
                    "{} the panel's \"{}\" (`{}`) is {}{key} ({} turns it off)",
                    if i == 0 { "" } else { ";" },
                    knob.label,
                    knob.key,
                    word(knob, *now),
                    either(&off)
                );
            }
        }
        s += ".";
        if !t.knobs.is_empty() {
            let read: Vec<String> = t.knobs.iter().map(|k| format!("\"{}\"", k.label)).collect();
            let _ = write!(
                s,
                " The panel's Techniques section shows it with the settings it reads: {}.",
                read.join(", ")
            );
        }
        let v = views(t, scene);
        if !v.is_empty() {
            let _ = write!(
                s,
                " The pass inspector (key I, or the panel's \"Pass inspector\") shows what its passes write and read: {}.",
                v.join(", ")
            );
        }
        s += "\n";
    }
    s
}
