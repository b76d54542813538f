//! Relative link targets (`[text](path)`, `![alt](path)`, `[label]: path`)
//! exist and stay inside the repository.

use crate::{lines, report, root};
use std::path::{Component, Path, PathBuf};

/// The line with its code spans blanked, so links and words inside code are not read.
fn without_code(line: &str) -> String {
    let mut out = String::new();
    let mut rest = line;
    while let Some(start) = rest.find('`') {
        let ticks = rest[start..].chars().take_while(|&c| c == '`').count();
        let after = &rest[start + ticks..];
        let fence = &rest[start..start + ticks];
        match after.find(fence) {
            Some(end) => {
                out.push_str(&rest[..start]);
                out.push_str("``");
                rest = &after[end + ticks..];
            }
            None => break,
        }
    }
    out.push_str(rest);
    out
}

/// Link targets on a line: `](target)` and reference definitions `[label]: target`.
pub fn link_targets(line: &str) -> Vec<String> {
    let mut targets = Vec::new();
    let text = without_code(line);
    let mut rest = text.as_str();
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        // Balanced parentheses, as Markdown allows in a destination.
        let mut depth = 0;
        let mut end = None;
        for (j, c) in after.char_indices() {
            match c {
                '(' => depth += 1,
                ')' if depth == 0 => {
                    end = Some(j);
                    break;
                }
                ')' => depth -= 1,
                _ => {}
            }
        }
        let Some(end) = end else { break };
        let dest = after[..end].trim();
        let dest = dest
            .strip_prefix('<')
            .and_then(|d| d.split_once('>'))
            .map(|(d, _)| d)
            .unwrap_or_else(|| dest.split_whitespace().next().unwrap_or(""));
        targets.push(dest.to_string());
        rest = &after[end..];
    }
    let t = text.trim_start();
    if t.starts_with('[')
        && let Some((_, dest)) = t.split_once("]:")
        && let Some(dest) = dest.split_whitespace().next()
    {
        targets.push(dest.to_string());
    }
    targets
}

pub fn is_external(target: &str) -> bool {
    target.starts_with('#')
        || target.starts_with("mailto:")
        || target
            .split_once(':')
            .is_some_and(|(scheme, _)| !scheme.is_empty() && !scheme.contains('/'))
}

/// `base/rel` with `.` and `..` folded; `None` if it climbs above the root.
pub fn normalize(base: &Path, rel: &str) -> Option<PathBuf> {
    let mut parts: Vec<String> = Vec::new();
    for c in base.join(rel).components() {
        match c {
            Component::ParentDir => {
                parts.pop()?;
            }
            Component::CurDir => {}
            Component::Normal(s) => parts.push(s.to_string_lossy().into_owned()),
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(parts.iter().collect())
}

#[test]
fn relative_links_point_at_files_in_the_repository() {
    let mut problems = Vec::new();
    for line in lines().iter().filter(|l| !l.fenced) {
        let dir = line.file.parent().unwrap_or(Path::new(""));
        for target in link_targets(&line.text) {
            if target.is_empty() || is_external(&target) {
                continue;
            }
            let path = target.split('#').next().unwrap_or("");
            if path.is_empty() {
                continue;
            }
            match normalize(dir, path) {
                None => problems.push(format!(
                    "{}: link `{target}` leaves the repository",
                    line.at()
                )),
                Some(p) if !root().join(&p).exists() => problems.push(format!(
                    "{}: link `{target}` points at {}, which does not exist",
                    line.at(),
                    p.display()
                )),
                Some(_) => {}
            }
        }
    }
    report("broken links", problems);
}
