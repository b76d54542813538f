//! `--set` keys and scene tables of any shape, deep ones included: the
//! loader never panics or overflows its stack, and its message is short.
//! Keys are the scenes' own, made deeper (up to hundreds of dotted parts),
//! indexed oddly, or arbitrary; values are any, or nested hundreds deep;
//! scene text gains dotted keys, table headers, arrays and inline tables
//! nested hundreds deep. Each property runs for at most `TIME_BOUND` (then
//! takes its remaining inputs as passed), so the suite's time is bounded.
//!
//! Kept inputs: tests/fuzz/regressions/scene-set/ (`# --set` lines, then
//! the scene), replayed by `regressions`.

use crate::run;
use crate::scene::{any_value, case_file, check, seeds, vocabulary};
use proptest::prelude::*;
use std::time::{Duration, Instant};

/// The most time one property spends on its inputs.
pub const TIME_BOUND: Duration = Duration::from_secs(20);

/// A key: one the scenes write, that key with more parts after it, one
/// with odd indices, or parts of any shape and number.
fn any_key() -> impl Strategy<Value = String> {
    let keys = vocabulary().0.clone();
    let part = "[a-z_]{1,8}(\\[([0-9]{1,3}|\\*|-1|99999999999999999999|)\\])?";
    prop_oneof![
        3 => proptest::sample::select(keys.clone()),
        2 => (proptest::sample::select(keys.clone()), 1usize..400)
            .prop_map(|(k, n)| format!("{k}{}", ".x".repeat(n))),
        1 => (proptest::sample::select(keys), "\\[[0-9*x-]{0,6}\\]")
            .prop_map(|(k, i)| match k.split_once('.') {
                Some((a, b)) => format!("{a}{i}.{b}"),
                None => format!("{k}{i}"),
            }),
        2 => proptest::collection::vec(part, 1..40).prop_map(|p| p.join(".")),
        1 => "[ -~]{0,24}",
    ]
}

/// A value: any, or arrays or inline tables nested up to 300 deep.
fn deep_value() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => any_value(),
        1 => (1usize..300).prop_map(|d| format!("{}1{}", "[".repeat(d), "]".repeat(d))),
        1 => (1usize..300).prop_map(|d| format!("{}1{}", "{a = ".repeat(d), "}".repeat(d))),
    ]
}

/// Stop taking inputs seriously once the property has run `TIME_BOUND`.
fn within(start: Instant) -> bool {
    start.elapsed() < TIME_BOUND
}

#[test]
fn any_set_key_on_any_shipped_scene() {
    let n = seeds().len();
    let case = (
        0..n,
        proptest::collection::vec((any_key(), deep_value()), 1..4),
    );
    let start = Instant::now();
    run(
        "scene-set",
        case,
        |(i, sets)| {
            let o: Vec<String> = sets.iter().map(|(k, v)| format!("{k}={v}")).collect();
            case_file(&seeds()[*i].1, &o)
        },
        |(i, sets)| {
            if !within(start) {
                return Ok(());
            }
            let (path, text) = &seeds()[i];
            let o: Vec<String> = sets.iter().map(|(k, v)| format!("{k}={v}")).collect();
            check(text, path, &o)
        },
    );
}

/// Text added to a shipped scene: a dotted key, a table header or an
/// array-of-tables header of `d` parts, or a value nested `d` deep, its
/// first part one of the scene's sections.
fn deep_table() -> impl Strategy<Value = String> {
    let sections = vocabulary().1.clone();
    let first = proptest::sample::select(
        sections
            .iter()
            .map(|s| s.trim_matches(|c| c == '[' || c == ']').to_string())
            .collect::<Vec<_>>(),
    );
    (first, 1usize..400, 0..5u8, any_value()).prop_map(|(s, d, kind, v)| {
        let parts = format!("{s}{}", ".k".repeat(d));
        match kind {
            0 => format!("{parts} = {v}"),
            1 => format!("[{parts}]\nk = {v}"),
            2 => format!("[[{parts}]]\nk = {v}"),
            3 => format!("{s}_deep = {}{v}{}", "[".repeat(d), "]".repeat(d)),
            _ => format!("{s}_deep = {}{v}{}", "{k = ".repeat(d), "}".repeat(d)),
        }
    })
}

#[test]
fn any_deep_table_in_any_shipped_scene() {
    let n = seeds().len();
    let start = Instant::now();
    run(
        "scene-tables",
        (0..n, deep_table(), any::<bool>()),
        |(i, t, first)| {
            let text = &seeds()[*i].1;
            let s = if *first {
                format!("{t}\n{text}")
            } else {
                format!("{text}\n{t}\n")
            };
            case_file(&s, &[])
        },
        |(i, t, first)| {
            if !within(start) {
                return Ok(());
            }
            let (path, text) = &seeds()[i];
            let s = if first {
                format!("{t}\n{text}")
            } else {
                format!("{text}\n{t}\n")
            };
            check(&s, path, &[])
        },
    );
}
