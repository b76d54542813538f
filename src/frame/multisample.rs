//! The world's multisampled twin (MSAA, notes 01 §4 "Fragment Operations",
//! per-sample processing): with `render.msaa` > 1 on the forward path, every
//! pass that draws the world draws into `MSAA`, a target of that many
//! samples per pixel, and the resolve pass
//! (src/techniques/fragment_tests/msaa.rs) blits it into the world image
//! (`post::world_image`: the output, or `hdr` when a post chain follows)
//! before anything reads it.
//!
//! Only the forward path: a deferred path would need a multisampled
//! G-buffer and its lighting run once per sample where a pixel's samples
//! differ, which gloss does not do; `render.msaa` is ignored there
//! (docs/fragment_tests/msaa.md).

use crate::frame::targets::{Depth, HDR, HDR_FORMAT, TargetDesc};
use crate::scene::{RenderPath, Scene};

/// The multisampled twin of the world image.
pub const MSAA: &str = "msaa";

/// Samples per pixel the world is drawn with: `render.msaa` on the forward
/// path, else 1 (no twin).
pub fn samples(scene: &Scene) -> u32 {
    if scene.render.path == RenderPath::Forward {
        scene.render.msaa.max(1)
    } else {
        1
    }
}

/// Whether this frame draws the world into `MSAA` and resolves it.
pub fn active(scene: &Scene) -> bool {
    samples(scene) > 1
}

/// The twin: the world image's colour format (RGBA16F with a chain; the
/// output's RGBA8 without one, which the renderer sets as it sets the
/// output's) and its own multisampled depth-stencil. None without MSAA.
pub fn target(scene: &Scene) -> Option<TargetDesc> {
    if !active(scene) {
        return None;
    }
    let format = if scene.post.is_empty() {
        glow::RGBA8
    } else {
        HDR_FORMAT
    };
    Some(TargetDesc {
        name: MSAA,
        samples: samples(scene),
        colors: vec![("color", format)],
        depth: Depth::Own(glow::DEPTH24_STENCIL8),
        ping_pong: false,
        mips: None,
        downscale: 1,
    })
}

/// Whether the twin stands in for the output (no post chain: its colour
/// format must follow the output's, since a resolve blits between equal
/// formats), judged from the plan's targets.
pub fn twins_output(targets: &[TargetDesc]) -> bool {
    !targets.iter().any(|t| t.name == HDR)
}
