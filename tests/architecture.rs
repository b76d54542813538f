//! The shape of the code (docs/architecture.md), checked:
//!
//! * imports run downwards: a module under src/ uses `crate::X` only for an
//!   X in a lower layer (or its own module), so there is no import circle;
//! * and between the files of one folder too: no file imports a sibling
//!   that imports it back, however long the way round (an import circle
//!   between files of a folder is found and named with its lines);
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

/// Folders the file-level check leaves out, each with the reason: none.
const FOLDERS_NOT_YET_CHECKED: &[&str] = &[];

/// The module path a file under src/ defines: `frame/draw_list.rs` is
/// frame::draw_list, `gl/mod.rs` is gl, `gl/texture/upload.rs` is
/// gl::texture::upload.
fn module_of(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(str::to_string)
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The paths a `use` or an expression names after `start` (which is just
/// past `crate::`, `super::` or `self::`): `a::b::{c, d::e}` gives a::b::c
/// and a::b::d::e; only the leading names matter here.
fn expand(rest: &str, prefix: &[String], out: &mut Vec<Vec<String>>) {
    let mut path = prefix.to_vec();
    let mut r = rest.trim_start();
    loop {
        if let Some(inner) = r.strip_prefix('{') {
            // Split at the commas of this brace level.
            let (mut depth, mut from) = (0, 0);
            for (i, c) in inner.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        expand(&inner[from..i], &path, out);
                        return;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        expand(&inner[from..i], &path, out);
                        from = i + 1;
                    }
                    _ => {}
                }
            }
            expand(&inner[from..], &path, out);
            return;
        }
        let name: String = r
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            break;
        }
        path.push(name.clone());
        r = &r[name.len()..];
        match r.strip_prefix("::") {
            Some(next) => r = next.trim_start(),
            None => break,
        }
    }
    if path.len() > prefix.len() {
        out.push(path);
    }
}

/// Every path a file names through `crate::`, `super::` or `self::`,
/// made absolute, with its line number. Lines from the file's first
/// `#[cfg(test)]` on are left out: `super` means the file itself there.
fn absolute_paths(file: &str, text: &str) -> Vec<(usize, Vec<String>)> {
    let module = module_of(file);
    let mut v = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("#[cfg(test)]") {
            break;
        }
        let code = line.split("//").next().unwrap_or("");
        let mut at = 0;
        while at < code.len() {
            let rest = &code[at..];
            let Some(found) = ["crate::", "super::", "self::"]
                .iter()
                .filter_map(|k| rest.find(k).map(|p| (p, *k)))
                .min()
            else {
                break;
            };
            let (p, keyword) = found;
            let before = rest[..p].chars().last();
            at += p + keyword.len();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let mut base = match keyword {
                "crate::" => Vec::new(),
                "super::" => module[..module.len().saturating_sub(1)].to_vec(),
                _ => module.clone(),
            };
            let mut tail = &code[at..];
            while let Some(t) = tail.strip_prefix("super::") {
                base.pop();
                tail = t;
            }
            let mut paths = Vec::new();
            expand(tail, &base, &mut paths);
            v.extend(paths.into_iter().map(|p| (i + 1, p)));
        }
    }
    v
}

/// The import circles between the files of each folder: for each folder,
/// its units (a file `x.rs` and a folder `x/` are one unit, x) and the
/// edges "unit a names sibling unit b" from every file in a. A folder's
/// mod.rs is the folder itself, not one of its units: it declares them,
/// and its items (`super::Gl`) are the folder's own. Returns one message
/// per circle, naming its units and the lines that close it.
fn folder_circles(files: &[(String, String)], skip: &[&str]) -> Vec<String> {
    use std::collections::{BTreeMap, BTreeSet};
    // folder -> its units
    let mut units: BTreeMap<Vec<String>, BTreeSet<String>> = BTreeMap::new();
    for (file, _) in files {
        let m = module_of(file);
        for k in 1..m.len() {
            units
                .entry(m[..k].to_vec())
                .or_default()
                .insert(m[k].clone());
        }
    }
    // folder -> (a, b) -> where
    let mut edges: BTreeMap<Vec<String>, BTreeMap<(String, String), String>> = BTreeMap::new();
    for (file, text) in files {
        let m = module_of(file);
        for (line, path) in absolute_paths(file, text) {
            for k in 1..m.len() {
                let folder = &m[..k];
                if path.len() <= k || path[..k] != *folder || path[k] == m[k] {
                    continue;
                }
                if units.get(folder).is_some_and(|u| u.contains(&path[k])) {
                    (edges.entry(folder.to_vec()).or_default())
                        .entry((m[k].clone(), path[k].clone()))
                        .or_insert(format!("src/{file}:{line}"));
                }
            }
        }
    }
    let mut circles = Vec::new();
    for (folder, e) in &edges {
        let name = folder.join("/");
        if skip
            .iter()
            .any(|s| name == *s || name.starts_with(&format!("{s}/")))
        {
            continue;
        }
        let nodes: Vec<&String> = units[folder].iter().collect();
        let n = nodes.len();
        let index = |u: &String| nodes.iter().position(|x| *x == u).unwrap();
        let mut reach = vec![vec![false; n]; n];
        for (a, b) in e.keys() {
            reach[index(a)][index(b)] = true;
        }
        for k in 0..n {
            for i in 0..n {
                for j in 0..n {
                    reach[i][j] |= reach[i][k] && reach[k][j];
                }
            }
        }
        let mut seen = vec![false; n];
        for i in 0..n {
            if seen[i] || !reach[i][i] {
                continue;
            }
            let members: Vec<usize> = (0..n).filter(|&j| reach[i][j] && reach[j][i]).collect();
            for &j in &members {
                seen[j] = true;
            }
            let inside: Vec<String> = e
                .iter()
                .filter(|((a, b), _)| members.contains(&index(a)) && members.contains(&index(b)))
                .map(|((a, b), at)| format!("{a} -> {b} ({at})"))
                .collect();
            circles.push(format!("src/{name}: {}", inside.join(", ")));
        }
    }
    circles
}

#[test]
fn files_within_a_folder_import_without_a_circle() {
    let circles = folder_circles(&src_files(), FOLDERS_NOT_YET_CHECKED);
    assert!(
        circles.is_empty(),
        "import circles between the files of a folder (each edge: the file that imports -> the file it imports):\n  {}",
        circles.join("\n  ")
    );
}

#[test]
fn the_file_check_sees_a_circle_and_only_a_circle() {
    // Made-up files: a and b name each other (one through a group, one
    // through an expression), c names only the folder's own item and a.
    let files = |b: &str| {
        vec![
            ("x/mod.rs".to_string(), "pub mod a;\npub mod b;\npub mod c;\npub struct Thing;\nuse self::a::A;\n".to_string()),
            ("x/a.rs".to_string(), "use crate::x::{Thing, c::C};\nuse super::{b::B};\n".to_string()),
            ("x/b.rs".to_string(), b.to_string()),
            ("x/c.rs".to_string(), "use super::Thing;\n// super::a in a comment\n#[cfg(test)]\nmod tests { use super::super::b::B; }\n".to_string()),
        ]
    };
    let circle = folder_circles(&files("fn f() { let _ = crate::x::a::A::new(); }\n"), &[]);
    assert_eq!(circle.len(), 1, "{circle:?}");
    assert!(circle[0].contains("a -> b (src/x/a.rs:2)"), "{circle:?}");
    assert!(circle[0].contains("b -> a (src/x/b.rs:1)"), "{circle:?}");
    assert!(!circle[0].contains("-> c"), "{circle:?}");
    // b imports only downwards: no circle, and a left-out folder is not checked.
    assert!(folder_circles(&files("use super::c::C;\n"), &[]).is_empty());
    assert!(folder_circles(&files("use super::a::A;\n"), &["x"]).is_empty());
}
