//! The scene loader never panics: on arbitrary text, on text shaped like a
//! scene file out of the format's own keys, and on the shipped scenes
//! mutated, with and without `--set` overrides, it returns a scene (whose
//! warnings and frame plan are made too) or an error with a message that
//! is not empty and at most `MAX_MESSAGE_CHARS` after the file's name.

use crate::{EXTREME_NUMBERS, root, run};
use gloss::scene::{MAX_MESSAGE_CHARS, Scene};
use proptest::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The shipped scenes: (path, text).
pub fn seeds() -> &'static [(PathBuf, String)] {
    static SEEDS: OnceLock<Vec<(PathBuf, String)>> = OnceLock::new();
    SEEDS.get_or_init(|| {
        let mut v: Vec<(PathBuf, String)> = std::fs::read_dir(root().join("scenes"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .map(|p| {
                let text = std::fs::read_to_string(&p).unwrap();
                (p, text)
            })
            .collect();
        v.sort();
        v
    })
}

/// The keys the shipped scenes write, dotted (`render.cutoff`,
/// `lights[0].intensity`), and their section headers.
pub fn vocabulary() -> &'static (Vec<String>, Vec<String>) {
    static WORDS: OnceLock<(Vec<String>, Vec<String>)> = OnceLock::new();
    WORDS.get_or_init(|| {
        let (mut keys, mut sections) = (Vec::new(), Vec::new());
        for (_, text) in seeds() {
            let mut section = String::new();
            for line in text.lines().map(str::trim) {
                if line.starts_with('[') {
                    sections.push(line.to_string());
                    let name = line.trim_matches(|c| c == '[' || c == ']');
                    section = if line.starts_with("[[") {
                        format!("{name}[0]")
                    } else {
                        name.to_string()
                    };
                } else if let Some((k, _)) = line.split_once('=')
                    && !line.starts_with('#')
                {
                    let k = k.trim();
                    keys.push(if section.is_empty() {
                        k.to_string()
                    } else {
                        format!("{section}.{k}")
                    });
                }
            }
        }
        for v in [&mut keys, &mut sections] {
            v.sort();
            v.dedup();
        }
        (keys, sections)
    })
}

/// Values of the wrong type, size or meaning.
fn hostile_values() -> Vec<String> {
    let mut v: Vec<String> = [
        "\"\"",
        "\"x\"",
        "[]",
        "{}",
        "true",
        "false",
        "[[]]",
        "[1e38, -1e38, nan]",
        "[0.0, 0.0, 0.0]",
        "[1, 2]",
        "[1, 2, 3, 4, 5]",
        "[-1.0, -1.0, -1.0, -1.0]",
        "{ a = 1 }",
        "\"/dev/zero\"",
        "\"assets\"",
        "\"assets/rock.OBJ\"",
        "\"assets/nothing.obj\"",
        "\"assets/bricks.png\"",
        "\"sphere\"",
        "\"embedded:scenes/none.png\"",
        "1979-05-27T07:32:00Z",
    ]
    .map(String::from)
    .to_vec();
    v.push(format!("\"{}\"", "a".repeat(100_000)));
    v.push(format!("[{}]", vec!["1.5"; 20_000].join(", ")));
    v.push(format!("{}{}", "[".repeat(500), "]".repeat(500)));
    v.extend(EXTREME_NUMBERS.iter().map(|s| s.to_string()));
    v
}

/// Values a scene might well hold: small numbers, triples, words the
/// format takes.
fn plausible_value() -> impl Strategy<Value = String> {
    let small = || {
        prop_oneof![
            (-2.0f32..10.0).prop_map(|f| format!("{f:?}")),
            (0u32..9).prop_map(|n| n.to_string())
        ]
    };
    let words = proptest::sample::select(vec![
        "\"forward\"",
        "\"deferred\"",
        "\"volumes\"",
        "\"prepass\"",
        "\"flat\"",
        "\"gouraud\"",
        "\"point\"",
        "\"spot\"",
        "\"directional\"",
        "\"sphere\"",
        "\"plane\"",
        "\"cube\"",
        "\"orthographic\"",
        "\"perspective\"",
        "\"gamma\"",
        "\"tonemap\"",
        "\"bloom\"",
        "\"fxaa\"",
        "\"blur\"",
        "\"reinhard\"",
        "true",
        "false",
    ]);
    prop_oneof![
        3 => small(),
        3 => (small(), small(), small()).prop_map(|(a, b, c)| format!("[{a}, {b}, {c}]")),
        1 => (small(), small()).prop_map(|(a, b)| format!("[{a}, {b}]")),
        1 => (small(), small(), small(), small()).prop_map(|(a, b, c, d)| format!("[{a}, {b}, {c}, {d}]")),
        2 => words.prop_map(String::from),
    ]
}

pub fn any_value() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => plausible_value(),
        3 => proptest::sample::select(hostile_values()),
        1 => "[ -~]{0,12}",
        1 => any::<f64>().prop_map(|f| format!("{f:?}")),
        1 => any::<i64>().prop_map(|n| n.to_string()),
    ]
}

/// A `KEY=VALUE` override, its key one the scenes write.
fn any_override() -> impl Strategy<Value = String> {
    let keys = vocabulary().0.clone();
    let key = prop_oneof![
        4 => proptest::sample::select(keys),
        1 => "[a-z_.\\[\\]*0-9]{0,16}",
    ];
    (key, any_value()).prop_map(|(k, v)| format!("{k}={v}"))
}

/// One edit of a scene file's text.
#[derive(Clone, Debug)]
enum Op {
    Byte(usize, u8),
    Insert(usize, String),
    Cut(usize, usize),
    DropLine(usize),
    DupLine(usize),
    SwapLines(usize, usize),
    /// Delete the k-th `key = value` line.
    DropKey(usize),
    /// The k-th number becomes an extreme one.
    Number(usize, String),
    /// The k-th `key = value` line's value becomes this.
    Value(usize, String),
    /// A `key = value` line, its key one the scenes write, goes in here.
    AddLine(usize, String),
}

fn any_op() -> impl Strategy<Value = Op> {
    let n = any::<usize>();
    let key_line = (
        proptest::sample::select(vocabulary().0.clone()),
        any_value(),
    )
        .prop_map(|(k, v)| format!("{} = {v}", k.rsplit('.').next().unwrap_or(&k)));
    prop_oneof![
        1 => (n, any::<u8>()).prop_map(|(i, b)| Op::Byte(i, b)),
        1 => (n, "[ -~\n]{1,8}").prop_map(|(i, s)| Op::Insert(i, s)),
        1 => (n, 1..64usize).prop_map(|(i, l)| Op::Cut(i, l)),
        1 => n.prop_map(Op::DropLine),
        1 => n.prop_map(Op::DupLine),
        1 => (n, n).prop_map(|(a, b)| Op::SwapLines(a, b)),
        4 => n.prop_map(Op::DropKey),
        6 => (n, proptest::sample::select(EXTREME_NUMBERS)).prop_map(|(i, s)| Op::Number(i, s.to_string())),
        6 => (n, any_value()).prop_map(|(i, v)| Op::Value(i, v)),
        3 => (n, key_line).prop_map(|(i, l)| Op::AddLine(i, l)),
        1 => (n, proptest::sample::select(vocabulary().1.clone())).prop_map(|(i, s)| Op::AddLine(i, s)),
    ]
}

/// Where the number tokens of `text` are (start, end).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit() && (i == 0 || !b[i - 1].is_ascii_alphanumeric());
        if starts {
            let from = if i > 0 && b[i - 1] == b'-' { i - 1 } else { i };
            let mut j = i;
            while j < b.len() && (b[j].is_ascii_digit() || b"._eE+-".contains(&b[j])) {
                j += 1;
            }
            out.push((from, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

fn apply(text: &str, ops: &[Op]) -> String {
    let mut t = text.to_string();
    for op in ops {
        let mut lines: Vec<String> = t.lines().map(String::from).collect();
        let keys: Vec<usize> = (0..lines.len())
            .filter(|&i| lines[i].contains('=') && !lines[i].trim_start().starts_with('#'))
            .collect();
        let at = |i: usize, n: usize| if n == 0 { 0 } else { i % n };
        match op {
            Op::Byte(i, v) => {
                let mut bytes = t.into_bytes();
                if !bytes.is_empty() {
                    let i = at(*i, bytes.len());
                    bytes[i] = *v;
                }
                t = String::from_utf8_lossy(&bytes).into_owned();
                continue;
            }
            Op::Insert(i, s) => {
                let i = at(*i, t.len() + 1);
                let i = (0..=i).rev().find(|&i| t.is_char_boundary(i)).unwrap_or(0);
                t.insert_str(i, s);
                continue;
            }
            Op::Cut(i, len) => {
                let i = at(*i, t.len() + 1);
                let end = (i + len).min(t.len());
                if t.is_char_boundary(i) && t.is_char_boundary(end) {
                    t.replace_range(i..end, "");
                }
                continue;
            }
            Op::Number(k, s) => {
                let ns = numbers(&t);
                if !ns.is_empty() {
                    let (a, b) = ns[at(*k, ns.len())];
                    t.replace_range(a..b, s);
                }
                continue;
            }
            Op::DropLine(i) if !lines.is_empty() => {
                lines.remove(at(*i, lines.len()));
            }
            Op::DupLine(i) if !lines.is_empty() => {
                let i = at(*i, lines.len());
                lines.insert(i, lines[i].clone());
            }
            Op::SwapLines(a, b) if !lines.is_empty() => {
                let n = lines.len();
                lines.swap(a % n, b % n);
            }
            Op::DropKey(k) if !keys.is_empty() => {
                lines.remove(keys[at(*k, keys.len())]);
            }
            Op::Value(k, v) if !keys.is_empty() => {
                let i = keys[at(*k, keys.len())];
                let key = lines[i].split('=').next().unwrap_or("").to_string();
                lines[i] = format!("{key}= {v}");
            }
            Op::AddLine(i, l) => {
                let i = at(*i, lines.len() + 1);
                lines.insert(i, l.clone());
            }
            _ => {}
        }
        t = lines.join("\n");
    }
    t
}

/// The property, for one text (named `path`) and its overrides.
pub fn check(text: &str, path: &Path, overrides: &[String]) -> Result<(), TestCaseError> {
    match Scene::parse_with(text, path, overrides) {
        Ok(scene) => {
            crate::accepted();
            let _ = scene.warnings();
            let _ = gloss::techniques::plan(&scene).to_string();
        }
        Err(e) => {
            let m = format!("{e:#}");
            prop_assert!(!m.trim().is_empty(), "an empty error message");
            let limit = path.display().to_string().chars().count() + MAX_MESSAGE_CHARS + 200;
            let n = m.chars().count();
            prop_assert!(
                n <= limit,
                "a message of {n} characters (at most {limit}): {}...",
                m.chars().take(300).collect::<String>()
            );
        }
    }
    Ok(())
}

/// The plain file of a case: `# --set KEY=VALUE` lines, then the text.
pub fn case_file(text: &str, overrides: &[String]) -> Vec<u8> {
    let mut s: String = overrides.iter().map(|o| format!("# --set {o}\n")).collect();
    s.push_str(text);
    s.into_bytes()
}

#[test]
fn the_loader_takes_any_text() {
    let text = prop_oneof![
        any::<String>(),
        proptest::collection::vec(any::<u8>(), 0..2000)
            .prop_map(|b| String::from_utf8_lossy(&b).into_owned()),
    ];
    run(
        "scene-text",
        text,
        |t| case_file(t, &[]),
        |t| check(&t, &root().join("scenes/fuzz.toml"), &[]),
    );
}

#[test]
fn the_loader_takes_any_scene_shaped_text() {
    // A valid camera, then sections each with keys of its own kind.
    let camera = "[camera]\neye = [0.0, 2.0, 6.0]\ntarget = [0.0, 0.0, 0.0]\n";
    let keys = vocabulary().0.clone();
    let section = (
        proptest::sample::select(vocabulary().1.clone()),
        proptest::collection::vec((any::<usize>(), any_value()), 0..6),
    )
        .prop_map(move |(header, entries)| {
            let name = header.trim_matches(|c| c == '[' || c == ']').to_string();
            let own: Vec<&String> = keys
                .iter()
                .filter(|k| {
                    k.strip_prefix(name.as_str())
                        .is_some_and(|r| r.starts_with('.') || r.starts_with("[0]."))
                })
                .collect();
            let mut s = header;
            for (k, v) in entries {
                if let Some(key) = own.get(k % own.len().max(1)) {
                    s.push_str(&format!(
                        "\n{} = {v}",
                        key.rsplit('.').next().unwrap_or(key)
                    ));
                }
            }
            s
        });
    let text = proptest::collection::vec(section, 0..8)
        .prop_map(move |l| format!("{camera}{}", l.join("\n")));
    run(
        "scene-shaped",
        text,
        |t| case_file(t, &[]),
        |t| check(&t, &root().join("scenes/fuzz.toml"), &[]),
    );
}

#[test]
fn the_loader_takes_any_mutated_scene() {
    let n = seeds().len();
    let case = (
        0..n,
        proptest::collection::vec(any_op(), 1..4),
        proptest::collection::vec(any_override(), 0..2),
    )
        .prop_map(|(i, ops, overrides)| {
            let (path, text) = &seeds()[i];
            (path.clone(), apply(text, &ops), overrides)
        });
    run(
        "scene-mutated",
        case,
        |(_, t, o)| case_file(t, o),
        |(path, text, overrides)| check(&text, &path, &overrides),
    );
}

#[test]
fn the_mutations_change_the_text() {
    // The harness is worth something only if its edits land.
    let text = "a = 1\n[render]\ncutoff = 0.5\n";
    assert_eq!(
        apply(text, &[Op::Number(1, "nan".into())]),
        "a = 1\n[render]\ncutoff = nan\n"
    );
    assert_eq!(apply(text, &[Op::DropKey(0)]), "[render]\ncutoff = 0.5");
    assert_eq!(
        apply(text, &[Op::Value(1, "[]".into())]),
        "a = 1\n[render]\ncutoff = []"
    );
    assert_eq!(numbers("x = [-1.5e3, 2]"), vec![(5, 11), (13, 14)]);
    assert!(vocabulary().0.iter().any(|k| k == "render.cutoff"));
}
