//! docs/README.md's map of the notes against the registry, generated: for
//! each section of the notes (src/trace/notes_sections.rs), the registered
//! techniques whose `notes` cite it, or the files that build it without a
//! technique, or why it is not built; then the techniques beyond the notes.
//! The page holds it between
//!
//! ```text
//! <!-- gloss registry -->
//! ... generated ...
//! <!-- end of gloss registry -->
//! ```
//!
//! and tests/trace/registry.rs fails when the page and the registry differ
//! (`GLOSS_BLESS=1` rewrites the block).

use super::notes_sections::{Otherwise, SECTIONS, Section};
use crate::frame::Technique;
use std::fmt::Write as _;

/// The block's opening marker.
pub const OPEN: &str = "<!-- gloss registry -->";
/// The block's closing marker.
pub const CLOSE: &str = "<!-- end of gloss registry -->";

/// A technique that says it goes beyond the notes implements no section
/// (the notes it names are what it improves on).
pub fn beyond_the_notes(t: &Technique) -> bool {
    t.notes.contains("beyond the notes")
}

/// What a technique's `notes` cites: (notes file, text) per clause, the
/// clauses split at `;`, a clause without "notes NN" in the notes of the
/// clause before it. "notes 01 §4.5, Blending; §6.1, Handling" gives
/// ("01", "§4.5, Blending") and ("01", "§6.1, Handling").
pub fn citations(notes: &str) -> Vec<(String, String)> {
    let mut file = String::new();
    let mut out = Vec::new();
    for clause in notes.split(';') {
        let mut text = clause.trim();
        if let Some(at) = text.find("notes ") {
            let digits: String = text[at + 6..].chars().take(2).collect();
            if digits.len() == 2 && digits.chars().all(|c| c.is_ascii_digit()) {
                file = digits;
                text = text[at + 8..].trim_start_matches([',', ' ']);
            }
        }
        if !file.is_empty() && !text.is_empty() {
            out.push((file.clone(), text.to_string()));
        }
    }
    out
}

/// The § numbers a citation's text starts with: "§8.6.2 step 1" gives
/// §8.6.2; a range "§8.2-8.3" gives §8.2 and §8.3.
pub fn numbers(text: &str) -> Vec<String> {
    let Some(rest) = text.strip_prefix('§') else {
        return vec![];
    };
    let token: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
        .collect();
    let token = token.trim_end_matches(['.', '-']);
    let Some((from, to)) = token.split_once('-') else {
        return vec![format!("§{token}")];
    };
    let range = from.rsplit_once('.').zip(to.rsplit_once('.'));
    match range {
        Some(((head, a), (head_b, b))) if head == head_b => {
            match (a.parse::<u32>(), b.parse::<u32>()) {
                (Ok(a), Ok(b)) if a <= b && b - a < 20 => {
                    (a..=b).map(|i| format!("§{head}.{i}")).collect()
                }
                _ => vec![format!("§{from}"), format!("§{to}")],
            }
        }
        _ => vec![format!("§{from}"), format!("§{to}")],
    }
}

/// Whether `citation` (in `file`) cites `section`: notes 01 by § number,
/// the others by the heading's title in the citation (any case).
fn cites_text(file: &str, text: &str, section: &Section) -> bool {
    if file != section.notes {
        return false;
    }
    if file == "01" {
        let n = numbers(text);
        return section.cites.iter().any(|c| n.iter().any(|x| x == c));
    }
    let lower = text.to_lowercase();
    section
        .cites
        .iter()
        .any(|c| lower.contains(&c.to_lowercase()))
}

/// The indices of the sections a technique's `notes` cite. A clause
/// "A to B" cites every section of its notes from A's to B's.
pub fn cited(t: &Technique) -> Vec<usize> {
    if beyond_the_notes(t) {
        return vec![];
    }
    let mut out: Vec<usize> = Vec::new();
    for (file, text) in citations(t.notes) {
        let mut hits: Vec<usize> = match text.split_once(" to ") {
            Some((a, b)) => {
                let first = (0..SECTIONS.len()).find(|&i| cites_text(&file, a, &SECTIONS[i]));
                let last = (0..SECTIONS.len()).rfind(|&i| cites_text(&file, b, &SECTIONS[i]));
                match (first, last) {
                    (Some(f), Some(l)) if f <= l => (f..=l)
                        .filter(|&i| SECTIONS[i].notes == file && !SECTIONS[i].cites.is_empty())
                        .collect(),
                    _ => vec![],
                }
            }
            None => (0..SECTIONS.len())
                .filter(|&i| cites_text(&file, &text, &SECTIONS[i]))
                .collect(),
        };
        hits.retain(|i| !out.contains(i));
        out.extend(hits);
    }
    out
}

/// `[light_volumes](deferred/light_volumes.md)`: the page's path relative
/// to docs/.
fn link(t: &Technique) -> String {
    format!(
        "[`{}`]({})",
        t.name,
        t.docs.strip_prefix("docs/").unwrap_or(t.docs)
    )
}

/// The generated text between the markers, for the registry `all`.
pub fn block(all: &[&Technique]) -> String {
    let by: Vec<Vec<&Technique>> = (0..SECTIONS.len())
        .map(|i| {
            (all.iter().copied())
                .filter(|t| cited(t).contains(&i))
                .collect()
        })
        .collect();
    let mut s = String::new();
    s += "Generated from the registry (`src/techniques/mod.rs`: each technique's \
          `notes`) and the notes' sections (`src/trace/notes_sections.rs`); a test \
          fails when this block and the registry differ.\n\n";
    s += "**Not built yet:**\n\n";
    for (i, sec) in SECTIONS.iter().enumerate() {
        if let (Otherwise::NotBuilt(why), true) = (&sec.otherwise, by[i].is_empty()) {
            let _ = writeln!(s, "- notes {} {}: {why}.", sec.notes, sec.title);
        }
    }
    s += "\n| notes | section | built by |\n|---|---|---|\n";
    for (i, sec) in SECTIONS.iter().enumerate() {
        let built = if !by[i].is_empty() {
            let names: Vec<String> = by[i].iter().map(|t| link(t)).collect();
            names.join(", ")
        } else {
            match &sec.otherwise {
                Otherwise::In(files) if !files.is_empty() => {
                    let files: Vec<String> = files.iter().map(|f| format!("`{f}`")).collect();
                    format!("in {}", files.join(", "))
                }
                Otherwise::In(_) => "**no registered technique cites it**".to_string(),
                Otherwise::NotBuilt(_) => "not built yet (above)".to_string(),
            }
        };
        let _ = writeln!(s, "| {} | {} | {built} |", sec.notes, sec.title);
    }
    s += "\nBeyond the notes (a technique that cites no section of them):\n\n";
    for t in all {
        if cited(t).is_empty() {
            let _ = writeln!(s, "- {}: {}", link(t), t.notes);
        }
    }
    s
}

/// Problems with the table itself: a section to be built by a technique
/// that no technique cites, a file named that does not exist under `root`.
pub fn problems(all: &[&Technique], root: &std::path::Path) -> Vec<String> {
    let mut out = Vec::new();
    for (i, sec) in SECTIONS.iter().enumerate() {
        let built = all.iter().any(|t| cited(t).contains(&i));
        match &sec.otherwise {
            Otherwise::In(files) if files.is_empty() && !built => out.push(format!(
                "notes {} {}: no registered technique cites it and no file is named",
                sec.notes, sec.title
            )),
            Otherwise::In(files) => {
                for f in files.iter().filter(|f| !root.join(f).exists()) {
                    out.push(format!(
                        "notes {} {}: {f} does not exist",
                        sec.notes, sec.title
                    ));
                }
            }
            Otherwise::NotBuilt(_) => {}
        }
    }
    out
}

/// The byte range of the generated text in `page`, between the markers.
pub fn range(page: &str) -> Option<(usize, usize)> {
    let start = page.find(OPEN)? + OPEN.len() + 1;
    let end = page[start..].find(CLOSE)? + start;
    Some((start, end))
}
