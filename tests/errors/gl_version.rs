//! OpenGL version and profile: older than 3.3 or a compatibility profile is
//! refused with what was found and what gloss needs.

use crate::contains_all;
use gloss::gl::{Backend, GlInfo};

fn fake_info(major: i32, minor: i32, core_profile: bool) -> GlInfo {
    GlInfo {
        backend: Backend::Egl,
        version: format!("{major}.{minor} Fake"),
        renderer: "fake".into(),
        vendor: "fake".into(),
        glsl: "1.50".into(),
        major,
        minor,
        core_profile,
        debug_context: false,
        khr_debug: false,
        max_uniform_block_size: 16384,
        max_clip_distances: 8,
        max_vertex_uniform_components: 1024,
        max_anisotropy: 1.0,
    }
}

#[test]
fn gl_version_too_old() {
    let msg = format!("{:#}", fake_info(3, 2, true).require_33_core().unwrap_err());
    contains_all(&msg, &["OpenGL 3.2", "needs OpenGL 3.3 core"]);
    let msg = format!(
        "{:#}",
        fake_info(2, 1, false).require_33_core().unwrap_err()
    );
    contains_all(&msg, &["OpenGL 2.1", "needs OpenGL 3.3 core"]);
}

#[test]
fn gl_compatibility_profile() {
    let msg = format!(
        "{:#}",
        fake_info(4, 6, false).require_33_core().unwrap_err()
    );
    contains_all(&msg, &["not a core profile", "needs OpenGL 3.3 core"]);
    fake_info(3, 3, true)
        .require_33_core()
        .expect("3.3 core is enough");
}
