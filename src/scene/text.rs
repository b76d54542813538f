//! Reading a scene file's text safely: the parser's messages cut to a
//! length a terminal can show, and every number checked against the range
//! of the 32-bit floats gloss computes in.

use anyhow::{Result, bail};

/// The most of a message about a scene file gloss prints: the TOML parser
/// quotes the offending line, and a check quotes the value it refuses,
/// either of which in a hostile file can be megabytes long.
pub const MAX_MESSAGE_CHARS: usize = 2000;

/// The longest last line `quoted` keeps whole after a cut: the TOML
/// parser ends its message with its reason ("cannot recurse further; max
/// recursion depth met"), after the line it quotes.
const REASON_CHARS: usize = 300;

/// A message, trimmed, and cut at `MAX_MESSAGE_CHARS` with a note of how
/// much was left out; a short last line (the parser's reason) is kept
/// after the cut.
pub(super) fn quoted(message: &str) -> String {
    let m = message.trim_end();
    if m.chars().count() <= MAX_MESSAGE_CHARS {
        return m.to_string();
    }
    let (body, reason) = match m.rsplit_once('\n') {
        Some((b, last)) if last.chars().count() <= REASON_CHARS => (b, Some(last)),
        _ => (m, None),
    };
    let room = MAX_MESSAGE_CHARS - reason.map_or(0, |r| r.chars().count() + 1);
    let cut = body.char_indices().nth(room).map_or(body.len(), |(i, _)| i);
    let mut out = format!(
        "{}... ({} more characters of the message left out)",
        &body[..cut],
        body[cut..].chars().count()
    );
    if let Some(r) = reason {
        out.push('\n');
        out.push_str(r);
    }
    out
}

/// A message about a binary file's content (an image decoder's) made
/// printable: a chunk type the decoder shows as `ChunkType { type: ... }`
/// becomes its bytes in hex, escaped or control characters become `?`,
/// and a reason the decoder repeats (`A: A`) is said once.
pub(crate) fn printable(message: &str) -> String {
    let mut m = message.to_string();
    while let Some(at) = m.find("ChunkType { type: ") {
        let end = m[at..].find(" }").map_or(m.len(), |e| at + e + 2);
        let inner = &m[at + "ChunkType { type: ".len()..end];
        let ty = inner.split(',').next().unwrap_or("");
        let hex: Vec<String> = unescape(ty).bytes().map(|b| format!("{b:02x}")).collect();
        m.replace_range(at..end, &format!("chunk [{}]", hex.join(" ")));
    }
    let mut out = String::new();
    let mut rest = m.as_str();
    while let Some(at) = rest.find("\\u{") {
        out.push_str(&rest[..at]);
        let end = rest[at..].find('}').map_or(rest.len(), |e| at + e + 1);
        out.push('?');
        rest = &rest[end..];
    }
    out.push_str(rest);
    let out: String = out
        .chars()
        .map(|c| if c.is_control() && c != '\n' { '?' } else { c })
        .collect();
    // "X: Y: Y" -> "X: Y".
    match out.rsplit_once(": ") {
        Some((head, last)) if head.ends_with(last) && !last.is_empty() => head.to_string(),
        _ => out,
    }
}

/// The characters Rust's Debug escapes as `\u{4}` back as they were.
fn unescape(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(at) = rest.find("\\u{") {
        out.push_str(&rest[..at]);
        let end = rest[at..].find('}').map_or(rest.len(), |e| at + e);
        let code = u32::from_str_radix(&rest[at + 3..end], 16).ok();
        out.extend(code.and_then(char::from_u32));
        rest = &rest[(end + 1).min(rest.len())..];
    }
    out.push_str(rest);
    out
}

/// `s` cut to `n` characters, with a note of how many were left out: a
/// `--set` the user typed, quoted in a message about it.
pub(super) fn short(s: &str, n: usize) -> String {
    match s.char_indices().nth(n) {
        None => s.to_string(),
        Some((cut, _)) => format!(
            "{}...({} more characters)",
            &s[..cut],
            s[cut..].chars().count()
        ),
    }
}

/// Every key `table` writes, dotted from the top (`render.cutoff`,
/// `lights[0].shadow.cube`, `materials.glass.alpha_ref`): the keys of a
/// table and of each entry of an array of tables are followed; any other
/// value is a leaf.
pub(super) fn written_keys(table: &toml::Table) -> std::collections::BTreeSet<String> {
    fn walk(t: &toml::Table, prefix: &str, out: &mut std::collections::BTreeSet<String>) {
        for (k, v) in t {
            let key = if prefix.is_empty() {
                k.clone()
            } else {
                format!("{prefix}.{k}")
            };
            match v {
                toml::Value::Table(inner) => walk(inner, &key, out),
                toml::Value::Array(a) => {
                    for (i, x) in a.iter().enumerate() {
                        if let toml::Value::Table(inner) = x {
                            walk(inner, &format!("{key}[{i}]"), out);
                        }
                    }
                }
                _ => {}
            }
            out.insert(key);
        }
    }
    let mut out = std::collections::BTreeSet::new();
    walk(table, "", &mut out);
    out
}

/// Every float of the file fits a 32-bit float (gloss's numbers are f32):
/// `1e39` would otherwise become infinity and be reported as "inf".
pub(super) fn floats_in_f32_range(table: &toml::Table, prefix: &str) -> Result<()> {
    fn check(v: &toml::Value, key: &str) -> Result<()> {
        match v {
            toml::Value::Float(f) if f.is_finite() && f.abs() > f64::from(f32::MAX) => bail!(
                "{key}: {f:e} is out of range of a 32-bit float (at most {:e} in size)",
                f32::MAX
            ),
            toml::Value::Array(a) => {
                (a.iter().enumerate()).try_for_each(|(i, x)| check(x, &format!("{key}[{i}]")))
            }
            toml::Value::Table(t) => floats_in_f32_range(t, key),
            _ => Ok(()),
        }
    }
    table.iter().try_for_each(|(k, v)| {
        let key = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        check(v, &key)
    })
}
