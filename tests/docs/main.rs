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
//! * The map (docs/README.md) and the errata name functions and tests that
//!   are in the files they name, and test files that hold tests.
//!
//! Only std: no Markdown parser, just the few constructs these files use.

mod ci_command;
mod links;
mod names;
mod outside;
mod paths;
mod self_check;

use std::path::{Path, PathBuf};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The folders a backticked path may start with.
pub const PREFIXES: [&str; 5] = ["src/", "glsl/", "scenes/", "tests/", "docs/"];

/// The extensions of files the docs name.
pub const EXTENSIONS: [&str; 8] = [
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
pub struct Line {
    pub file: PathBuf,
    pub number: usize,
    pub text: String,
    /// Inside a fenced code block (the fence lines themselves count as inside).
    pub fenced: bool,
}

impl Line {
    pub fn at(&self) -> String {
        format!("{}:{}", self.file.display(), self.number)
    }
}

pub fn lines() -> Vec<Line> {
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

pub fn report(what: &str, problems: Vec<String>) {
    assert!(
        problems.is_empty(),
        "{} {what}:\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
}
