//! The demo's keys that change a render setting, as data: the key as the
//! demo's key table (src/demo/keys.rs) names it, the knob it changes, and
//! how. The "Try it" blocks of docs/ (src/trace/try_it.rs) name a
//! technique's keys from here; tests/trace/try_it.rs checks every entry
//! against the demo's own handling of the key, so the two cannot drift.

use super::{AREA_LIGHTS, Knob, PATH, SHADING, STENCIL_VOLUMES};

/// What pressing the key does to its knob.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyEffect {
    /// Sets the knob to its choice `i`.
    Choose(usize),
    /// The next choice, round.
    Next,
    /// A yes/no knob flipped.
    Toggle,
}

pub struct KnobKey {
    /// As the demo's key table names it ("3", "G").
    pub key: &'static str,
    pub knob: &'static Knob,
    pub effect: KeyEffect,
}

const fn k(key: &'static str, knob: &'static Knob, effect: KeyEffect) -> KnobKey {
    KnobKey { key, knob, effect }
}

/// Every demo key that changes a render setting.
pub static KNOB_KEYS: &[KnobKey] = &[
    k("1", &PATH, KeyEffect::Choose(0)),
    k("2", &PATH, KeyEffect::Choose(1)),
    k("3", &PATH, KeyEffect::Choose(2)),
    k("4", &PATH, KeyEffect::Choose(3)),
    k("G", &SHADING, KeyEffect::Next),
    k("V", &STENCIL_VOLUMES, KeyEffect::Toggle),
    k("L", &AREA_LIGHTS, KeyEffect::Toggle),
];
