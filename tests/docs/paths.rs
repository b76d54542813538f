//! Backticked repository paths, and the prefixed paths in fenced commands,
//! exist; `*` and `<placeholder>` match at least one file; a bare file name
//! names a file somewhere under the documented folders.

use crate::{EXTENSIONS, PREFIXES, lines, report, root};
use std::path::{Path, PathBuf};

/// The inline code spans of a line outside fenced blocks, in order.
fn code_spans(line: &str) -> Vec<&str> {
    let mut spans = Vec::new();
    let mut rest = line;
    while let Some(start) = rest.find('`') {
        let ticks = rest[start..].chars().take_while(|&c| c == '`').count();
        let after = &rest[start + ticks..];
        let fence = &rest[start..start + ticks];
        match after.find(fence) {
            Some(end) => {
                spans.push(after[..end].trim());
                rest = &after[end + ticks..];
            }
            None => break,
        }
    }
    spans
}

/// Does `name` match `pattern`, where `*` matches any run of characters?
pub fn wildcard(pattern: &str, name: &str) -> bool {
    match pattern.split_once('*') {
        None => pattern == name,
        Some((head, tail)) => {
            let Some(rest) = name.strip_prefix(head) else {
                return false;
            };
            (0..=rest.len())
                .filter(|&i| rest.is_char_boundary(i))
                .any(|i| wildcard(tail, &rest[i..]))
        }
    }
}

/// Files and folders under `dir` matching the `/`-separated `pattern`.
pub fn glob(dir: &Path, pattern: &str) -> bool {
    let (first, rest) = match pattern.split_once('/') {
        Some((f, r)) => (f, Some(r)),
        None => (pattern, None),
    };
    let matches: Vec<PathBuf> = if first.contains('*') {
        std::fs::read_dir(dir)
            .map(|rd| {
                rd.flatten()
                    .filter(|e| wildcard(first, &e.file_name().to_string_lossy()))
                    .map(|e| e.path())
                    .collect()
            })
            .unwrap_or_default()
    } else {
        let p = dir.join(first);
        if p.exists() { vec![p] } else { vec![] }
    };
    match rest {
        None | Some("") => !matches.is_empty(),
        Some(r) => matches.iter().any(|m| m.is_dir() && glob(m, r)),
    }
}

/// Every file under the repository's documented folders, relative to the root.
fn repository_files() -> Vec<String> {
    fn walk(dir: &Path, root: &Path, out: &mut Vec<String>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, root, out);
            } else {
                out.push(p.strip_prefix(root).unwrap().to_string_lossy().into_owned());
            }
        }
    }
    let root = root();
    let mut out = Vec::new();
    for prefix in PREFIXES {
        walk(&root.join(prefix), &root, &mut out);
    }
    out
}

/// `<name>` placeholders become `*`; an item suffix (`::name`) and trailing
/// punctuation are dropped.
pub fn clean_path(token: &str) -> String {
    let token = token.trim_matches(|c: char| "\"'(),;:[]".contains(c));
    let token = token.split("::").next().unwrap_or(token);
    // A source line, as the trace names it: `src/x.rs:12`.
    let token = match token.rsplit_once(':') {
        Some((path, line)) if !line.is_empty() && line.chars().all(|c| c.is_ascii_digit()) => path,
        _ => token,
    };
    let mut out = String::new();
    let mut in_placeholder = false;
    for c in token.chars() {
        match c {
            '<' => {
                in_placeholder = true;
                out.push('*');
            }
            '>' => in_placeholder = false,
            _ if in_placeholder => {}
            _ => out.push(c),
        }
    }
    out
}

fn has_prefix(path: &str) -> bool {
    PREFIXES.iter().any(|p| path.starts_with(p))
}

fn has_extension(path: &str) -> bool {
    EXTENSIONS.iter().any(|e| path.ends_with(e))
}

/// A file-like span that is not a repository file: a picture gloss writes
/// (`gloss-default.png`), a build output (`target/...`), an extension alone
/// (`.obj`), a key with a value.
fn is_output_or_fragment(path: &str) -> bool {
    (!path.contains('/') && path.ends_with(".png"))
        || path.starts_with("target/")
        || path.starts_with('.')
        || path.contains('=')
}

/// Why a path mentioned in the docs is wrong, if it is.
fn check_path(path: &str, files: &[String]) -> Option<String> {
    if path.is_empty() {
        return None;
    }
    let root = root();
    if has_prefix(path) {
        let exists = if path.contains('*') {
            glob(&root, path.trim_end_matches('/'))
        } else {
            root.join(path).exists()
        };
        return (!exists).then(|| format!("`{path}` does not exist in the repository"));
    }
    // A name without a known folder: some file under those folders must end with it.
    let pattern = format!("*/{path}");
    let found = root.join(path).exists() || files.iter().any(|f| wildcard(&pattern, f));
    (!found).then(|| format!("`{path}` names no file under {}", PREFIXES.join(", ")))
}

#[test]
fn backticked_paths_exist() {
    let files = repository_files();
    let mut problems = Vec::new();
    for line in lines() {
        let candidates: Vec<String> = if line.fenced {
            // Commands: only tokens that start with a repository folder.
            line.text
                .split_whitespace()
                .map(clean_path)
                .filter(|t| has_prefix(t))
                .collect()
        } else {
            code_spans(&line.text)
                .into_iter()
                .flat_map(|span| {
                    let tokens: Vec<&str> = span.split_whitespace().collect();
                    if tokens.len() == 1 {
                        let p = clean_path(tokens[0]);
                        if has_prefix(&p) || (has_extension(&p) && !is_output_or_fragment(&p)) {
                            vec![p]
                        } else {
                            vec![]
                        }
                    } else {
                        // A command or an expression: its repository paths only.
                        tokens
                            .into_iter()
                            .map(clean_path)
                            .filter(|t| has_prefix(t))
                            .collect()
                    }
                })
                .collect()
        };
        for path in candidates {
            if let Some(why) = check_path(&path, &files) {
                problems.push(format!("{}: {why}", line.at()));
            }
        }
    }
    report("paths that do not exist", problems);
}
