//! What README.md and the pages of docs/ (the map in docs/README.md, the
//! errata, every technique's page) say lives in a file is in it:
//!
//! * `src/x.rs::name`: `name` occurs in src/x.rs;
//! * `src/x.rs` (`a`, `b`): each name in the parentheses right after a path
//!   occurs in that file (or in a file under it, for a folder); `rotate_x/y/z`
//!   is looked up as `rotate_x`;
//! * `name` in `src/x.rs`: the same;
//! * a test file the map or the errata name (`tests/...rs`) has tests in
//!   it: a binary's main.rs that only lists modules is not a test to point
//!   at (other pages may name the binary as such).
//!
//! A name is a backticked identifier; calls and expressions
//! (`glCullFace(GL_BACK)`) are not looked up. A GL function is looked up as
//! glow spells it (`glBindSampler` as `bind_sampler`), a GL constant
//! without its prefix (`GL_RGBA16F` as `RGBA16F`).

use crate::{report, root};

/// The pages whose test files must hold tests.
const MAP_PAGES: [&str; 2] = ["docs/README.md", "docs/notes-errata.md"];

/// The pages checked: README.md and every page under docs/.
fn pages() -> Vec<String> {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "md") {
                out.push(p);
            }
        }
    }
    let mut found = vec![root().join("README.md")];
    walk(&root().join("docs"), &mut found);
    let mut out: Vec<String> = (found.iter())
        .map(|p| p.strip_prefix(root()).unwrap().display().to_string())
        .collect();
    out.sort();
    out
}

fn is_path(s: &str) -> bool {
    ["src/", "tests/", "glsl/", "scenes/"]
        .iter()
        .any(|p| s.starts_with(p))
}

/// What to look for: `rotate_x/y/z` -> `rotate_x`, `glBindSampler` ->
/// `bind_sampler`, `GL_RGBA16F` -> `RGBA16F`; None for what is not a name.
fn name(s: &str) -> Option<String> {
    let base = s.split('/').next()?;
    let mut chars = base.chars();
    let first = chars.next()?;
    if !((first.is_ascii_alphabetic() || first == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_'))
    {
        return None;
    }
    if let Some(rest) = base.strip_prefix("GL_") {
        return Some(rest.to_string());
    }
    match base.strip_prefix("gl") {
        Some(rest) if rest.starts_with(|c: char| c.is_ascii_uppercase()) => {
            let mut snake = String::new();
            for (i, c) in rest.chars().enumerate() {
                if c.is_ascii_uppercase() && i > 0 {
                    snake.push('_');
                }
                snake.push(c.to_ascii_lowercase());
            }
            Some(snake)
        }
        _ => Some(base.to_string()),
    }
}

/// Every file's text at `path` (the file, or each file under a folder).
fn texts(path: &str) -> Vec<String> {
    fn walk(p: &std::path::Path, out: &mut Vec<String>) {
        if p.is_dir() {
            for e in std::fs::read_dir(p).into_iter().flatten().flatten() {
                walk(&e.path(), out);
            }
        } else if let Ok(t) = std::fs::read_to_string(p) {
            out.push(t);
        }
    }
    let mut out = Vec::new();
    walk(&root().join(path.trim_end_matches('/')), &mut out);
    out
}

/// What is wrong with the claim "`name` is in `path`".
fn missing(path: &str, name: &str) -> Option<String> {
    let t = texts(path);
    if t.is_empty() {
        return Some(format!("{path} does not exist"));
    }
    (!t.iter().any(|x| x.contains(name))).then(|| format!("`{name}` is not in {path}"))
}

/// The items of a page: a table row, or a bullet with its continuation lines.
fn items(text: &str) -> Vec<(usize, String)> {
    let mut out: Vec<(usize, String)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start();
        let starts =
            t.is_empty() || t.starts_with("- ") || t.starts_with('|') || t.starts_with('#');
        match out.last_mut() {
            Some((_, item)) if !starts => {
                item.push(' ');
                item.push_str(t);
            }
            _ => out.push((i + 1, t.to_string())),
        }
    }
    out
}

/// The problems of one item: each claim it makes that the files deny.
pub fn check(item: &str, binaries: bool) -> Vec<String> {
    let mut problems = Vec::new();
    // Alternating text and backticked spans: odd parts are spans.
    let parts: Vec<&str> = item.split('`').collect();
    let mut current: Option<&str> = None;
    let mut depth = 0usize;
    let mut in_parens: Option<&str> = None;
    for (i, part) in parts.iter().enumerate() {
        if i % 2 == 0 {
            for c in part.chars() {
                match c {
                    '(' => {
                        depth += 1;
                        if depth == 1 {
                            in_parens = current;
                        }
                    }
                    ')' => {
                        depth = depth.saturating_sub(1);
                        if depth == 0 {
                            in_parens = None;
                        }
                    }
                    // Only parentheses right after the path are about it.
                    c if !c.is_whitespace() && depth == 0 => current = None,
                    _ => {}
                }
            }
            continue;
        }
        let span = *part;
        if is_path(span) {
            let (path, item_name) = match span.split_once("::") {
                Some((p, n)) => (p, Some(n)),
                None => (span, None),
            };
            if let Some(n) = item_name {
                problems.extend(missing(path, n));
            }
            // `name` in `path`
            if i >= 2
                && parts[i - 1].trim() == "in"
                && let Some(n) = name(parts[i - 2])
            {
                problems.extend(missing(path, &n));
            }
            if binaries && path.starts_with("tests/") && path.ends_with(".rs") {
                let t = texts(path);
                if !t.is_empty() && !t[0].contains("#[test]") {
                    problems.push(format!("{path} is named for its tests and has none"));
                }
            }
            current = Some(path);
        } else if let (Some(path), Some(n)) = (in_parens.filter(|_| depth > 0), name(span)) {
            // `name` in `other/path`: looked up there instead.
            let elsewhere = parts.get(i + 1).is_some_and(|t| t.trim() == "in")
                && parts.get(i + 2).is_some_and(|p| is_path(p));
            if !elsewhere {
                problems.extend(missing(path, &n));
            }
        }
    }
    problems
}

#[test]
fn the_maps_names_are_in_the_files_it_names() {
    let mut problems = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(root().join(&page)).unwrap();
        for (line, item) in items(&text) {
            // The map and the errata point at tests; other pages also
            // name a binary's main.rs as the binary.
            let binaries = MAP_PAGES.contains(&page.as_str());
            problems.extend(
                check(&item, binaries)
                    .into_iter()
                    .map(|p| format!("{page}:{line}: {p}")),
            );
        }
    }
    report("claims of the docs that the files they name deny", problems);
}

/// The check sees each kind of wrong claim, and passes a right one.
#[test]
fn the_name_check_sees_a_wrong_row() {
    let ok =
        "| x | `src/math/mod.rs` (`orthographic`, `rotate_x/y/z`) | `tests/lighting/forward.rs` |";
    assert_eq!(check(ok, true), Vec::<String>::new());
    // Elsewhere a binary may be named as such.
    assert!(check("`tests/deferred/main.rs`", false).is_empty());
    assert_eq!(
        check("`src/math/mod.rs` (`no_such_fn_here`)", true).len(),
        1
    );
    assert_eq!(check("`src/math/mod.rs::no_such_fn_here`", true).len(), 1);
    assert_eq!(
        check("`no_such_fn_here` in `src/math/tests.rs`", true).len(),
        1
    );
    assert_eq!(check("`tests/deferred/main.rs`", true).len(), 1);
    assert_eq!(check("`src/no/such/file.rs` (`x`)", true).len(), 1);
    // A call is not a name; a name after the parentheses closed is not looked up.
    assert!(
        check(
            "`src/math/mod.rs` (`glCullFace(GL_BACK)`) then `unrelated`",
            true
        )
        .is_empty()
    );
    // GL names as glow spells them; a name placed in another file is looked up there.
    assert!(
        check(
            "`src/frame/draw_textures.rs` (`glBindSampler`, `GL_TEXTURE0`)",
            true
        )
        .is_empty()
    );
    assert_eq!(check("`src/math/mod.rs` (`glBindSampler`)", true).len(), 1);
    assert!(
        check(
            "`src/math/mod.rs` (`orthographic_matches_glam_and_gl` in `src/math/tests.rs`)",
            true
        )
        .is_empty()
    );
    assert_eq!(
        check(
            "`src/math/mod.rs` (`normal_matrix` in `src/math/depth.rs`)",
            true
        )
        .len(),
        1
    );
}
