//! The trace printed: one line a call (`glName(args) -> result` and where
//! in the source it was made), under a heading per pass; runs of calls that
//! repeat (the same functions from the same lines, other values) folded
//! after their first time.

use crate::gl::trace::{Call, PassLabel};
use std::fmt::Write as _;

/// Which calls to keep.
#[derive(Clone, Debug, Default)]
pub struct Filter {
    /// Only the passes of this technique (as the registry names it).
    pub technique: Option<String>,
    /// Only passes of this name (as `gloss plan` names them).
    pub pass: Option<String>,
}

impl Filter {
    fn keeps(&self, label: &Option<std::rc::Rc<PassLabel>>) -> bool {
        let Some(l) = label else {
            // Between passes: the renderer's own calls (debug groups).
            return self.technique.is_none() && self.pass.is_none();
        };
        self.technique.as_ref().is_none_or(|t| *t == l.technique)
            && self
                .pass
                .as_ref()
                .is_none_or(|p| *p == l.pass || *p == l.title)
    }
}

/// A call as a line: `glBlendFunc(GL_ONE, GL_ONE)`.
pub fn call_text(c: &Call) -> String {
    let mut s = format!("{}({})", c.function, c.args.join(", "));
    if let Some(r) = &c.result {
        let _ = write!(s, " -> {r}");
    }
    s
}

/// Where a call was made: `src/x.rs:12` (`via src/gl/y.rs:3`).
pub fn site_text(c: &Call) -> String {
    let mut s = match c.site.line {
        0 => format!("{} (tail call)", c.site.file),
        line => format!("{}:{line}", c.site.file),
    };
    if let Some((file, line)) = &c.site.via {
        let _ = write!(s, " via {file}:{line}");
    }
    s
}

/// The kept calls, grouped by pass in frame order.
pub fn by_pass<'a>(
    calls: &'a [Call],
    filter: &Filter,
) -> Vec<(Option<&'a PassLabel>, Vec<&'a Call>)> {
    let mut groups: Vec<(Option<&PassLabel>, Vec<&Call>)> = Vec::new();
    for c in calls.iter().filter(|c| filter.keeps(&c.pass)) {
        let label = c.pass.as_deref();
        match groups.last_mut() {
            Some((l, v)) if *l == label => v.push(c),
            _ => groups.push((label, vec![c])),
        }
    }
    groups
}

/// A pass's heading: `3. lighting: light_volumes (notes 04, Light Volumes)`.
pub fn heading(label: Option<&PassLabel>) -> String {
    match label {
        Some(l) => format!("{}. {}: {} ({})", l.number, l.title, l.technique, l.notes),
        None => "between passes (the renderer)".to_string(),
    }
}

/// One line per call, repeated runs folded: `(line text, site)` rows and
/// fold notes (site empty).
pub fn rows(calls: &[&Call]) -> Vec<(String, String)> {
    let key = |c: &Call| (c.function, c.site.clone());
    let keys: Vec<_> = calls.iter().map(|c| key(c)).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < calls.len() {
        let period =
            (1..=32.min((calls.len() - i) / 2)).find(|&p| keys[i..i + p] == keys[i + p..i + 2 * p]);
        let Some(p) = period else {
            out.push((call_text(calls[i]), site_text(calls[i])));
            i += 1;
            continue;
        };
        let mut times = 2;
        while i + (times + 1) * p <= calls.len()
            && keys[i..i + p] == keys[i + times * p..i + (times + 1) * p]
        {
            times += 1;
        }
        for c in &calls[i..i + p] {
            out.push((call_text(c), site_text(c)));
        }
        let what = if p == 1 { "this call" } else { "these calls" };
        let again = match times - 1 {
            1 => "once more".to_string(),
            n => format!("{n} more times"),
        };
        out.push((
            format!("... {what} {again}, with other values"),
            String::new(),
        ));
        i += times * p;
    }
    out
}

/// The listing as plain text (the terminal) or Markdown (docs/).
pub fn render(calls: &[Call], filter: &Filter, markdown: bool) -> String {
    let mut s = String::new();
    for (label, group) in by_pass(calls, filter) {
        let rows = rows(&group);
        let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0).min(72);
        if markdown {
            let _ = writeln!(s, "{}\n\n```text", heading(label));
        } else {
            let _ = writeln!(s, "{}", heading(label));
        }
        for (text, site) in rows {
            let indent = if markdown { "" } else { "  " };
            let line = if site.is_empty() {
                format!("{indent}{text}")
            } else {
                format!("{indent}{text:<width$}  {site}")
            };
            let _ = writeln!(s, "{}", line.trim_end());
        }
        if markdown {
            let _ = writeln!(s, "```\n");
        }
    }
    s
}
