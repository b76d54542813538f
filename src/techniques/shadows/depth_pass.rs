//! The depth-only state a shadow map is drawn with (notes 01 §8.5), shared
//! by shadow_map.rs and cascaded_shadow_maps.rs so both set and restore the
//! same state, in the same order, from one place.

use crate::scene::Shadow;
use glow::HasContext;

/// Depth test and writes (GL_LESS), depth clamp, the slope-scaled offset
/// and, with `cull_front`, front-face culling; `restore` undoes it.
///
/// # Safety
/// A current GL context.
pub unsafe fn set(gl: &glow::Context, s: &Shadow) {
    unsafe {
        gl.enable(glow::DEPTH_TEST);
        gl.depth_func(glow::LESS);
        gl.depth_mask(true);
        // A caster nearer the light than the near plane still casts:
        // its depth is clamped to the near plane instead of clipped.
        gl.enable(glow::DEPTH_CLAMP);
        // Acne (notes 01 §8.5.1): push each stored depth away from the
        // light by slope_bias x its slope (glPolygonOffset(factor, units)).
        if s.slope_bias > 0.0 {
            gl.enable(glow::POLYGON_OFFSET_FILL);
            gl.polygon_offset(s.slope_bias, 0.0);
        }
        // Store the faces turned away from the light: the depth that is
        // compared lies on the far side of each caster.
        if s.cull_front {
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::FRONT);
        }
    }
}

/// Back to GL's defaults: no culling (GL_BACK), no polygon offset, no
/// depth clamp, no depth test, GL_CCW.
///
/// # Safety
/// A current GL context.
pub unsafe fn restore(gl: &glow::Context) {
    unsafe {
        gl.cull_face(glow::BACK);
        gl.disable(glow::CULL_FACE);
        gl.polygon_offset(0.0, 0.0);
        gl.disable(glow::POLYGON_OFFSET_FILL);
        gl.disable(glow::DEPTH_CLAMP);
        gl.disable(glow::DEPTH_TEST);
        gl.front_face(glow::CCW);
    }
}
