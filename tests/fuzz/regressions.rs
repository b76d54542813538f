//! Inputs kept as plain files under tests/fuzz/regressions/<property>/,
//! replayed through the same property on every run: inputs that once
//! broke gloss, and hostile ones written by hand.
//!
//! * `scene-*/`: a scene file, read as if it lay in scenes/ (so that
//!   `assets/...` paths resolve); leading `# --set KEY=VALUE` lines are
//!   overrides.
//! * `obj-*/`, `mtl-*/`, `png-*/`, `gltf-*/`: the file's bytes (`gltf-scene*/`:
//!   a .gltf read as a whole scene, the others a skin).
//! * `cli/`: one argument a line.

use crate::root;
use std::path::PathBuf;

/// Every file of every folder under tests/fuzz/regressions/, with its folder's name.
fn cases() -> Vec<(String, PathBuf)> {
    let dir = root().join("tests/fuzz/regressions");
    let mut out = Vec::new();
    for folder in std::fs::read_dir(&dir).expect("tests/fuzz/regressions") {
        let folder = folder.unwrap().path();
        if !folder.is_dir() {
            continue;
        }
        let name = folder.file_name().unwrap().to_string_lossy().into_owned();
        for f in std::fs::read_dir(&folder).unwrap() {
            out.push((name.clone(), f.unwrap().path()));
        }
    }
    out.sort();
    out
}

#[test]
fn every_kept_input_still_holds() {
    let cases = cases();
    let mut failed = Vec::new();
    let mut kinds = std::collections::BTreeSet::new();
    for (kind, file) in &cases {
        let bytes = std::fs::read(file).unwrap();
        let result = if kind.starts_with("scene") {
            let text = String::from_utf8_lossy(&bytes);
            let overrides: Vec<String> = text
                .lines()
                .map_while(|l| l.strip_prefix("# --set "))
                .map(String::from)
                .collect();
            crate::scene::check(&text, &root().join("scenes/regression.toml"), &overrides)
        } else if kind.starts_with("obj") {
            crate::obj::check(&bytes)
        } else if kind.starts_with("mtl") {
            crate::mtl::check(&bytes)
        } else if kind.starts_with("png") {
            crate::png::check(&bytes)
        } else if kind.starts_with("gltf-scene") {
            crate::gltf::check_scene(&bytes)
        } else if kind.starts_with("gltf") {
            crate::gltf::check(&bytes)
        } else if kind == "cli" {
            let args: Vec<String> = String::from_utf8_lossy(&bytes)
                .lines()
                .map(String::from)
                .collect();
            crate::cli::check(&args)
        } else {
            panic!("{}: no property named {kind}", file.display());
        };
        kinds.insert(kind.clone());
        if let Err(e) = result {
            failed.push(format!("{}: {e}", file.display()));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    // The folders are there and hold something for each kind of input.
    for kind in [
        "scene-mutated",
        "scene-set",
        "obj-shaped",
        "mtl-mutated",
        "png-mutated",
        "gltf-mutated",
        "gltf-scene",
        "cli",
    ] {
        assert!(kinds.contains(kind), "no kept inputs for {kind}: {kinds:?}");
    }
}
