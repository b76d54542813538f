//! Where the demo's shaders come from: `glsl/` when it runs from the crate
//! (actions.rs rebuilds the renderer when one of them changes), else the
//! shaders compiled into the binary.

use crate::gl::program::{self, Sources};
use std::path::PathBuf;

/// Every shader file gloss embeds (the ones live reload watches).
pub(super) fn shader_names() -> Vec<&'static str> {
    static NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    NAMES
        .get_or_init(program::embedded_names)
        .iter()
        .map(String::as_str)
        .collect()
}

/// `./glsl` when it is gloss's shader directory (running from the crate, so
/// edited shaders are picked up), else the shaders compiled into the binary.
pub(super) fn shader_sources() -> Sources {
    let dir = PathBuf::from("glsl");
    let names = program::embedded_names();
    if dir.is_dir() && !names.is_empty() && names.iter().all(|n| dir.join(n).is_file()) {
        let dir = dir.canonicalize().unwrap_or(dir);
        println!("gloss: shaders from {}", dir.display());
        Sources::Directory(dir)
    } else {
        Sources::Embedded
    }
}
