//! Live shader reload: the demo reads its shaders from `glsl/` when it runs
//! from the crate, and rebuilds the renderer when one of them changes.

use super::{Demo, to_i32};
use crate::gl::program::{self, Sources};
use crate::renderer::Renderer;
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

impl Demo {
    /// Live shader reload: twice a second, look at glsl/'s modification times;
    /// when a file changed, build a new renderer from the new sources. A
    /// shader that fails to compile is reported (file and line) and the old
    /// renderer keeps running, so an edit never closes the window.
    pub(super) fn reload_shaders_if_changed(&mut self) {
        let Some(run) = self.running.as_mut() else {
            return;
        };
        if run.shaders_checked.elapsed() < std::time::Duration::from_millis(500) {
            return;
        }
        run.shaders_checked = std::time::Instant::now();
        let now = self.sources.modified(&shader_names());
        if now == run.shaders_seen {
            return;
        }
        run.shaders_seen = now;
        let (w, h) = run.ctx.size();
        match Renderer::new(
            &run.ctx.gl,
            &run.ctx.debug,
            &self.scene,
            &self.sources,
            to_i32(w.max(1)),
            to_i32(h.max(1)),
        ) {
            Ok(r) => {
                run.renderer = r;
                eprintln!("gloss: shaders reloaded from glsl/");
            }
            Err(e) => eprintln!("gloss: shader reload failed, keeping the old shaders:\n{e:#}"),
        }
    }
}
