//! The far field's keys that can be set to no effect: `render.far_radius`
//! (src/techniques/deferred/far_lists.rs) off the tiled path, without the
//! far field, or with the harmonics far field, which has a fallback of its
//! own. (Their ranges are in checks.rs; the other tiled keys' warnings in
//! warnings.rs.)

use super::{RenderPath, Scene};

/// The warning for `render.far_radius`, when the file sets it where it
/// does nothing.
pub(super) fn warning(s: &Scene) -> Option<String> {
    let r = &s.render;
    let why = if r.far_radius == 0 || !s.keys_written.contains("render.far_radius") {
        return None;
    } else if r.path != RenderPath::Tiled {
        "only the tiled path has a far field"
    } else if r.far_field == 0 {
        "the far field is off (render.far_field = 0)"
    } else if r.far_field_sh {
        "the harmonics far field (render.far_field_sh) has a fallback of its own"
    } else {
        return None;
    };
    Some(format!(
        "render.far_radius = {} has no effect: {why}",
        r.far_radius
    ))
}
