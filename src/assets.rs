//! Where gloss reads scene files and their meshes and textures from: the
//! disk, or the scenes that ship with gloss, embedded in the binary (as the
//! shaders are) so that `gloss` runs from any directory and after
//! `cargo install`. An embedded file's path starts with `embedded:`
//! (`embedded:scenes/default.toml`); paths relative to an embedded scene
//! stay embedded. A path the user gives is read from disk when it exists
//! there; otherwise a shipped scene of that name is used.

pub mod write;

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
    not_a_file(path).is_none()
}

/// What is wrong with `path` as a file to read (a mesh, a texture, a
/// sprite a scene names): `None` for a regular file, on disk (through any
/// symbolic links) or embedded; otherwise what is there instead, in words
/// that follow the path: "does not exist", "is a directory", "is a FIFO
/// (named pipe), not a regular file", "is a symbolic link to /dev/zero,
/// which is a character device ...". Only metadata is read, nothing is
/// opened, so a FIFO never blocks and a device is never read.
pub fn not_a_file(path: &Path) -> Option<String> {
    if embedded(path).is_some() {
        return None;
    }
    if let Some((file, _)) = gltf_image(path) {
        return not_a_file(&file);
    }
    if path.to_str().is_some_and(|s| s.starts_with(EMBEDDED)) {
        return Some("does not exist (gloss embeds no such file)".into());
    }
    let own = match std::fs::symlink_metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Some("does not exist".into());
        }
        Err(e) => return Some(format!("cannot be read: {e}")),
    };
    if !own.file_type().is_symlink() {
        return file_kind(own.file_type()).map(str::to_string);
    }
    let to = std::fs::read_link(path)
        .map(|t| t.display().to_string())
        .unwrap_or_else(|_| "?".into());
    let which = match std::fs::metadata(path) {
        Ok(m) => file_kind(m.file_type())?.to_string(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => "does not exist".into(),
        Err(e) => format!("cannot be read: {e}"),
    };
    Some(format!("is a symbolic link to {to}, which {which}"))
}

/// An image inside a glTF file, as a material names it: `FILE#images[N]`
/// (src/geometry/gltf_images.rs) gives the glTF file and N.
pub fn gltf_image(path: &Path) -> Option<(PathBuf, usize)> {
    let s = path.to_str()?;
    let (file, rest) = s.rsplit_once("#images[")?;
    let index = rest.strip_suffix(']')?;
    if file.is_empty() || index.is_empty() || !index.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((PathBuf::from(file), index.parse().ok()?))
}

/// `None` for a regular file, else what the file type is, in words.
fn file_kind(t: std::fs::FileType) -> Option<&'static str> {
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("is a directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_fifo() {
            return Some("is a FIFO (named pipe), not a regular file");
        }
        if t.is_char_device() {
            return Some("is a character device, not a regular file");
        }
        if t.is_block_device() {
            return Some("is a block device, not a regular file");
        }
        if t.is_socket() {
            return Some("is a socket, not a regular file");
        }
    }
    Some("is not a regular file")
}

/// Does the file name `name` end in `.ext`, in any case (`rock.OBJ`)?
pub fn has_extension(name: &str, ext: &str) -> bool {
    Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
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
    v.retain(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext)));
    v.sort();
    v
}

/// The path to read for a scene the user named: the file on disk if it
/// exists, else the shipped scene of that path or name
/// (`scenes/default.toml`, `default.toml` or `default`), else `path`
/// unchanged (reading it then fails with a clear message).
pub fn scene_path(path: &Path) -> PathBuf {
    // Anything at the path, a dangling link included, is the user's: a
    // link to nothing is an error to report, not the shipped scene.
    if std::fs::symlink_metadata(path).is_ok()
        || path.to_str().is_some_and(|s| s.starts_with(EMBEDDED))
    {
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
    let file = std::fs::File::open(path).map_err(|e| match not_a_file(path) {
        // A link to nothing says so.
        Some(why) if why.starts_with("is a symbolic link") => {
            anyhow!("cannot read {what} {}: it {why}", path.display())
        }
        _ => anyhow!("cannot read {what} {}: {e}", path.display()),
    })?;
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

    #[test]
    fn what_is_not_a_file_is_named() {
        let dir = std::env::temp_dir().join(format!("gloss-assets-kinds-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("a.png");
        std::fs::write(&file, b"x").unwrap();
        assert_eq!(not_a_file(&file), None);
        let said = |p: &Path| not_a_file(p).expect("not a file");
        assert_eq!(said(&dir.join("none.png")), "does not exist");
        assert_eq!(said(&dir), "is a directory");
        #[cfg(unix)]
        {
            let link = dir.join("zero.png");
            std::os::unix::fs::symlink("/dev/zero", &link).unwrap();
            let s = said(&link);
            assert!(
                s.starts_with("is a symbolic link to /dev/zero, which is a character device"),
                "{s}"
            );
            let dangling = dir.join("dangling.png");
            std::os::unix::fs::symlink(dir.join("gone"), &dangling).unwrap();
            assert!(said(&dangling).ends_with("which does not exist"));
            let good = dir.join("good.png");
            std::os::unix::fs::symlink(&file, &good).unwrap();
            assert_eq!(not_a_file(&good), None);
        }
        assert!(has_extension("rock.OBJ", "obj") && has_extension("a/b.Png", "png"));
        assert!(!has_extension("obj", "obj") && !has_extension("a.objx", "obj"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
