//! Where gloss reads scene files and their meshes and textures from: the
//! disk, or the scenes that ship with gloss, embedded in the binary (as the
//! shaders are) so that `gloss` runs from any directory and after
//! `cargo install`. An embedded file's path starts with `embedded:`
//! (`embedded:scenes/default.toml`); paths relative to an embedded scene
//! stay embedded. A path the user gives is read from disk when it exists
//! there; otherwise a shipped scene of that name is used.

use anyhow::{Result, anyhow, bail};
use include_dir::{Dir, File, include_dir};
use std::borrow::Cow;
use std::path::{Path, PathBuf};

static SCENES: Dir<'static> = include_dir!("$CARGO_MANIFEST_DIR/scenes");

/// The prefix that marks an embedded path.
pub const EMBEDDED: &str = "embedded:";

/// The embedded file at `path` (`embedded:scenes/...`), if any.
pub fn embedded(path: &Path) -> Option<&'static File<'static>> {
    let s = path.to_str()?.strip_prefix(EMBEDDED)?;
    let inside = s.strip_prefix("scenes/")?;
    SCENES.get_file(normalise(inside))
}

/// `a/./b/../c` -> `a/c`, so that joined paths find their embedded file.
fn normalise(p: &str) -> String {
    let mut parts: Vec<&str> = Vec::new();
    for c in p.split('/') {
        match c {
            "" | "." => {}
            ".." => {
                parts.pop();
            }
            c => parts.push(c),
        }
    }
    parts.join("/")
}

/// Does `path` name a file, on disk or embedded?
pub fn is_file(path: &Path) -> bool {
    embedded(path).is_some() || path.is_file()
}

/// Every shipped scene, as `scenes/NAME.toml`, sorted.
pub fn shipped_scenes() -> Vec<String> {
    let mut v: Vec<String> = SCENES
        .files()
        .filter(|f| f.path().extension().is_some_and(|e| e == "toml"))
        .map(|f| format!("scenes/{}", f.path().display()))
        .collect();
    v.sort();
    v
}

/// The files ending in `.ext` in the `assets` folder beside the scene file
/// `scene` (embedded for a shipped scene), sorted: what the demo's panel
/// offers as meshes and textures.
pub fn assets_beside(scene: &Path, ext: &str) -> Vec<PathBuf> {
    let Some(dir) = scene.parent() else {
        return Vec::new();
    };
    let assets = dir.join("assets");
    let mut v: Vec<PathBuf> = if dir.to_str().is_some_and(|s| s.starts_with(EMBEDDED)) {
        SCENES
            .get_dir("assets")
            .map(|d| {
                d.files()
                    .filter_map(|f| f.path().file_name())
                    .map(|name| assets.join(name))
                    .collect()
            })
            .unwrap_or_default()
    } else {
        std::fs::read_dir(&assets)
            .map(|rd| rd.filter_map(|e| Some(e.ok()?.path())).collect())
            .unwrap_or_default()
    };
    v.retain(|p| p.extension().is_some_and(|e| e == ext));
    v.sort();
    v
}

/// The path to read for a scene the user named: the file on disk if it
/// exists, else the shipped scene of that path or name
/// (`scenes/default.toml`, `default.toml` or `default`), else `path`
/// unchanged (reading it then fails with a clear message).
pub fn scene_path(path: &Path) -> PathBuf {
    if path.exists() || path.to_str().is_some_and(|s| s.starts_with(EMBEDDED)) {
        return path.to_path_buf();
    }
    let name = path.to_string_lossy();
    let stem = name.trim_start_matches("./").trim_start_matches("scenes/");
    let file = if stem.ends_with(".toml") {
        stem.to_string()
    } else {
        format!("{stem}.toml")
    };
    if SCENES.get_file(&file).is_some() {
        PathBuf::from(format!("{EMBEDDED}scenes/{file}"))
    } else {
        path.to_path_buf()
    }
}

/// Read a whole file of at most `max_bytes`, naming it as `what` in errors.
pub fn read(path: &Path, max_bytes: u64, what: &str) -> Result<Cow<'static, [u8]>> {
    if let Some(f) = embedded(path) {
        return Ok(Cow::Borrowed(f.contents()));
    }
    if path.to_str().is_some_and(|s| s.starts_with(EMBEDDED)) {
        bail!(
            "cannot read {what} {}: gloss embeds no such file (`gloss scenes` lists the shipped scenes)",
            path.display()
        );
    }
    use std::io::Read as _;
    let file = std::fs::File::open(path)
        .map_err(|e| anyhow!("cannot read {what} {}: {e}", path.display()))?;
    let mut bytes = Vec::new();
    file.take(max_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| anyhow!("cannot read {what} {}: {e}", path.display()))?;
    if bytes.len() as u64 > max_bytes {
        bail!(
            "{what} {} is larger than {max_bytes} bytes, the limit for it",
            path.display()
        );
    }
    Ok(Cow::Owned(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_scenes_are_found_by_path_or_name() {
        assert!(shipped_scenes().contains(&"scenes/default.toml".to_string()));
        let p = PathBuf::from("embedded:scenes/default.toml");
        for name in ["default", "default.toml", "scenes/default.toml"] {
            // Relative to a directory without those files.
            let named = Path::new("/nonexistent-gloss-dir").join(name);
            assert_eq!(scene_path(&named), named, "an absolute missing path stays");
            if !Path::new(name).exists() {
                assert_eq!(scene_path(Path::new(name)), p);
            }
        }
        assert!(is_file(&p));
        assert!(is_file(
            &p.parent().unwrap().join("assets/../assets/bricks.png")
        ));
        assert!(!is_file(Path::new("embedded:scenes/none.toml")));
    }
}
