//! How the lighting passes read the maps: the comparison sampler's
//! parameters on each depth texture, and the program's block and sampler
//! units.

use super::{CASCADES_BINDING, SHADOWS_BINDING, UNIT_2D, UNIT_CASCADES, UNIT_CUBE};
use crate::gl::Gl;
use crate::gl::depth_map::DepthMap;
use crate::gl::program::Program;
use crate::scene::Pcf;
use crate::scene::shadows::MAX_SHADOW_MAPS_2D;
use glow::HasContext;

/// The notes' "specialised sampler that takes a 4 component vector and
/// returns the result of the shadow depth test": GL_TEXTURE_COMPARE_MODE =
/// GL_COMPARE_REF_TO_TEXTURE, with GL_LEQUAL ("z <= light depth: lit").
/// GL_LINEAR filtering makes the hardware compare the four nearest texels
/// and blend the results (2x2 PCF); outside a 2D map the border depth 1.0
/// leaves points lit.
pub(super) fn as_shadow_sampler(gl: &Gl, map: &DepthMap, pcf: Pcf) {
    let t = map.target;
    let filter = if pcf == Pcf::Hardware {
        glow::LINEAR
    } else {
        glow::NEAREST
    } as i32;
    unsafe {
        gl.bind_texture(t, Some(map.texture));
        let compare = glow::COMPARE_REF_TO_TEXTURE as i32;
        gl.tex_parameter_i32(t, glow::TEXTURE_COMPARE_MODE, compare);
        gl.tex_parameter_i32(t, glow::TEXTURE_COMPARE_FUNC, glow::LEQUAL as i32);
        gl.tex_parameter_i32(t, glow::TEXTURE_MIN_FILTER, filter);
        gl.tex_parameter_i32(t, glow::TEXTURE_MAG_FILTER, filter);
        if t == glow::TEXTURE_2D || t == glow::TEXTURE_2D_ARRAY {
            let border = glow::CLAMP_TO_BORDER as i32;
            gl.tex_parameter_i32(t, glow::TEXTURE_WRAP_S, border);
            gl.tex_parameter_i32(t, glow::TEXTURE_WRAP_T, border);
            gl.tex_parameter_f32_slice(t, glow::TEXTURE_BORDER_COLOR, &[1.0; 4]);
        } else {
            for w in [
                glow::TEXTURE_WRAP_S,
                glow::TEXTURE_WRAP_T,
                glow::TEXTURE_WRAP_R,
            ] {
                gl.tex_parameter_i32(t, w, glow::CLAMP_TO_EDGE as i32);
            }
        }
        gl.bind_texture(t, None);
    }
}

/// Tell a lighting program where the `Shadows` block and the map samplers
/// are (GLSL 3.30 has no `layout(binding = n)`).
pub fn setup_program(p: &Program) {
    p.bind_uniform_block("Shadows", SHADOWS_BINDING);
    p.bind_uniform_block("Cascades", CASCADES_BINDING);
    p.use_program();
    p.set_i32("u_shadow_cascades", UNIT_CASCADES as i32);
    for i in 0..MAX_SHADOW_MAPS_2D {
        p.set_i32(&format!("u_shadow_map[{i}]"), (UNIT_2D as usize + i) as i32);
        p.set_i32(
            &format!("u_shadow_cube[{i}]"),
            (UNIT_CUBE as usize + i) as i32,
        );
    }
    p.unuse();
}
