//! The shape of the code (docs/architecture.md), checked:
//!
//! * imports run downwards: a module under src/ uses `crate::X` only for an
//!   X in a lower layer (or its own module), so there is no import circle;
//! * a technique imports no technique of another chapter, and never the
//!   renderer or the tools;
//! * every source file can be read in one sitting (at most 400 lines),
//!   except the tables a script generates.

use std::path::{Path, PathBuf};

/// The layers, bottom first, as src/lib.rs lists them.
const LAYERS: &[(&str, u32)] = &[
    ("math", 0),
    ("image_compare", 0),
    ("assets", 0),
    ("geometry", 1),
    ("gl", 2),
    ("scene", 3),
    ("lighting", 4),
    ("frame", 5),
    ("techniques", 6),
    ("renderer", 7),
    ("bench", 8),
    ("demo", 8),
    ("trace", 8),
    ("cli", 9),
];

const MAX_LINES: usize = 400;

fn layer(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|l| l.1)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

fn src_files() -> Vec<(String, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let rel = p
                .strip_prefix(&src)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (rel, std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

/// Every `crate::a::b` path on a line that is not a comment, with its line number.
fn crate_paths(text: &str) -> Vec<(usize, Vec<String>)> {
    let mut v = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(at) = rest.find("crate::") {
            let tail = &rest[at + "crate::".len()..];
            let path: Vec<String> = tail
                .split("::")
                .map(|s| {
                    s.chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect::<String>()
                })
                .take_while(|s| !s.is_empty())
                .collect();
            if !path.is_empty() {
                v.push((i + 1, path));
            }
            rest = tail;
        }
    }
    v
}

#[test]
fn imports_only_run_downwards() {
    let mut wrong = Vec::new();
    for (file, text) in src_files() {
        let module = file.split('/').next().unwrap().trim_end_matches(".rs");
        if module == "lib" || module == "main" {
            continue;
        }
        let Some(own) = layer(module) else {
            wrong.push(format!(
                "src/{file}: module {module} is in no layer of LAYERS"
            ));
            continue;
        };
        for (line, path) in crate_paths(&text) {
            let target = path[0].as_str();
            match layer(target) {
                None => wrong.push(format!(
                    "src/{file}:{line}: crate::{target} is in no layer (re-exports at the crate root hide where things live)"
                )),
                Some(l) if target != module && l >= own => wrong.push(format!(
                    "src/{file}:{line}: {module} (layer {own}) imports crate::{target} (layer {l})"
                )),
                _ => {}
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "imports that run upwards or sideways:\n  {}",
        wrong.join("\n  ")
    );
}

#[test]
fn a_technique_imports_no_other_chapter() {
    let mut wrong = Vec::new();
    for (file, text) in src_files() {
        let parts: Vec<&str> = file.split('/').collect();
        if parts.len() != 3 || parts[0] != "techniques" {
            continue;
        }
        let chapter = parts[1];
        for (line, path) in crate_paths(&text) {
            if path[0] == "techniques" && path.get(1).map(String::as_str) != Some(chapter) {
                wrong.push(format!(
                    "src/{file}:{line}: a {chapter} technique imports crate::{}",
                    path.join("::")
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_check_sees_an_upward_import() {
    // The checks above are worth something only if they can fail.
    let text = "use crate::frame::Frame;\n// crate::renderer in a comment\nlet x = crate::renderer::Renderer::new();\n";
    let paths = crate_paths(text);
    assert_eq!(paths.len(), 2);
    assert_eq!(
        paths[1],
        (
            3,
            vec![
                "renderer".to_string(),
                "Renderer".to_string(),
                "new".to_string()
            ]
        )
    );
    assert!(layer("renderer").unwrap() > layer("frame").unwrap());
}

#[test]
fn every_source_file_reads_in_one_sitting() {
    let long: Vec<String> = src_files()
        .into_iter()
        .filter(|(_, text)| text.lines().count() > MAX_LINES)
        // A table a script writes (src/gl/trace/shims.rs) is looked up, not read.
        .filter(|(_, text)| !text.starts_with("// Generated by "))
        .map(|(file, text)| format!("src/{file}: {} lines", text.lines().count()))
        .collect();
    assert!(
        long.is_empty(),
        "files over {MAX_LINES} lines:\n  {}",
        long.join("\n  ")
    );
}
