//! The documentation stays true to the repository: README.md and every
//! Markdown file under docs/ are read, and each problem is reported with its
//! file and line.
//!
//! * A relative link target (`[text](path)`, `![alt](path)`, `[label]: path`)
//!   must exist and stay inside the repository.
//! * A backticked repository path (`src/...`, `glsl/...`, `scenes/...`,
//!   `tests/...`, `docs/...`) must exist relative to the repository root. An
//!   item suffix is stripped (`src/math/mod.rs::normal_matrix`); `*` and
//!   `<placeholder>` match any run of characters
//!   (`glsl/lighting/forward_flat.*`, `tests/golden/<scene>.png`), and at
//!   least one file must match. A backticked file name with one of the
//!   repository's extensions and no such prefix (`gbuffer_read.glsl`,
//!   `assets/checker.png`) must name a file somewhere under those folders.
//!   Bare PNG names without a folder are pictures gloss writes
//!   (`gloss-default.png`) and `target/...` is build output: neither is checked.
//! * Prefixed paths inside fenced code blocks (the commands) must exist too.
//! * The text points at nothing outside the repository: no `../shared`, no
//!   issue numbers, no "closing note".
//! * README.md's test command is the command `.ci/run` runs.
//!
//! Only std: no Markdown parser, just the few constructs these files use.

use std::path::{Component, Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The folders a backticked path may start with.
const PREFIXES: [&str; 5] = ["src/", "glsl/", "scenes/", "tests/", "docs/"];

/// The extensions of files the docs name.
const EXTENSIONS: [&str; 8] = [
    ".rs", ".toml", ".glsl", ".vert", ".frag", ".geom", ".md", ".png",
];

/// README.md and every .md under docs/, sorted, relative to the root.
fn markdown_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "md") {
                out.push(p);
            }
        }
    }
    let root = root();
    let mut files = vec![root.join("README.md")];
    walk(&root.join("docs"), &mut files);
    files.sort();
    files
        .into_iter()
        .map(|p| p.strip_prefix(&root).unwrap().to_path_buf())
        .collect()
}

/// One line of a Markdown file, with where it came from.
struct Line {
    file: PathBuf,
    number: usize,
    text: String,
    /// Inside a fenced code block (the fence lines themselves count as inside).
    fenced: bool,
}

impl Line {
    fn at(&self) -> String {
        format!("{}:{}", self.file.display(), self.number)
    }
}

fn lines() -> Vec<Line> {
    let mut out = Vec::new();
    for file in markdown_files() {
        let text = std::fs::read_to_string(root().join(&file))
            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let mut fenced = false;
        for (i, l) in text.lines().enumerate() {
            let fence = l.trim_start().starts_with("```");
            out.push(Line {
                file: file.clone(),
                number: i + 1,
                text: l.to_string(),
                fenced: fenced || fence,
            });
            if fence {
                fenced = !fenced;
            }
        }
    }
    out
}

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
fn link_targets(line: &str) -> Vec<String> {
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

fn is_external(target: &str) -> bool {
    target.starts_with('#')
        || target.starts_with("mailto:")
        || target
            .split_once(':')
            .is_some_and(|(scheme, _)| !scheme.is_empty() && !scheme.contains('/'))
}

/// `base/rel` with `.` and `..` folded; `None` if it climbs above the root.
fn normalize(base: &Path, rel: &str) -> Option<PathBuf> {
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

/// Does `name` match `pattern`, where `*` matches any run of characters?
fn wildcard(pattern: &str, name: &str) -> bool {
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
fn glob(dir: &Path, pattern: &str) -> bool {
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
fn clean_path(token: &str) -> String {
    let token = token.trim_matches(|c: char| "\"'(),;:[]".contains(c));
    let token = token.split("::").next().unwrap_or(token);
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

fn report(what: &str, problems: Vec<String>) {
    assert!(
        problems.is_empty(),
        "{} {what}:\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
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

/// Where `word` occurs in `text` (ASCII case-insensitive), at word starts.
fn word_starts(text: &str, word: &str) -> Vec<usize> {
    let lower = text.to_ascii_lowercase();
    lower
        .match_indices(word)
        .map(|(i, _)| i)
        .filter(|&i| {
            i == 0
                || !lower[..i]
                    .chars()
                    .next_back()
                    .is_some_and(|c| c.is_ascii_alphanumeric())
        })
        .collect()
}

/// "issue 3", "issues 3 and 4", "issue #12", "Issue no. 7".
fn names_an_issue_number(text: &str) -> bool {
    word_starts(text, "issue").into_iter().any(|i| {
        let rest = &text[i + "issue".len()..];
        let rest = rest.strip_prefix(['s', 'S']).unwrap_or(rest);
        let rest = rest.trim_start();
        let rest = rest
            .strip_prefix("no.")
            .or_else(|| rest.strip_prefix("No."))
            .unwrap_or(rest)
            .trim_start();
        let rest = rest.strip_prefix('#').unwrap_or(rest);
        rest.starts_with(|c: char| c.is_ascii_digit())
    })
}

#[test]
fn docs_point_at_nothing_outside_the_repository() {
    let mut problems = Vec::new();
    for line in lines() {
        let t = &line.text;
        if t.contains("../shared") {
            problems.push(format!(
                "{}: `../shared` is outside the repository: cite the notes by file name and section",
                line.at()
            ));
        }
        if names_an_issue_number(t) {
            problems.push(format!(
                "{}: an issue number means nothing to a reader of the repository: say what it holds",
                line.at()
            ));
        }
        if !word_starts(t, "closing note").is_empty() {
            problems.push(format!(
                "{}: \"closing note\" points outside the repository: link the file that holds it",
                line.at()
            ));
        }
    }
    report("references outside the repository", problems);
}

#[test]
fn readme_test_command_is_what_ci_runs() {
    let ci = std::fs::read_to_string(root().join(".ci/run")).expect(".ci/run");
    let ci_command = ci
        .lines()
        .map(str::trim)
        .rfind(|l| !l.is_empty())
        .expect(".ci/run has a last line");
    let readme = lines()
        .into_iter()
        .filter(|l| l.file == Path::new("README.md"))
        .collect::<Vec<_>>();
    let test_line = readme
        .iter()
        .find(|l| l.fenced && l.text.contains("cargo test"))
        .expect("README.md shows the test command in a code block");
    let command = test_line.text.split(" #").next().unwrap_or("").trim();
    assert_eq!(
        command,
        ci_command,
        "{}: README.md's test command differs from the last line of .ci/run",
        test_line.at()
    );
}

#[test]
fn the_checks_themselves() {
    assert!(names_an_issue_number("see issue 3"));
    assert!(names_an_issue_number("Issues #12 and 13"));
    assert!(!names_an_issue_number("a known issue with 3 lights"));
    assert!(!names_an_issue_number("tissue 3"));
    assert_eq!(
        link_targets("[a](docs/x.md) and ![b](<y z.png>) `[c](no.md)`"),
        ["docs/x.md", "y z.png"]
    );
    assert_eq!(
        link_targets("[ref]: ../tests/golden/plane.png"),
        ["../tests/golden/plane.png"]
    );
    assert_eq!(
        clean_path("`src/math/mod.rs::normal_matrix`".trim_matches('`')),
        "src/math/mod.rs"
    );
    assert_eq!(clean_path("tests/golden/<scene>.png"), "tests/golden/*.png");
    assert!(wildcard("forward_flat.*", "forward_flat.geom"));
    assert!(!wildcard("forward_flat.*", "forward.frag"));
    assert_eq!(normalize(Path::new("docs"), "../../x"), None);
    assert_eq!(
        normalize(Path::new("docs/deferred"), "../../tests/golden/plane.png"),
        Some(PathBuf::from("tests/golden/plane.png"))
    );
    assert!(is_external("https://www.khronos.org/opengl/wiki"));
    assert!(!is_external("lighting/forward.md"));
    assert!(glob(&root(), "tests/golden/*.png"));
    assert!(glob(&root(), "scenes/*.toml"));
}
